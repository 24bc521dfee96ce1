/// @file csg/bvh/clip_ray.h
/// @brief The exact slab test of Bounds3::clipRay, inline for the hot callers that test a
/// box once per ray (the children of small Boolean nodes, the torus's bounds), where the call
/// cost a fifth of the test. Bounds3::clipRay is this function.
#pragma once

#include "csg/types.h"

#include <utility>

namespace kerf {

/// Bounds3::clipRay(ray, tmin, tmax) for box b: same operations, same results.
inline bool clipRayExact(const Bounds3& b, const Ray& ray, double& tmin, double& tmax) {
    for (int a = 0; a < 3; ++a) {
        const double o = ray.origin[a], d = ray.dir[a];
        if (d == 0.0) {  // also -0: the ray runs parallel to this slab
            if (o < b.lo[a] || o > b.hi[a]) return false;
            continue;
        }
        const double inv = 1.0 / d;
        double t0 = (b.lo[a] - o) * inv, t1 = (b.hi[a] - o) * inv;
        if (t0 > t1) std::swap(t0, t1);
        // (±inf - o)·inv is ±inf, never NaN, because inv is finite and nonzero here.
        if (t0 > tmin) tmin = t0;
        if (t1 < tmax) tmax = t1;
        if (tmin > tmax) return false;
    }
    return true;
}

}  // namespace kerf
