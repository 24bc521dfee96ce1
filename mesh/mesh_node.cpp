// A mesh as a leaf of the solid tree. A solid mesh's spans come from its sorted crossings:
// the winding number (entered +1, left −1, counted from −∞ where it is 0) is positive inside.
// An open mesh is a surface: it is met, never entered, and faces every ray.
#include "mesh/mesh_shape.h"

#include "csg/primitives/primitive.h"
#include "mesh/watertight_triangle.h"

#include <vector>

namespace kerf {

namespace {

class MeshNode final : public Primitive {
public:
    MeshNode(std::shared_ptr<const MeshShape> shape, bool smooth)
        : mShape(std::move(shape)), mSmooth(smooth) {
        mBounds = meshBounds(mShape->mesh());
    }

    void spans(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
               SpanList& out) const override {
        out.clear();
        ++ctx.stats.primitiveTests;
        thread_local std::vector<TriangleCrossing> crossings;
        BvhStats stats;
        const bool solid = mShape->isSolid();
        // A solid needs the crossings before tmin too: they say whether the ray starts inside.
        mShape->bvh().allCrossings(ray, solid ? -kInf : tmin, solid ? kInf : tmax, crossings,
                                   stats);
        count(ctx, stats);
        if (!solid) {  // a surface: a zero-width span at each crossing
            for (const TriangleCrossing& c : crossings) {
                const Boundary b = surfaceBoundary(ray, c.t, c.triangle);
                out.push_back({b, b});
            }
            return;
        }
        int winding = 0;
        Boundary in;
        for (size_t i = 0; i < crossings.size();) {
            // Crossings at one t (a ray through an edge or vertex) count together.
            const double t = crossings[i].t;
            const size_t first = i;
            int net = 0;
            for (; i < crossings.size() && crossings[i].t == t; ++i)
                net += crossings[i].entering ? 1 : -1;
            const int before = winding;
            winding += net;
            if (before <= 0 && winding > 0) {
                in = boundaryAt(ray, t, crossings, first, i, true);
            } else if (before > 0 && winding <= 0) {
                out.push_back({in, boundaryAt(ray, t, crossings, first, i, false)});
            }
        }
    }

    bool firstSurface(const Ray& ray, double tmin, double tmax, TraceContext& ctx, Boundary& hit,
                      bool& entering) const override {
        TriangleHit h;
        BvhStats stats;
        const bool found = mShape->bvh().closestHit(ray, tmin, tmax, h, stats);
        count(ctx, stats);
        if (!found) return false;
        if (!mShape->isSolid()) {
            hit = surfaceBoundary(ray, h.t, h.triangle);
            entering = true;
            return true;
        }
        entering = enters(ray, h.triangle);
        hit = boundary(h.t, normalAt(ray, h.t, h.triangle));
        return true;
    }

    bool anySurface(const Ray& ray, double tmin, double tmax, TraceContext& ctx) const override {
        // Every crossing of a mesh is a surface (of a solid or an open surface): any will do.
        BvhStats stats;
        const bool found = mShape->bvh().anyHit(ray, tmin, tmax, stats);
        count(ctx, stats);
        return found;
    }

    double value(const Vec3& p) const override { return mShape->value(p); }
    Interval valueInterval(const IntervalVec3& box) const override {
        return mShape->range(box.x, box.y, box.z);
    }
    long double valueExtended(const LVec3& p) const override { return mShape->valueExtended(p); }
    ExprId implicitExpr(ExprGraph& g, ExprId x, ExprId y, ExprId z) const override {
        return g.field(x, y, z, mShape);
    }

    NodeKind kind() const override { return NodeKind::Mesh; }
    NodeParams params() const override { return MeshParams{mShape, mSmooth}; }

private:
    static void count(TraceContext& ctx, const BvhStats& stats) {
        ctx.stats.meshNodes += stats.nodesVisited;
        ctx.stats.triangleTests += stats.trianglesTested;
    }

    Vec3 normalAt(const Ray& ray, double t, uint32_t triangle) const {
        return mShape->shadingNormal(triangle, ray.at(t), mSmooth);
    }

    /// Whether the ray enters the solid through the triangle: the watertight test's own
    /// orientation, exact where a dot product with the normal could round the wrong way.
    bool enters(const Ray& ray, uint32_t triangle) const {
        const auto& tri = mShape->mesh().triangles[triangle];
        const auto& pos = mShape->mesh().positions;
        TriangleIntersection x;
        if (intersectWatertight(ShearedRay(ray), pos[tri[0]], pos[tri[1]], pos[tri[2]], -kInf, kInf,
                                x))
            return x.entering;
        return glm::dot(ray.dir, mShape->faceNormal(triangle)) < 0.0;
    }

    /// The boundary where the winding changes at t: the normal of a crossing that goes the
    /// same way (entering or leaving), so it is outward for the solid.
    Boundary boundaryAt(const Ray& ray, double t, const std::vector<TriangleCrossing>& cs,
                        size_t first, size_t last, bool entering) const {
        uint32_t triangle = cs[first].triangle;
        for (size_t k = first; k < last; ++k)
            if (cs[k].entering == entering) {
                triangle = cs[k].triangle;
                break;
            }
        return boundary(t, normalAt(ray, t, triangle));
    }

    /// A surface's boundary faces the ray (two-sided).
    Boundary surfaceBoundary(const Ray& ray, double t, uint32_t triangle) const {
        Vec3 n = normalAt(ray, t, triangle);
        if (glm::dot(mShape->faceNormal(triangle), ray.dir) > 0.0) n = -n;
        return boundary(t, n);
    }

    std::shared_ptr<const MeshShape> mShape;
    bool mSmooth;
};

}  // namespace

NodePtr meshNode(std::shared_ptr<const MeshShape> shape, bool smooth) {
    return std::make_shared<const MeshNode>(std::move(shape), smooth);
}

}  // namespace kerf
