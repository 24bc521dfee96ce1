/// @file csg/format.h
/// @brief Numbers as kerf prints them (messages, summaries, statistics): printf formats, but
/// NaN is "nan" whatever its sign bit. glibc prints "-nan" for a NaN with the sign bit set
/// (0 · −inf gives one), which reads like a negative number.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

namespace kerf {

/// `pattern` holds one floating-point conversion (e.g. "%g", "%.3f s").
inline std::string formatDouble(const char* pattern, double value) {
    if (std::isnan(value)) value = std::fabs(value);  // clears the sign bit: prints "nan"
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

}  // namespace kerf
