#include "catplan/base/process.hpp"

#include <array>
#include <fcntl.h>
#include <initializer_list>
#include <span>
#include <string_view>
#include <sys/resource.h>
#include <unistd.h>

namespace catplan {

namespace {

// The start of a small kernel file (statm, a cgroup limit) as text, read raw: no stdio buffer
// is allocated, so it costs one open, one read and one close; empty when it cannot be read.
std::string_view read_small_file(const char* path, std::span<char> buf) {
    int fd = ::open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        return {};
    }
    ssize_t n = ::read(fd, buf.data(), buf.size());
    ::close(fd);
    return n > 0 ? std::string_view(buf.data(), static_cast<std::size_t>(n)) : std::string_view();
}

// The decimal number at the start of text, or 0 when there is none.
std::size_t leading_number(std::string_view text) {
    std::size_t v = 0;
    for (char c : text) {
        if (c < '0' || c > '9') {
            break;
        }
        v = v * 10 + static_cast<std::size_t>(c - '0');
    }
    return v;
}

// The cgroup v2 (then v1) memory limit of this process, or 0 for none or unknown.
std::size_t cgroup_limit_bytes() {
    for (const char* path :
         {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"}) {
        std::array<char, 64> buf{};
        // "max" (no limit) reads as no number.
        if (std::size_t v = leading_number(read_small_file(path, buf)); v > 0) {
            return v;
        }
    }
    return 0;
}

// /proc/self/statm, opened once per thread and read again from its start each time: a search
// samples it every millisecond and a transfer starts many small searches, and an open of a /proc
// path costs ten times the read. A process forked since the open has its own file to open.
class Statm {
public:
    Statm(const Statm&) = delete;
    Statm& operator=(const Statm&) = delete;

    ~Statm() { close(); }

    static std::string_view read(std::span<char> buf) {
        thread_local Statm self;
        return self.read_into(buf);
    }

private:
    Statm() = default;

    std::string_view read_into(std::span<char> buf) {
        pid_t pid = ::getpid();
        if (fd_ < 0 || pid != pid_) {
            close();
            fd_ = ::open("/proc/self/statm", O_RDONLY | O_CLOEXEC);
            pid_ = pid;
        }
        ssize_t n = fd_ < 0 ? -1 : ::pread(fd_, buf.data(), buf.size(), 0);
        return n > 0 ? std::string_view(buf.data(), static_cast<std::size_t>(n))
                     : std::string_view();
    }

    void close() {
        if (fd_ >= 0) {
            ::close(fd_);
            fd_ = -1;
        }
    }

    int fd_ = -1;
    pid_t pid_ = 0;
};

} // namespace

std::size_t resident_bytes() {
    // statm holds "size resident shared text lib data dt" in pages.
    std::array<char, 128> buf{};
    std::string_view text = Statm::read(buf);
    std::size_t space = text.find(' ');
    if (space == std::string_view::npos) {
        return 0;
    }
    std::size_t pages = leading_number(text.substr(space + 1));
    long page = ::sysconf(_SC_PAGESIZE);
    return page > 0 ? pages * static_cast<std::size_t>(page) : 0;
}

long peak_rss_kib() {
    rusage usage{};
    if (getrusage(RUSAGE_SELF, &usage) != 0) {
        return 0;
    }
    return usage.ru_maxrss;
}

std::size_t physical_memory_bytes() {
    // Read once: every search asks for its default memory limit, and a repair runs many.
    static const std::size_t bytes = [] {
        long pages = ::sysconf(_SC_PHYS_PAGES);
        long page = ::sysconf(_SC_PAGESIZE);
        std::size_t phys = pages > 0 && page > 0
                               ? static_cast<std::size_t>(pages) * static_cast<std::size_t>(page)
                               : 0;
        std::size_t cg = cgroup_limit_bytes();
        return cg > 0 && (phys == 0 || cg < phys) ? cg : phys;
    }();
    return bytes;
}

std::size_t default_memory_limit_bytes() {
    return physical_memory_bytes() / 4 * 3;
}

} // namespace catplan
