/// @file csg/stopwatch.h
/// @brief Seconds since a steady-clock instant: the one way the commands and exporters time
/// their stages for --stats.
#pragma once

#include <chrono>

namespace kerf {

inline double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace kerf
