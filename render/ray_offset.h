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
///
/// The bound itself (hitErrorBound) lives beside Hit in csg/bvh/scene_geometry.h: the nearest-hit
/// search uses it too, to tell when surfaces of two objects coincide. A hit with such a twin
/// carries a relError widened by their distance, so the new ray starts past both surfaces and
/// neither re-hits the one behind it nor misses the one it is in.
#pragma once

#include "csg/bvh/scene_geometry.h"

namespace kerf {

/// The origin for a ray leaving the surface at `p` on the side `side` points to (a unit
/// normal oriented toward where the new ray goes), `errorBound` from hitErrorBound.
inline Vec3 offsetRayOrigin(const Vec3& p, const Vec3& side, double errorBound) {
    return p + errorBound * side;
}

}  // namespace kerf
