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

/// The first surface boundary with tmin < t ≤ tmax in sorted spans, if any.
const Boundary* firstSurface(const SpanList& spans, double tmin, double tmax, bool& entering) {
    for (const Span& s : spans) {
        if (s.in.t > tmax) return nullptr;
        if (s.in.t > tmin && s.in.isSurface()) {
            entering = true;
            return &s.in;
        }
        if (s.out.t > tmin && s.out.t <= tmax && s.out.isSurface()) {
            entering = false;
            return &s.out;
        }
    }
    return nullptr;
}

}  // namespace

SceneGeometry::SceneGeometry(std::vector<NodePtr> objects)
    : mObjects(std::move(objects)), mBvh(objectBounds(mObjects)) {}

std::optional<Hit> SceneGeometry::nearestHit(const Ray& ray, double tmin, double tmax,
                                             TraceContext& ctx) const {
    std::optional<Hit> best;
    SpanList spans;
    double nearest = tmax;  // shrinks as hits are found: farther objects cannot win
    mBvh.traverse(ray, tmin, tmax, ctx.stats, [&](int index, double tEnter) {
        if (tEnter > nearest) return nearest;
        mObjects[index]->spans(ray, tmin, nearest, ctx, spans);
        bool entering = true;
        const Boundary* b = firstSurface(spans, tmin, nearest, entering);
        if (b == nullptr || (best && b->t >= best->t)) return nearest;
        Hit h;
        h.t = b->t;
        const double len = glm::length(b->normal);
        h.normal = len > 0.0 ? b->normal / len : -glm::normalize(ray.dir);
        h.entering = entering;
        h.material = b->material == Boundary::kNoMaterial ? 0 : b->material;
        h.primitive = b->primitive;
        h.relError = b->relError;
        h.object = index;
        best = h;
        nearest = h.t;
        return nearest;
    });
    return best;
}

Bounds3 SceneGeometry::bounds() const {
    Bounds3 b;
    for (const NodePtr& o : mObjects) b = Bounds3::hull(b, o->bounds());
    return b;
}

}  // namespace kerf
