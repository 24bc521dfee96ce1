/// @file csg/normalize.h
/// @brief Unit vectors of any finite vector, however long or short.
#pragma once

#include "csg/types.h"

#include <algorithm>
#include <cmath>

namespace kerf {

/// The vector scaled by a power of two (exact) so its largest component lies in [1, 2): its
/// squared length then neither overflows (|v| > 1e154) nor underflows (|v| < 1e-154).
/// A zero or non-finite vector comes back unchanged.
inline Vec3 scaledToUnitRange(const Vec3& v) {
    const double big = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
    if (!(big > 0) || !std::isfinite(big)) return v;
    const int e = std::ilogb(big);
    return Vec3(std::ldexp(v.x, -e), std::ldexp(v.y, -e), std::ldexp(v.z, -e));
}

/// v / |v| for any finite nonzero v. Where glm::normalize does not overflow or underflow this
/// gives the same bits (scaling by a power of two commutes with rounding).
inline Vec3 normalizeSafe(const Vec3& v) { return glm::normalize(scaledToUnitRange(v)); }

}  // namespace kerf
