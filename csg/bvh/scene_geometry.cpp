// The scene's objects behind one BVH, searched near to far for the first surface crossing;
// coincident surfaces of separate objects are told apart by a fixed rule, not by ulps.
#include "csg/bvh/scene_geometry.h"

#include <cmath>

namespace kerf {

namespace {

std::vector<Bounds3> objectBounds(const std::vector<NodePtr>& objects) {
    std::vector<Bounds3> boxes;
    boxes.reserve(objects.size());
    for (const NodePtr& o : objects) boxes.push_back(o->bounds());
    return boxes;
}

/// What the coincidence test needs of a ray, computed once per search: |d|.
struct RayScale {
    double dirLength;
};

/// What it needs of a hit besides its relError (which merging widens): the rounding term of
/// its error bound, which depends only on where the hit is.
struct HitScale {
    double rounding;
};

/// How far along the ray (in t) another surface may be computed and still coincide with the
/// hit h: within h's error bound at this size, counting h's own relError or only rounding.
/// The same value as hitErrorBound(ray, h.t, ray.at(h.t), rel) / |ray.dir|.
double coincidenceWindow(const RayScale& rs, const Hit& h, const HitScale& hs, bool withRelError) {
    const double rel = withRelError ? h.relError : 0.0;
    return hitErrorBound(hs.rounding, h.t, rel, rs.dirLength) / rs.dirLength;
}

/// Whether the new hit h replaces the best so far. Surfaces of two objects at one place are
/// one crossing, decided by a fixed rule rather than by ulps of t or the search order:
///  - where the ray leaves one object and enters the other within either's error (relError
///    included), it meets the one it enters: it passes from one into the other, and a ray
///    leaving the other would start inside this one;
///  - where it enters (or leaves) both within rounding, the object listed first wins.
///    Within a root finder's error the nearer estimate still wins, as before.
/// The winner's relError is widened to reach the other surface, so rays leaving it start past
/// both.
bool preferOrMerge(const RayScale& rs, Hit& h, const HitScale& hs, Hit& best,
                   const HitScale& bests) {
    const double gap = h.t - best.t;
    const bool passing = h.entering != best.entering;
    const double window = std::max(coincidenceWindow(rs, h, hs, passing),
                                   coincidenceWindow(rs, best, bests, passing));
    if (gap < -window) return true;
    if (gap > window) return false;
    const bool takeNew = passing ? h.entering : h.object < best.object;
    Hit& winner = takeNew ? h : best;
    const double other = takeNew ? best.relError : h.relError;
    const double t = std::fabs(winner.t);
    winner.relError = std::max(winner.relError, other) + (t > 0.0 ? std::fabs(gap) / t : 0.0);
    return takeNew;
}

}  // namespace

SceneGeometry::SceneGeometry(std::vector<NodePtr> objects, bool objectBvh)
    : mObjects(std::move(objects)), mUseBvh(objectBvh) {
    if (mUseBvh) mBvh = Bvh(objectBounds(mObjects), Bvh::Split::Median);
}

std::optional<Hit> SceneGeometry::nearestHit(const Ray& ray, double tmin, double tmax,
                                             TraceContext& ctx) const {
    std::optional<Hit> best;
    HitScale bestScale{0.0};
    RayScale rayScale{0.0};
    double nearest = tmax;  // shrinks as hits are found: farther objects cannot win
    traverse(ray, tmin, tmax, ctx, [&](int index, double tEnter) {
        if (tEnter > nearest) return nearest;
        Boundary bd;
        bool entering = true;
        if (!mObjects[index]->firstSurface(ray, tmin, nearest, ctx, bd, entering)) return nearest;
        Hit h;
        h.t = bd.t;
        const double len = glm::length(bd.normal);
        h.normal = len > 0.0 ? bd.normal / len : -glm::normalize(ray.dir);
        h.entering = entering;
        h.material = bd.hasMaterial() ? bd.material : 0;
        h.primitive = bd.primitive;
        h.relError = bd.relError;
        h.object = index;
        if (!best) rayScale.dirLength = glm::length(ray.dir);
        const HitScale scale{hitRoundingBound(ray, ray.at(h.t))};
        if (best && !preferOrMerge(rayScale, h, scale, *best, bestScale)) return nearest;
        best = h;
        bestScale = scale;
        // Farther objects cannot win, but one whose surface coincides with this one can.
        nearest = std::min(nearest, h.t + coincidenceWindow(rayScale, h, scale, true));
        return nearest;
    });
    return best;
}

bool SceneGeometry::occluded(const Ray& ray, double tmin, double tmax, TraceContext& ctx) const {
    const OcclusionScope scope(ctx);  // whether, not where exactly nor which way it faces
    bool blocked = false;
    traverse(ray, tmin, tmax, ctx, [&](int index, double) {
        if (blocked) return -kInf;  // an empty range: the walk ends without more tests
        blocked = mObjects[index]->anySurface(ray, tmin, tmax, ctx);
        return blocked ? -kInf : tmax;
    });
    return blocked;
}

Bounds3 SceneGeometry::bounds() const {
    Bounds3 b;
    for (const NodePtr& o : mObjects) b = Bounds3::hull(b, o->bounds());
    return b;
}

}  // namespace kerf
