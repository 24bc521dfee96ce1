// The scene's objects behind one BVH, searched near to far for the first surface crossing.
#include "csg/scene_geometry.h"

#include <cmath>

namespace kerf {

namespace {

std::vector<Bounds3> objectBounds(const std::vector<NodePtr>& objects) {
    std::vector<Bounds3> boxes;
    boxes.reserve(objects.size());
    for (const NodePtr& o : objects) boxes.push_back(o->bounds());
    return boxes;
}

}  // namespace

SceneGeometry::SceneGeometry(std::vector<NodePtr> objects)
    : mObjects(std::move(objects)), mBvh(objectBounds(mObjects), Bvh::Split::Median) {}

std::optional<Hit> SceneGeometry::nearestHit(const Ray& ray, double tmin, double tmax,
                                             TraceContext& ctx) const {
    std::optional<Hit> best;
    double nearest = tmax;  // shrinks as hits are found: farther objects cannot win
    mBvh.traverse(ray, tmin, tmax, ctx.stats, [&](int index, double tEnter) {
        if (tEnter > nearest) return nearest;
        Boundary bd;
        bool entering = true;
        if (!mObjects[index]->firstSurface(ray, tmin, nearest, ctx, bd, entering)) return nearest;
        if (best && bd.t >= best->t) return nearest;
        Hit h;
        h.t = bd.t;
        const double len = glm::length(bd.normal);
        h.normal = len > 0.0 ? bd.normal / len : -glm::normalize(ray.dir);
        h.entering = entering;
        h.material = bd.material == Boundary::kNoMaterial ? 0 : bd.material;
        h.primitive = bd.primitive;
        h.relError = bd.relError;
        h.object = index;
        best = h;
        nearest = h.t;
        return nearest;
    });
    return best;
}

bool SceneGeometry::occluded(const Ray& ray, double tmin, double tmax, TraceContext& ctx) const {
    bool blocked = false;
    mBvh.traverse(ray, tmin, tmax, ctx.stats, [&](int index, double) {
        if (blocked) return -kInf;  // an empty range: the walk ends without more tests
        Boundary bd;
        bool entering = true;
        blocked = mObjects[index]->firstSurface(ray, tmin, tmax, ctx, bd, entering);
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
