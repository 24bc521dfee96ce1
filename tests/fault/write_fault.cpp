/// @file tests/fault/write_fault.cpp
/// @brief A fault-injection shim, loaded with LD_PRELOAD into a kerf subprocess by the tests
/// of failed writes (tests/app/write_fault_test.cpp). It wraps the libc calls that put bytes
/// in files (write, pwrite, writev, fwrite) and, for files whose path contains
/// KERF_FAULT_MATCH, behaves like a disk that is full or very slow:
///   KERF_FAULT_AFTER=N   the first N bytes (over all matching files) pass, later writes fail
///                        with ENOSPC (a short write first, like a disk that fills mid-call);
///   KERF_FAULT_DROP=1    writes report success but put nothing in the file (a lost write);
///   KERF_FAULT_FSYNC=1   fsync and fdatasync fail with EIO (a file system that reports the
///                        failure only when flushing);
///   KERF_FAULT_STALL=F   the first matching write creates the file F (so the test knows the
///                        write has started) and then blocks forever, for signal tests.
/// Without KERF_FAULT_MATCH every call goes straight through.
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <sys/uio.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <cstring>

namespace {

std::atomic<long long> gPassed{0};  ///< bytes let through to matching files so far

template <typename F>
F real(const char* name) {
    return reinterpret_cast<F>(::dlsym(RTLD_NEXT, name));
}

/// True when `fd` is open on a file whose path contains KERF_FAULT_MATCH.
bool matches(int fd) {
    const char* pattern = std::getenv("KERF_FAULT_MATCH");
    if (pattern == nullptr || *pattern == '\0' || fd < 0) return false;
    char link[64];
    ::snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
    char path[4096];
    const ssize_t n = ::readlink(link, path, sizeof path - 1);
    if (n <= 0) return false;
    path[n] = '\0';
    return std::strstr(path, pattern) != nullptr;
}

/// Blocks forever once KERF_FAULT_STALL names a marker file, after creating it.
void stallIfAsked() {
    const char* marker = std::getenv("KERF_FAULT_STALL");
    if (marker == nullptr || *marker == '\0') return;
    const int fd = ::open(marker, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd >= 0) ::close(fd);
    for (;;) ::pause();
}

/// How many of `size` bytes a matching write may put in the file; 0 means fail with ENOSPC.
size_t allowance(size_t size) {
    stallIfAsked();
    const char* after = std::getenv("KERF_FAULT_AFTER");
    if (after == nullptr) return size;
    const long long limit = std::atoll(after);
    const long long passed = gPassed.load();
    const long long left = limit > passed ? limit - passed : 0;
    const size_t allowed = size < size_t(left) ? size : size_t(left);
    gPassed += (long long)allowed;
    return allowed;
}

}  // namespace

extern "C" {

bool flagSet(const char* name) {
    const char* value = std::getenv(name);
    return value != nullptr && *value != '\0' && *value != '0';
}

ssize_t write(int fd, const void* data, size_t size) {
    static const auto next = real<ssize_t (*)(int, const void*, size_t)>("write");
    if (size == 0 || !matches(fd)) return next(fd, data, size);
    const size_t allowed = allowance(size);
    if (allowed == 0) {
        errno = ENOSPC;
        return -1;
    }
    if (flagSet("KERF_FAULT_DROP")) return ssize_t(allowed);
    return next(fd, data, allowed);
}

int fsync(int fd) {
    static const auto next = real<int (*)(int)>("fsync");
    if (!matches(fd) || !flagSet("KERF_FAULT_FSYNC")) return next(fd);
    errno = EIO;
    return -1;
}

int fdatasync(int fd) {
    static const auto next = real<int (*)(int)>("fdatasync");
    if (!matches(fd) || !flagSet("KERF_FAULT_FSYNC")) return next(fd);
    errno = EIO;
    return -1;
}

ssize_t pwrite(int fd, const void* data, size_t size, off_t offset) {
    static const auto next = real<ssize_t (*)(int, const void*, size_t, off_t)>("pwrite");
    if (size == 0 || !matches(fd)) return next(fd, data, size, offset);
    const size_t allowed = allowance(size);
    if (allowed == 0) {
        errno = ENOSPC;
        return -1;
    }
    return next(fd, data, allowed, offset);
}

ssize_t pwrite64(int fd, const void* data, size_t size, off_t offset) {
    return pwrite(fd, data, size, offset);
}

ssize_t writev(int fd, const struct iovec* iov, int count) {
    static const auto next = real<ssize_t (*)(int, const struct iovec*, int)>("writev");
    if (!matches(fd)) return next(fd, iov, count);
    ssize_t done = 0;
    for (int i = 0; i < count; ++i) {
        const ssize_t n = write(fd, iov[i].iov_base, iov[i].iov_len);
        if (n < 0) return done > 0 ? done : -1;
        done += n;
        if (size_t(n) < iov[i].iov_len) break;
    }
    return done;
}

size_t fwrite(const void* data, size_t size, size_t count, FILE* stream) {
    static const auto next = real<size_t (*)(const void*, size_t, size_t, FILE*)>("fwrite");
    if (size == 0 || count == 0 || !matches(::fileno(stream)))
        return next(data, size, count, stream);
    const size_t allowed = allowance(size * count) / size;
    const size_t done = allowed > 0 ? next(data, size, allowed, stream) : 0;
    if (done < count) errno = ENOSPC;
    return done;
}

}  // extern "C"
