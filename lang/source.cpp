// Reading model files and rejecting anything that is not UTF-8 text, at the first bad byte.
#include "lang/source.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace kerf {

SourceLoc locationOf(const SourceText& source, size_t offset) {
    SourceLoc loc;
    loc.file = source.name;
    loc.line = 1;
    size_t lineStart = 0;
    const std::string& t = *source.text;
    for (size_t i = 0; i < offset && i < t.size(); ++i) {
        if (t[i] == '\n') {
            ++loc.line;
            lineStart = i + 1;
        }
    }
    loc.col = static_cast<int>(offset - lineStart) + 1;
    return loc;
}

namespace {

std::string hexByte(unsigned char c) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "0x%02X", c);
    return buf;
}

/// Length of the valid UTF-8 sequence starting at s[i], or 0 if it is not valid
/// (overlong forms, surrogates and code points above U+10FFFF are invalid).
size_t utf8SequenceLength(const std::string& s, size_t i) {
    const auto byte = [&](size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char c = byte(i);
    if (c < 0x80) return 1;
    size_t n;
    unsigned lo = 0x80, hi = 0xBF;  // allowed range of the second byte
    if (c >= 0xC2 && c <= 0xDF)
        n = 2;
    else if (c >= 0xE0 && c <= 0xEF) {
        n = 3;
        if (c == 0xE0) lo = 0xA0;
        if (c == 0xED) hi = 0x9F;
    } else if (c >= 0xF0 && c <= 0xF4) {
        n = 4;
        if (c == 0xF0) lo = 0x90;
        if (c == 0xF4) hi = 0x8F;
    } else {
        return 0;
    }
    if (i + n > s.size()) return 0;
    if (byte(i + 1) < lo || byte(i + 1) > hi) return 0;
    for (size_t k = 2; k < n; ++k)
        if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
    return n;
}

}  // namespace

bool checkSourceText(const SourceText& source, DiagnosticSink& sink) {
    const std::string& t = *source.text;
    for (size_t i = 0; i < t.size();) {
        const unsigned char c = static_cast<unsigned char>(t[i]);
        if (c == 0) {
            sink.error(locationOf(source, i), "file contains a NUL byte; is it a binary file?",
                       "model files are UTF-8 text");
            return false;
        }
        const bool allowedControl = c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
        if ((c < 0x20 && !allowedControl) || c == 0x7F) {
            sink.error(
                locationOf(source, i),
                "file contains the control character " + hexByte(c) + "; is it a binary file?",
                "model files are UTF-8 text");
            return false;
        }
        const size_t n = utf8SequenceLength(t, i);
        if (n == 0) {
            sink.error(locationOf(source, i), "invalid UTF-8 byte " + hexByte(c),
                       "model files are UTF-8 text; re-save the file as UTF-8");
            return false;
        }
        i += n;
    }
    return true;
}

namespace {

std::string tooLarge(int64_t maxBytes) {
    return "it is larger than " + std::to_string(maxBytes >> 20) + " MB (" +
           std::to_string(maxBytes) + " bytes), the limit for a model file";
}

/// The reason to refuse a file with this status, or an empty string.
std::string statusProblem(const struct stat& st, int64_t maxBytes) {
    if (S_ISDIR(st.st_mode)) return "it is a directory";
    if (!S_ISREG(st.st_mode)) return "it is not a regular file (a device, FIFO or socket)";
    if (st.st_size > maxBytes) return tooLarge(maxBytes);
    return {};
}

}  // namespace

std::string sourceFileProblem(const std::string& path, int64_t maxBytes) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0)
        return errno == ENOENT || errno == ENOTDIR ? "no such file" : std::strerror(errno);
    return statusProblem(st, maxBytes);
}

std::optional<std::string> readFileBytes(const std::string& path, std::string& why,
                                         int64_t maxBytes) {
    why = sourceFileProblem(path, maxBytes);  // stat first: never open a FIFO or a device
    if (!why.empty()) return std::nullopt;
    // O_NONBLOCK so that a FIFO swapped in since the stat cannot block the open; fstat then
    // checks the file actually opened.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        why = std::strerror(errno);
        return std::nullopt;
    }
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};
    struct stat st {};
    if (::fstat(fd, &st) != 0) {
        why = std::strerror(errno);
        return std::nullopt;
    }
    why = statusProblem(st, maxBytes);
    if (!why.empty()) return std::nullopt;
    std::string bytes;
    bytes.reserve(static_cast<size_t>(st.st_size));
    char buffer[1 << 16];
    for (;;) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n == 0) break;
        if (n < 0) {
            if (errno == EINTR) continue;
            why = std::string("read error: ") + std::strerror(errno);
            return std::nullopt;
        }
        if (static_cast<int64_t>(bytes.size()) + n > maxBytes) {  // grew while being read
            why = tooLarge(maxBytes);
            return std::nullopt;
        }
        bytes.append(buffer, static_cast<size_t>(n));
    }
    return bytes;
}

std::optional<SourceText> readModelFile(const std::string& path, DiagnosticSink& sink) {
    std::string why;
    std::optional<std::string> bytes = readFileBytes(path, why);
    if (!bytes) {
        sink.error(SourceLoc{std::make_shared<const std::string>(path), 0, 0},
                   "cannot read '" + path + "': " + why);
        return std::nullopt;
    }
    return SourceText{std::make_shared<const std::string>(path),
                      std::make_shared<const std::string>(std::move(*bytes))};
}

}  // namespace kerf
