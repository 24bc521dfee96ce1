/// @file io/temporary_files.cpp
/// @brief A signal-safe table of in-flight temporary files and the handler that removes them.
#include "io/temporary_files.h"

#include <limits.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <mutex>

namespace kerf {
namespace {

// More than kerf ever writes at once (the image and its AOVs are written one after another).
constexpr int kSlots = 32;
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

enum SlotState : int { kFree = 0, kFilling = 1, kArmed = 2 };

struct Slot {
    std::atomic<int> state{kFree};
    char path[PATH_MAX];
};
static_assert(std::atomic<int>::is_always_lock_free, "the handler reads the table lock-free");

Slot gSlots[kSlots];

/// Async-signal-safe only: atomic loads, unlink, raise.
extern "C" void removeTemporariesAndDie(int signal) {
    const int savedErrno = errno;
    for (Slot& slot : gSlots)
        if (slot.state.load(std::memory_order_acquire) == kArmed) ::unlink(slot.path);
    errno = savedErrno;
    // SA_RESETHAND restored the default action; the signal is blocked until this handler
    // returns, then it ends the process as it would have without kerf's handler.
    ::raise(signal);
}

void installHandlers() {
    for (const int signal : kSignals) {
        struct sigaction current;
        if (::sigaction(signal, nullptr, &current) != 0) continue;
        if ((current.sa_flags & SA_SIGINFO) || current.sa_handler != SIG_DFL) continue;
        struct sigaction action;
        std::memset(&action, 0, sizeof action);
        action.sa_handler = removeTemporariesAndDie;
        sigfillset(&action.sa_mask);
        action.sa_flags = SA_RESETHAND;
        ::sigaction(signal, &action, nullptr);
    }
}

std::string absolute(const std::string& path) {
    if (!path.empty() && path[0] == '/') return path;
    char cwd[PATH_MAX];
    if (::getcwd(cwd, sizeof cwd) == nullptr) return path;
    return std::string(cwd) + "/" + path;
}

}  // namespace

InFlightTemporary::InFlightTemporary(const std::string& path) {
    static std::once_flag installed;
    std::call_once(installed, installHandlers);
    const std::string full = absolute(path);
    if (full.size() >= PATH_MAX) return;
    for (int i = 0; i < kSlots; ++i) {
        int expected = kFree;
        if (!gSlots[i].state.compare_exchange_strong(expected, kFilling)) continue;
        std::memcpy(gSlots[i].path, full.c_str(), full.size() + 1);
        gSlots[i].state.store(kArmed, std::memory_order_release);
        mSlot = i;
        return;
    }
}

InFlightTemporary::~InFlightTemporary() {
    if (mSlot >= 0) gSlots[mSlot].state.store(kFree, std::memory_order_release);
}

}  // namespace kerf
