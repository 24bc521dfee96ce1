/// @file render/ray_offset.h
/// @brief Where a secondary ray starts: past its origin surface by a bound derived from the
/// hit's own error, never by a scene-scale epsilon.
///
/// Why the bound holds. The hit point p = o + t·d carries two kinds of error:
///  1. Rounding. The closed forms solve in object space and map back through one or two
///     affine maps, then evaluate o + t·d: a chain of at most a dozen or so operations on
///     coordinates no larger than M = max(max_i |o_i|, max_i |p_i|), each off by at most half
///     an ulp relative. The point is therefore within c·M·2^-52 of the true surface, with
///     c = 16 as a generous count of those operations (it assumes transforms of moderate
///     condition number, as modelling transforms are).
///  2. The root finder. A surface found by root isolation is only within its Boundary::relError
///     (the tolerance it was isolated to; 0 for closed forms): up to relError·t·|d| along the ray.
/// Moving p along the normal by more than the sum puts it strictly on the chosen side of the
/// true surface, so the new ray can start there with tmin = 0 and never meet the surface it
/// leaves. Both terms scale with the scene: a scene scaled by 1e-6 or 1e6 gets offsets scaled
/// by the same factor and renders the same. Lengths that matter for shading (Beer absorption,
/// mist) are measured from p itself, not from the moved origin, so the offset does not bias them.
#pragma once

#include "csg/types.h"

#include <algorithm>
#include <cmath>

namespace kerf {

/// Rounding operations counted in the bound (see the file comment).
constexpr double kHitRoundingOps = 16.0;

/// An upper bound on the distance between the computed hit point `p` = ray.at(t) and the true
/// surface, for a hit whose distance is within relative error `relTolerance` (Hit::relError).
inline double hitErrorBound(const Ray& ray, double t, const Vec3& p, double relTolerance) {
    const Vec3 ap = glm::abs(p);
    const Vec3 ao = glm::abs(ray.origin);
    const double magnitude = std::max({ap.x, ap.y, ap.z, ao.x, ao.y, ao.z});
    const double rounding = kHitRoundingOps * magnitude * 0x1.0p-52;
    return rounding + relTolerance * std::abs(t) * glm::length(ray.dir);
}

/// The origin for a ray leaving the surface at `p` on the side `side` points to (a unit
/// normal oriented toward where the new ray goes), `errorBound` from hitErrorBound.
inline Vec3 offsetRayOrigin(const Vec3& p, const Vec3& side, double errorBound) {
    return p + errorBound * side;
}

}  // namespace kerf
