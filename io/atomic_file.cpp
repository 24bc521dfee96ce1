/// @file io/atomic_file.cpp
/// @brief A temporary file beside the target, written and checked by kerf itself, renamed
/// onto the target. Libraries never write outputs to disk (images are encoded in memory by
/// the plug-in), so no library can lose a write error (libpng ignores a failed fwrite) or
/// exit the process on one (libjpeg's default error handler).
#include "io/atomic_file.h"

#include "io/temporary_files.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>

namespace kerf {
namespace {

std::string errnoText(int error) { return std::strerror(error); }

/// Splits "dir/name" into "dir/" and "name" ("" and the path when there is no slash).
void splitPath(const std::string& path, std::string& dir, std::string& name) {
    const size_t slash = path.find_last_of('/');
    dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
    name = slash == std::string::npos ? path : path.substr(slash + 1);
}

/// The folder as the user wrote it, for messages: "out" for "out/x.png", "/" for "/x.png".
std::string folderForMessage(const std::string& dir) {
    if (dir.empty()) return ".";
    const size_t end = dir.find_last_not_of('/');
    return end == std::string::npos ? "/" : dir.substr(0, end + 1);
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

/// A fresh temporary name beside the target.
std::string temporaryName(const std::string& path, const std::string& suffix) {
    static const char kLetters[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    thread_local std::mt19937_64 random(std::random_device{}() ^ uint64_t(::getpid()) << 32);
    std::string dir, name;
    splitPath(path, dir, name);
    std::string unique(8, 'x');
    for (char& c : unique) c = kLetters[random() % (sizeof kLetters - 1)];
    return dir + "." + name + ".kerf-tmp-" + unique + suffix;
}

/// Writes all `size` bytes; "" or the reason.
std::string writeAll(int fd, const unsigned char* data, size_t size) {
    size_t done = 0;
    while (done < size) {
        const ssize_t n = ::write(fd, data + done, size - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return errnoText(errno);
        if (n == 0) return "the file system accepted no more bytes";
        done += size_t(n);
    }
    return "";
}

/// Everything after the temporary is open: write, flush to disk, check the size, close.
std::string fill(int fd, const std::string& path, const void* data, size_t size) {
    // mkstemp-style creation makes the file private; the result should be readable like any
    // new file, or keep the permissions of the file it replaces.
    std::string error;
    if (::fchmod(fd, permissionsFor(path)) != 0) error = errnoText(errno);
    if (error.empty()) error = writeAll(fd, static_cast<const unsigned char*>(data), size);
    // Some file systems (NFS, quotas, thin volumes) report a full disk only here.
    if (error.empty() && ::fsync(fd) != 0) error = errnoText(errno);
    struct stat written;
    if (error.empty() && ::fstat(fd, &written) != 0) error = errnoText(errno);
    if (error.empty() && size_t(written.st_size) != size)
        error = "the file holds " + std::to_string(written.st_size) + " bytes instead of " +
                std::to_string(size);
    if (::close(fd) != 0 && error.empty()) error = errnoText(errno);
    return error;
}

}  // namespace

std::string cannotWrite(const std::string& path, const std::string& reason) {
    return "cannot write '" + path + "': " + reason;
}

std::string outputProblem(const std::string& path, bool probe) {
    std::string dir, name;
    splitPath(path, dir, name);
    if (name.empty()) return "the file name is missing";
    const std::string folder = folderForMessage(dir);
    struct stat info;
    if (::stat(dir.empty() ? "." : dir.c_str(), &info) != 0) {
        if (errno == ENOENT) return "folder '" + folder + "' does not exist";
        if (errno == ENOTDIR) return "'" + folder + "' is not a folder";
        return "cannot reach folder '" + folder + "': " + errnoText(errno);
    }
    if (!S_ISDIR(info.st_mode)) return "'" + folder + "' is not a folder";
    if (::stat(path.c_str(), &info) == 0) {
        if (S_ISDIR(info.st_mode)) return "it is a folder";
        // Renaming onto a device or a pipe would replace it with a plain file.
        if (!S_ISREG(info.st_mode)) return "it exists and is not a regular file";
    }
    if (!probe) return "";
    const std::string temporary = temporaryName(path, "");
    InFlightTemporary guard(temporary);
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd < 0) return "cannot create a file in folder '" + folder + "': " + errnoText(errno);
    ::close(fd);
    ::unlink(temporary.c_str());
    return "";
}

void checkOutputWritable(const std::string& path) {
    const std::string problem = outputProblem(path, true);
    if (!problem.empty()) throw FileWriteError(cannotWrite(path, problem));
}

std::string replaceFile(const std::string& path, const std::string& suffix, const void* data,
                        size_t size) {
    const std::string problem = outputProblem(path, false);
    if (!problem.empty()) return problem;
    for (int attempt = 0; attempt < 100; ++attempt) {
        const std::string temporary = temporaryName(path, suffix);
        // Registered before it exists: a signal at any moment finds it in the table.
        InFlightTemporary guard(temporary);
        const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
        if (fd < 0 && errno == EEXIST) continue;
        if (fd < 0) {
            const int error = errno;
            const std::string why = outputProblem(path, false);
            return why.empty() ? "cannot create a temporary file: " + errnoText(error) : why;
        }
        std::string error = fill(fd, path, data, size);
        if (error.empty() && std::rename(temporary.c_str(), path.c_str()) != 0)
            error = "cannot rename the temporary file onto it: " + errnoText(errno);
        if (!error.empty()) ::unlink(temporary.c_str());
        return error;
    }
    return "cannot create a temporary file: every name tried exists";
}

}  // namespace kerf
