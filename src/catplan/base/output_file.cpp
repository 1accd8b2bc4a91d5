#include "catplan/base/output_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <unistd.h>
#include <vector>

namespace catplan {

bool write_file_atomically(const std::string& path, std::string_view contents, std::string& error) {
    std::string pattern = path + ".tmp.XXXXXX";
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    int fd = mkstemp(name.data());
    if (fd < 0) {
        error = "cannot create a temporary file next to '" + path + "': " + std::strerror(errno);
        return false;
    }
    std::size_t done = 0;
    while (done < contents.size()) {
        auto n = ::write(fd, contents.data() + done, contents.size() - done);
        if (n < 0) {
            if (errno == EINTR) {
                continue;
            }
            error = "cannot write '" + path + "': " + std::strerror(errno);
            ::close(fd);
            std::remove(name.data());
            return false;
        }
        done += static_cast<std::size_t>(n);
    }
    if (::close(fd) != 0 || std::rename(name.data(), path.c_str()) != 0) {
        error = "cannot write '" + path + "': " + std::strerror(errno);
        std::remove(name.data());
        return false;
    }
    return true;
}

} // namespace catplan
