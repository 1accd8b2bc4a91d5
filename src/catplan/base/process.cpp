#include "catplan/base/process.hpp"

#include <cstdio>
#include <fcntl.h>
#include <initializer_list>
#include <sys/resource.h>
#include <unistd.h>

namespace catplan {

std::size_t resident_bytes() {
    // statm holds "size resident shared text lib data dt" in pages; a raw read avoids stdio's
    // buffer allocation, so sampling costs one open, one read and one close.
    int fd = ::open("/proc/self/statm", O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        return 0;
    }
    char buf[128];
    ssize_t n = ::read(fd, buf, sizeof buf - 1);
    ::close(fd);
    if (n <= 0) {
        return 0;
    }
    buf[n] = '\0';
    const char* p = buf;
    while (*p != '\0' && *p != ' ') {
        ++p; // skip the total size
    }
    std::size_t pages = 0;
    for (++p; *p >= '0' && *p <= '9'; ++p) {
        pages = pages * 10 + static_cast<std::size_t>(*p - '0');
    }
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

namespace {

// The cgroup v2 (then v1) memory limit of this process, or 0 for none or unknown.
std::size_t cgroup_limit_bytes() {
    for (const char* path :
         {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"}) {
        std::FILE* f = std::fopen(path, "re");
        if (f == nullptr) {
            continue;
        }
        unsigned long long v = 0;
        int got = std::fscanf(f, "%llu", &v); // "max" (no limit) reads as nothing
        std::fclose(f);
        if (got == 1 && v > 0) {
            return static_cast<std::size_t>(v);
        }
    }
    return 0;
}

} // namespace

std::size_t physical_memory_bytes() {
    long pages = ::sysconf(_SC_PHYS_PAGES);
    long page = ::sysconf(_SC_PAGESIZE);
    std::size_t phys = pages > 0 && page > 0
                           ? static_cast<std::size_t>(pages) * static_cast<std::size_t>(page)
                           : 0;
    std::size_t cg = cgroup_limit_bytes();
    if (cg > 0 && (phys == 0 || cg < phys)) {
        return cg;
    }
    return phys;
}

std::size_t default_memory_limit_bytes() {
    return physical_memory_bytes() / 4 * 3;
}

} // namespace catplan
