/// @file render/accuracy_files.cpp
/// @brief Text files through a temporary file and rename.
#include "render/accuracy_files.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

namespace kerf {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& reason) {
    throw TextWriteError("cannot write '" + path + "': " + reason);
}

/// Writes all of `text` to the open descriptor; false on a failed write.
bool writeAll(int fd, const std::string& text) {
    size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        done += size_t(n);
    }
    return true;
}

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

void writeTextFileAtomically(const std::string& path, const std::string& text) {
    const size_t slash = path.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
    const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    if (name.empty()) fail(path, "the file name is empty");
    std::string temporary = dir + "." + name + ".kerf-tmp-XXXXXX";
    const int fd = mkstemp(temporary.data());
    if (fd < 0) fail(path, std::string("cannot create a temporary file: ") + std::strerror(errno));
    // mkstemp makes the file private (0600); a report should be readable like any new file.
    ::fchmod(fd, permissionsFor(path));
    std::string error;
    if (!writeAll(fd, text)) error = std::string("write failed: ") + std::strerror(errno);
    if (::close(fd) != 0 && error.empty())
        error = std::string("close failed: ") + std::strerror(errno);
    if (error.empty() && std::rename(temporary.c_str(), path.c_str()) != 0)
        error = std::string("cannot rename the temporary file onto it: ") + std::strerror(errno);
    if (!error.empty()) {
        std::remove(temporary.c_str());
        fail(path, error);
    }
}

}  // namespace kerf
