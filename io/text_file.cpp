/// @file io/text_file.cpp
/// @brief Text files through a temporary file and a rename (io/atomic_file.h).
#include "io/text_file.h"

#include "io/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>

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

}  // namespace

void writeTextFileAtomically(const std::string& path, const std::string& text) {
    if (path.empty() || path.back() == '/') fail(path, "the file name is empty");
    const std::string error = writeThroughTemporary(path, "", [&](int fd, const std::string&) {
        if (!writeAll(fd, text)) return std::string("write failed: ") + std::strerror(errno);
        return std::string();
    });
    if (!error.empty()) fail(path, error);
}

}  // namespace kerf
