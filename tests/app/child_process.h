/// @file tests/app/child_process.h
/// @brief Running the built `kerf` as a child process the test can signal: fork and exec with
/// extra environment variables (the fault-injection shim of tests/fault/ is set up through
/// them), stdout and stderr to files. Header-only because the test build compiles only
/// *_test.cpp files.
#pragma once

#include "kerf_runner.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <utility>

extern char** environ;

namespace kerf::test {

using Environment = std::vector<std::pair<std::string, std::string>>;

/// The environment that makes the shim fail or stall writes to files whose path contains
/// `match` (tests/fault/write_fault.cpp).
inline Environment faultEnvironment(const std::string& match) {
    // A sanitizer build must accept the shim ahead of its runtime; other options stay.
    const char* asan = std::getenv("ASAN_OPTIONS");
    std::string asanOptions = asan != nullptr && *asan != '\0' ? std::string(asan) + ":" : "";
    return {{"LD_PRELOAD", KERF_WRITE_FAULT_SHIM},
            {"KERF_FAULT_MATCH", match},
            {"ASAN_OPTIONS", asanOptions + "verify_asan_link_order=0"}};
}

class KerfChild {
public:
    /// Starts kerf with `args` in `cwd`, the variables of `extra` added to the environment.
    KerfChild(const TempDir& cwd, const std::vector<std::string>& args, const Environment& extra)
        : mOut((cwd.path() / ".stdout").string()), mErr((cwd.path() / ".stderr").string()) {
        std::vector<std::string> env;
        for (char** e = environ; *e != nullptr; ++e) {
            const std::string entry = *e;
            bool replaced = false;
            for (const auto& [name, value] : extra) replaced |= entry.rfind(name + "=", 0) == 0;
            if (!replaced) env.push_back(entry);
        }
        for (const auto& [name, value] : extra) env.push_back(name + "=" + value);
        std::vector<std::string> argv = {KERF_BINARY};
        argv.insert(argv.end(), args.begin(), args.end());
        // Everything the child needs is built before fork (no allocation after it).
        const std::string dir = cwd.path().string();
        std::vector<char*> argPointers, envPointers;
        for (const std::string& a : argv) argPointers.push_back(const_cast<char*>(a.c_str()));
        for (const std::string& e : env) envPointers.push_back(const_cast<char*>(e.c_str()));
        argPointers.push_back(nullptr);
        envPointers.push_back(nullptr);
        mPid = ::fork();
        if (mPid < 0) throw std::runtime_error("fork failed");
        if (mPid == 0) runChild(dir, argPointers, envPointers);
    }
    ~KerfChild() {
        if (mPid > 0) {
            ::kill(mPid, SIGKILL);
            ::waitpid(mPid, nullptr, 0);
        }
    }
    KerfChild(const KerfChild&) = delete;
    KerfChild& operator=(const KerfChild&) = delete;

    pid_t pid() const { return mPid; }

    /// Waits for the child to end; false if it has not ended after `polls` checks 10 ms
    /// apart (then it is killed: a hang fails the test instead of blocking the suite).
    bool wait(int polls = 12000) {
        for (int i = 0; i < polls; ++i) {
            if (::waitpid(mPid, &mStatus, WNOHANG) == mPid) {
                mPid = -1;
                mOutText = take(mOut);
                mErrText = take(mErr);
                return true;
            }
            ::usleep(10000);
        }
        return false;
    }

    int exitCode() const { return WIFEXITED(mStatus) ? WEXITSTATUS(mStatus) : -1; }
    int signal() const { return WIFSIGNALED(mStatus) ? WTERMSIG(mStatus) : 0; }
    /// stdout and stderr, read (and their files removed) when wait() saw the child end.
    const std::string& out() const { return mOutText; }
    const std::string& err() const { return mErrText; }

private:
    [[noreturn]] void runChild(const std::string& dir, const std::vector<char*>& argv,
                               const std::vector<char*>& env) {
        // Only async-signal-safe calls after fork: the test process may have other threads.
        // A test runner may have started us with SIGINT ignored or signals blocked; kerf must
        // see them as an interactive run would.
        sigset_t none;
        sigemptyset(&none);
        ::sigprocmask(SIG_SETMASK, &none, nullptr);
        ::signal(SIGINT, SIG_DFL);
        ::signal(SIGTERM, SIG_DFL);
        if (::chdir(dir.c_str()) != 0) ::_exit(127);
        const int in = ::open("/dev/null", O_RDONLY);
        const int out = ::open(mOut.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int err = ::open(mErr.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (in < 0 || out < 0 || err < 0 || ::dup2(in, 0) < 0 || ::dup2(out, 1) < 0 ||
            ::dup2(err, 2) < 0)
            ::_exit(127);
        ::execve(argv[0], argv.data(), env.data());
        ::_exit(127);
    }

    static std::string take(const std::string& path) {
        std::string text = readFile(path);
        std::error_code ec;
        fs::remove(path, ec);
        return text;
    }

    std::string mOut, mErr;
    std::string mOutText, mErrText;
    pid_t mPid = -1;
    int mStatus = 0;
};

}  // namespace kerf::test
