/// @file io/atomic_file.cpp
/// @brief A temporary file beside the target, renamed onto it.
#include "io/atomic_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

namespace kerf {
namespace {

/// The permissions a plain new file would get: those of the file being replaced, else 0666
/// less the umask, read from /proc because umask() can only be read by setting it (a race
/// with other threads creating files).
mode_t permissionsFor(const std::string& path) {
    struct stat existing;
    if (::stat(path.c_str(), &existing) == 0 && S_ISREG(existing.st_mode))
        return existing.st_mode & 07777;
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("Umask:", 0) == 0)
            return 0666 & ~mode_t(std::strtoul(line.c_str() + 6, nullptr, 8));
    return 0644;
}

}  // namespace

std::string writeThroughTemporary(const std::string& path, const std::string& suffix,
                                  const TemporaryFileWriter& write) {
    const size_t slash = path.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
    const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    std::string temporary = dir + "." + name + ".kerf-tmp-XXXXXX" + suffix;
    const int fd = mkstemps(temporary.data(), int(suffix.size()));
    if (fd < 0) return std::string("cannot create a temporary file: ") + std::strerror(errno);
    // mkstemps makes the file private (0600); the result should be readable like any new file.
    ::fchmod(fd, permissionsFor(path));
    std::string error = write(fd, temporary);
    if (::close(fd) != 0 && error.empty())
        error = std::string("close failed: ") + std::strerror(errno);
    if (error.empty() && std::rename(temporary.c_str(), path.c_str()) != 0)
        error = std::string("cannot rename the temporary file onto it: ") + std::strerror(errno);
    if (!error.empty()) std::remove(temporary.c_str());
    return error;
}

}  // namespace kerf
