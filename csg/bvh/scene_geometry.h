/// @file csg/bvh/scene_geometry.h
/// @brief The objects of a scene behind one BVH: nearest hit for camera and bounce rays, all
/// spans along a segment for shadow rays.
#pragma once

#include "csg/bvh/bvh.h"
#include "csg/bvh/clip_ray.h"
#include "csg/tree/node.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <type_traits>
#include <vector>

namespace kerf {

struct Hit {
    double t = 0.0;
    Vec3 normal{0.0};      ///< world space, unit, outward of the solid (along the ray when leaving)
    bool entering = true;  ///< the ray goes from outside to inside the solid here
    int32_t material = 0;  ///< never kNoMaterial: objects without one get 0, the default
    uint32_t primitive = 0;
    int object = -1;
    /// Boundary::relError of the surface hit, widened to cover any other object's surface
    /// that coincides with it (see nearestHit), so a ray leaving the hit starts past both.
    double relError = 0.0;
};

/// Rounding operations counted in the error of a computed hit point (render/ray_offset.h
/// explains the bound).
constexpr double kHitRoundingOps = 16.0;

/// The rounding term of hitErrorBound alone (the part that depends on the point, not on the
/// tolerance), for searches that weigh one hit against several tolerances.
inline double hitRoundingBound(const Ray& ray, const Vec3& p) {
    const Vec3 ap = glm::abs(p);
    const Vec3 ao = glm::abs(ray.origin);
    // The largest of the six as std::max({…}) picks it (the first of equals, NaN as it does),
    // without the initializer list's loop.
    double magnitude = ap.x;
    if (magnitude < ap.y) magnitude = ap.y;
    if (magnitude < ap.z) magnitude = ap.z;
    if (magnitude < ao.x) magnitude = ao.x;
    if (magnitude < ao.y) magnitude = ao.y;
    if (magnitude < ao.z) magnitude = ao.z;
    return kHitRoundingOps * magnitude * 0x1.0p-52;
}

/// hitErrorBound from its rounding term (hitRoundingBound) and |ray.dir|, computed once.
inline double hitErrorBound(double rounding, double t, double relTolerance, double dirLength) {
    return rounding + relTolerance * std::abs(t) * dirLength;
}

/// An upper bound on the distance between the computed hit point `p` = ray.at(t) and the true
/// surface, for a hit whose distance is within relative error `relTolerance` (Hit::relError):
/// rounding of coordinates of this size, plus the root finder's error along the ray.
inline double hitErrorBound(const Ray& ray, double t, const Vec3& p, double relTolerance) {
    return hitErrorBound(hitRoundingBound(ray, p), t, relTolerance, glm::length(ray.dir));
}

class SceneGeometry {
public:
    /// objectBvh false: objects are tested one after the other, in order, with no BVH over
    /// them (`--accel none`, for measuring what the BVH and the octree save).
    explicit SceneGeometry(std::vector<NodePtr> objects, bool objectBvh = true);

    /// The first surface crossing with tmin < t ≤ tmax, over all objects. Crossings of
    /// several objects that coincide within their error (hitErrorBound) are one place, decided
    /// whatever order the search finds them in: the ray meets the object it enters there
    /// rather than one it leaves (it passes from one into the other), else the object listed
    /// first.
    std::optional<Hit> nearestHit(const Ray& ray, double tmin, double tmax,
                                  TraceContext& ctx) const;

    /// Whether any surface lies with tmin < t ≤ tmax: shadow rays of opaque scenes, which can
    /// stop at the first object that blocks instead of looking for the nearest.
    bool occluded(const Ray& ray, double tmin, double tmax, TraceContext& ctx) const;

    /// Calls visit(objectIndex, spans) for every object whose spans meet (tmin, tmax);
    /// spans are as Node::spans gives them (exact on [tmin, tmax], materials filled). A visit
    /// that returns bool ends the search by returning false (a shadow ray already blocked
    /// needs no other object's spans).
    template <class Visit>
    void forEachObjectSpans(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
                            Visit&& visit) const;

    const std::vector<NodePtr>& objects() const { return mObjects; }
    Bounds3 bounds() const;

private:
    /// mBvh.traverse, or every object in order when there is no BVH: visit(index, tEnter)
    /// returns the new end of the range.
    template <class Visit>
    void traverse(const Ray& ray, double tmin, double tmax, TraceContext& ctx, Visit&& visit) const;

    std::vector<NodePtr> mObjects;
    bool mUseBvh = true;
    Bvh mBvh;
};

template <class Visit>
void SceneGeometry::traverse(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
                             Visit&& visit) const {
    if (mUseBvh) return mBvh.traverse(ray, tmin, tmax, ctx.stats, visit);
    for (size_t i = 0; i < mObjects.size() && tmin <= tmax; ++i) {
        double t0 = tmin, t1 = tmax;
        ++ctx.stats.boundsTests;
        if (!clipRayExact(mObjects[i]->bounds(), ray, t0, t1)) continue;
        tmax = std::min(tmax, visit(int(i), t0));
    }
}

template <class Visit>
void SceneGeometry::forEachObjectSpans(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
                                       Visit&& visit) const {
    SpanList spans;
    traverse(ray, tmin, tmax, ctx, [&](int index, double) {
        mObjects[index]->spans(ray, tmin, tmax, ctx, spans);
        if (spans.empty()) return tmax;
        fillMaterial(spans, 0);
        if constexpr (std::is_same_v<decltype(visit(index, spans)), bool>) {
            if (!visit(index, spans)) return -kInf;  // an empty range ends the walk
        } else {
            visit(index, spans);
        }
        return tmax;
    });
}

}  // namespace kerf
