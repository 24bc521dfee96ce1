/// @file csg/interval/interval_round.h
/// @brief One-ulp outward steps on the bit pattern of a double: the rounding of every interval
/// operation, inline and without a library call (nextafter costs a call and a branch maze).
#pragma once

#include <cstdint>
#include <cstring>
#include <limits>

namespace kerf::interval_kernel {

inline uint64_t bitsOf(double v) {
    uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
}
inline double fromBits(uint64_t b) {
    double v;
    std::memcpy(&v, &b, sizeof v);
    return v;
}

/// One ulp towards −inf; −inf and NaN stay put, +inf becomes the largest double (a correct
/// lower bound for a result that overflowed). On the bit patterns a positive double steps
/// down by decrementing them, a negative one by incrementing them: b − (sign ? −1 : 1),
/// without a data-dependent branch.
inline double down(double v) {
    if (!(v > -std::numeric_limits<double>::infinity())) return v;  // −inf or NaN
    if (v == 0.0) return -std::numeric_limits<double>::denorm_min();
    const uint64_t b = bitsOf(v);
    const uint64_t step = static_cast<uint64_t>(static_cast<int64_t>(b) >> 63) | 1u;
    return fromBits(b - step);
}
/// One ulp towards +inf (the mirror of down).
inline double up(double v) { return -down(-v); }

}  // namespace kerf::interval_kernel
