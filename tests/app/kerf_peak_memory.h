/// @file tests/app/kerf_peak_memory.h
/// @brief Runs the built kerf as a child process and reports its peak resident memory (the
/// kernel's ru_maxrss from wait4), for the tests that bound what a reader allocates on a
/// hostile file against the file's size. Header-only like kerf_runner.h.
#pragma once

#include "app/kerf_runner.h"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <string>
#include <vector>

namespace kerf::test {

struct KerfPeakRun {
    int exitCode = -1;    ///< -1 when the child did not exit normally (a signal)
    std::string err;      ///< stderr
    int64_t peakRss = 0;  ///< bytes
};

/// Runs kerf with `args` in `cwd`, stdin and stdout from and to /dev/null, stderr to a file;
/// returns its exit code, stderr and peak RSS. fork + exec rather than std::system so the
/// figure is this child's alone (getrusage(RUSAGE_CHILDREN) keeps the largest child ever).
inline KerfPeakRun runKerfMeasuringPeak(const TempDir& cwd, const std::vector<std::string>& args) {
    const std::string errPath = (cwd.path() / ".stderr-peak").string();
    std::vector<std::string> argv{KERF_BINARY};
    argv.insert(argv.end(), args.begin(), args.end());
    std::vector<char*> cargv;
    for (std::string& a : argv) cargv.push_back(a.data());
    cargv.push_back(nullptr);
    const pid_t pid = fork();
    if (pid == 0) {
        const int devNull = open("/dev/null", O_RDWR);
        const int errFd = open(errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (devNull < 0 || errFd < 0 || chdir(cwd.path().c_str()) != 0) _exit(127);
        dup2(devNull, 0);
        dup2(devNull, 1);
        dup2(errFd, 2);
        execv(cargv[0], cargv.data());
        _exit(127);
    }
    KerfPeakRun run;
    int status = 0;
    struct rusage usage {};
    if (pid < 0 || wait4(pid, &status, 0, &usage) != pid) return run;
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.peakRss = static_cast<int64_t>(usage.ru_maxrss) * 1024;  // Linux reports kB
    run.err = readFile(errPath);
    fs::remove(errPath);
    return run;
}

/// True in a build with AddressSanitizer, whose shadow memory and quarantine make RSS figures
/// meaningless as bounds (the peak tests then check only the exit code and message).
constexpr bool kUnderAddressSanitizer =
#if defined(__SANITIZE_ADDRESS__)
    true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
    true;
#else
    false;
#endif
#else
    false;
#endif

}  // namespace kerf::test
