#include "catplan/base/output_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <random>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>

namespace catplan {
namespace {

std::string why(const std::string& what, const std::string& path) {
    return what + " '" + path + "': " + std::strerror(errno);
}

std::string directory_of(const std::string& path) {
    auto slash = path.rfind('/');
    return slash == std::string::npos ? "" : path.substr(0, slash + 1);
}

// The /proc/self/fd links (which /dev/stdout and /dev/fd/N lead to, through a link to the
// directory) name an open file of the process; they are written in place, never resolved further
// (their text is "pipe:[123]", not a path) or replaced.
bool is_process_link(const std::string& path) {
    std::string dir = directory_of(path);
    char* real = ::realpath(dir.empty() ? "." : dir.c_str(), nullptr);
    bool in_proc = real != nullptr && std::string(real).rfind("/proc/", 0) == 0;
    std::free(real);
    return in_proc;
}

// Follows a chain of symlinks to the path they end at (which may not exist yet: writing through a
// dangling link creates its target, as the shell's `>` does); stops at a /proc/self/fd link.
bool resolve_links(std::string& path, std::string& error) {
    for (int depth = 0; depth < 40; ++depth) {
        struct stat st {};

        if (is_process_link(path) || ::lstat(path.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) {
            return true;
        }
        std::string target(4096, '\0');
        auto n = ::readlink(path.c_str(), target.data(), target.size());
        if (n < 0) {
            error = why("cannot follow the link", path);
            return false;
        }
        target.resize(static_cast<std::size_t>(n));
        if (target.front() != '/') {
            target.insert(0, directory_of(path));
        }
        path = std::move(target);
    }
    errno = ELOOP;
    error = why("cannot follow the link", path);
    return false;
}

bool write_all(int fd, std::string_view contents) {
    std::size_t done = 0;
    while (done < contents.size()) {
        auto n = ::write(fd, contents.data() + done, contents.size() - done);
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n <= 0) {
            return false;
        }
        done += static_cast<std::size_t>(n);
    }
    return true;
}

// A seed for the temporary names: the kernel's random bytes (std::random_device asks the CPU
// first, which traps to the hypervisor in a virtual machine), else the process id and the time.
unsigned seed() {
    unsigned s = 0;
    if (::getrandom(&s, sizeof s, GRND_NONBLOCK) == static_cast<ssize_t>(sizeof s)) {
        return s;
    }
    return static_cast<unsigned>(::getpid()) ^ static_cast<unsigned>(::time(nullptr));
}

// A new file in the target's directory, named after it; created with O_EXCL so that it is ours,
// with mode 0666 so that the umask (and a default ACL) applies as to any new file.
int create_temporary(const std::string& target, std::string& name) {
    static std::minstd_rand random(seed());
    static constexpr char kDigits[] = "0123456789abcdefghijklmnopqrstuvwxyz";
    for (int attempt = 0; attempt < 100; ++attempt) {
        name = target + ".tmp.";
        for (int i = 0; i < 6; ++i) {
            name += kDigits[random() % (sizeof kDigits - 1)];
        }
        int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0 || errno != EEXIST) {
            return fd;
        }
    }
    return -1;
}

} // namespace

OutputSet::~OutputSet() {
    for (auto& s : staged_) {
        if (s.fd >= 0) {
            ::close(s.fd);
        }
        if (!committed_ && !s.temporary.empty()) {
            ::unlink(s.temporary.c_str());
        }
    }
}

bool OutputSet::stage(const std::string& path, std::string_view contents, std::string& error) {
    Staged s;
    s.target = path;
    if (!resolve_links(s.target, error)) {
        return false;
    }
    for (const auto& other : staged_) {
        if (other.target == s.target) {
            error = "'" + path + "' is named as two outputs";
            return false;
        }
    }

    struct stat st {};

    bool exists = ::stat(s.target.c_str(), &st) == 0;
    if (exists && S_ISDIR(st.st_mode)) {
        errno = EISDIR;
        error = why("cannot write", path);
        return false;
    }
    if (exists && (!S_ISREG(st.st_mode) || is_process_link(s.target))) {
        // In place: a regular file reached through /proc/self/fd is the shell's redirection, so
        // append as the process's own descriptor would.
        s.fd =
            ::open(s.target.c_str(), O_WRONLY | O_CLOEXEC | (S_ISREG(st.st_mode) ? O_APPEND : 0));
        if (s.fd < 0) {
            error = why("cannot write", path);
            return false;
        }
        s.contents = contents;
        staged_.push_back(std::move(s));
        return true;
    }
    int fd = create_temporary(s.target, s.temporary);
    if (fd < 0) {
        error = why("cannot create", path);
        return false;
    }
    if (exists && ::geteuid() == 0) {
        // Best effort, as cp -p; before fchmod, which a change of owner would undo (setuid bits).
        static_cast<void>(::fchown(fd, st.st_uid, st.st_gid));
    }
    // No fsync: the rename below is what keeps a failed run from leaving a partial file, and, as
    // a compiler's or `sed -i`'s output, the file's durability is the file system's. A flush costs
    // more than a whole small transfer (about half a millisecond a file, waiting on the disk).
    bool ok = write_all(fd, contents) && (!exists || ::fchmod(fd, st.st_mode & 07777) == 0);
    int saved = errno;
    if (::close(fd) != 0 && ok) {
        ok = false;
        saved = errno;
    }
    if (!ok) {
        errno = saved;
        error = why("cannot write", path);
        ::unlink(s.temporary.c_str());
        return false;
    }
    s.contents.clear();
    staged_.push_back(std::move(s)); // from here on the destructor removes the temporary file
    return true;
}

bool OutputSet::commit(std::string& error) {
    if (committed_) {
        error = "an output set is committed once";
        return false;
    }
    for (auto& s : staged_) {
        if (s.fd >= 0 && !write_all(s.fd, s.contents)) {
            error = why("cannot write", s.target);
            return false;
        }
    }
    for (auto& s : staged_) {
        if (!s.temporary.empty() && std::rename(s.temporary.c_str(), s.target.c_str()) != 0) {
            error = why("cannot write", s.target);
            return false;
        }
        s.temporary.clear(); // in place now: not ours to remove
    }
    committed_ = true;
    return true;
}

bool write_file_atomically(const std::string& path, std::string_view contents, std::string& error) {
    OutputSet set;
    return set.stage(path, contents, error) && set.commit(error);
}

} // namespace catplan
