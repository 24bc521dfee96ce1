/// @file app/progress_bar.h
/// @brief A one-line progress bar with percentage and estimated time left, redrawn in place
/// with '\r'. Only used when stderr is a terminal; the caller decides that.
#pragma once

#include <chrono>
#include <cstdio>
#include <mutex>

namespace kerf::app {

class ProgressBar {
public:
    /// Draws on `out` (normally stderr).
    explicit ProgressBar(std::FILE* out);

    /// Records the fraction done (0..1). Safe to call from several threads; redraws at most
    /// every tenth of a second, and whenever the whole percentage changes.
    void update(double fraction);

    /// Draws 100 % and ends the line. Idempotent.
    void finish();

private:
    using Clock = std::chrono::steady_clock;
    void draw(double fraction);

    std::FILE* mOut;
    std::mutex mMutex;
    Clock::time_point mStart;
    Clock::time_point mLastDraw;
    int mLastPercent = -1;
    double mFraction = 0;
    bool mFinished = false;
};

/// True when file descriptor 2 is a terminal.
bool stderrIsTerminal();

}  // namespace kerf::app
