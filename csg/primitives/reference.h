/// @file csg/primitives/reference.h
/// @brief First hits computed in higher precision, for measuring the error of the fast paths
/// (`kerf bench accuracy`, the hard-case tests). Slow; never used for rendering.
///
/// Method: the candidate crossings come from interval root isolation (sound: it misses no
/// sign change wider than its tolerance) run at a tight tolerance; each candidate is then
/// re-located by bisection of the object's implicit form evaluated in long double
/// (Node::valueExtended) until the bracket is a few long-double ulps wide. A candidate whose
/// bracket shows no sign change in long double is a tangency within the reference's own
/// uncertainty and is reported as such.
#pragma once

#include "csg/bvh/scene_geometry.h"

namespace kerf {

struct ReferenceHit {
    enum class Kind {
        Miss,       ///< no surface along the ray
        Hit,        ///< a surface at t, certain in long double
        Uncertain,  ///< a tangency or a crossing the long-double refinement cannot confirm
    };
    Kind kind = Kind::Miss;
    long double t = 0;  ///< the hit distance (parameter of ray.at)
    Vec3 normal{0.0};   ///< world unit outward normal (from the long-double gradient)
    int object = -1;
};

/// The reference first hit with tmin < t along `ray`, over every object of the scene.
ReferenceHit referenceNearestHit(const SceneGeometry& geometry, const Ray& ray, double tmin = 0.0);

}  // namespace kerf
