/// @file tests/util/interval_checks.h
/// @brief Comparing intervals bit for bit and printing them, for the tests that require two
/// evaluators to agree exactly.
#pragma once

#include "csg/interval/interval.h"

#include <cstring>
#include <sstream>
#include <string>

namespace kerf::test {

/// lo, hi and the NaN flag identical to the bit (so −0 differs from +0).
inline bool sameBits(const Interval& a, const Interval& b) {
    return std::memcmp(&a.lo, &b.lo, sizeof(double)) == 0 &&
           std::memcmp(&a.hi, &b.hi, sizeof(double)) == 0 && a.maybeNan == b.maybeNan;
}

/// "[lo, hi]" to 17 digits, "nan?" where the flag is set.
inline std::string describe(const Interval& a) {
    std::ostringstream s;
    s.precision(17);
    s << "[" << a.lo << ", " << a.hi << (a.maybeNan ? "] nan?" : "]");
    return s.str();
}

}  // namespace kerf::test
