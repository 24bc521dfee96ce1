/// @file csg/format.h
/// @brief Numbers as kerf prints them (messages, summaries, statistics): printf formats, but
/// NaN is "nan" whatever its sign bit. glibc prints "-nan" for a NaN with the sign bit set
/// (0 · −inf gives one), which reads like a negative number.
#pragma once

#include <cfloat>
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

/// `value` as `pattern` prints it among values of magnitude up to `scale` (e.g. the corners of
/// one box): a value within 16 ulps of `scale` from 0 prints as "0", as does -0. Rotations and
/// outward rounding leave such residues (-2.22045e-16 beside 1, or -4.94066e-324) where the
/// exact value is 0; the digits %g shows are far coarser. The value itself is not changed, and
/// the rule is relative, so a scene scaled by 1e-300 prints the same digits.
inline std::string formatDoubleAtScale(const char* pattern, double value, double scale) {
    if (std::fabs(value) <= 16 * DBL_EPSILON * std::fabs(scale))
        value = 0.0;  // also turns -0 into 0
    return formatDouble(pattern, value);
}

}  // namespace kerf
