/// @file app/progress_bar.cpp
#include "app/progress_bar.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <unistd.h>

namespace kerf::app {

namespace {

constexpr int kBarWidth = 40;
constexpr auto kMinRedrawInterval = std::chrono::milliseconds(100);

/// "1:05" or "1:02:03"; "--:--" while nothing is known yet.
std::string formatDuration(double seconds) {
    if (!std::isfinite(seconds) || seconds < 0) return "--:--";
    const long total = std::lround(seconds);
    const long h = total / 3600, m = (total / 60) % 60, s = total % 60;
    char buffer[32];
    if (h > 0) {
        std::snprintf(buffer, sizeof buffer, "%ld:%02ld:%02ld", h, m, s);
    } else {
        std::snprintf(buffer, sizeof buffer, "%ld:%02ld", m, s);
    }
    return buffer;
}

}  // namespace

bool stderrIsTerminal() { return isatty(STDERR_FILENO) == 1; }

ProgressBar::ProgressBar(std::FILE* out) : mOut(out), mStart(Clock::now()), mLastDraw(mStart) {}

void ProgressBar::update(double fraction) {
    std::lock_guard<std::mutex> lock(mMutex);
    if (mFinished) return;
    // Calls may arrive out of order from several threads: the bar never goes backwards.
    mFraction = std::max(mFraction, std::clamp(fraction, 0.0, 1.0));
    const int percent = int(mFraction * 100.0);
    const auto now = Clock::now();
    if (percent == mLastPercent && now - mLastDraw < kMinRedrawInterval) return;
    mLastPercent = percent;
    mLastDraw = now;
    draw(mFraction);
}

void ProgressBar::finish() {
    std::lock_guard<std::mutex> lock(mMutex);
    if (mFinished) return;
    draw(1.0);
    std::fputc('\n', mOut);
    std::fflush(mOut);
    mFinished = true;
}

void ProgressBar::draw(double fraction) {
    const double elapsed = std::chrono::duration<double>(Clock::now() - mStart).count();
    const double left = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : -1.0;
    const int filled = int(fraction * kBarWidth);
    std::string bar(size_t(filled), '#');
    bar.append(size_t(kBarWidth - filled), '.');
    std::fprintf(mOut, "\r[%s] %3d%%  %s left ", bar.c_str(), int(fraction * 100.0),
                 fraction >= 1.0 ? "0:00" : formatDuration(left).c_str());
    std::fflush(mOut);
}

}  // namespace kerf::app
