// A level set as a leaf of the solid tree (volume/grids/level_set_node.h).
#include "volume/grids/level_set_node.h"

#include "csg/primitives/primitive.h"
#include "csg/tree/solids.h"

#include <vector>

namespace kerf {

namespace {

class LevelSetLeaf final : public Primitive {
public:
    explicit LevelSetLeaf(std::shared_ptr<const LevelSetGrid> grid) : mGrid(std::move(grid)) {
        mBounds = mGrid->insideBounds();
    }

    void spans(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
               SpanList& out) const override {
        out.clear();
        ++ctx.stats.primitiveTests;
        thread_local std::vector<LevelSetCrossing> crossings;
        const bool inside = mGrid->walk(ray, tmin, tmax, false, crossings);
        Boundary in = clipBoundary(tmin);
        bool isIn = inside;
        for (const LevelSetCrossing& c : crossings) {
            const Boundary b = rootBoundary(c.t, normal(ray, c), ctx);
            if (c.entering) {
                in = b;
            } else {
                out.push_back({in, b});
            }
            isIn = c.entering;
        }
        if (isIn) out.push_back({in, clipBoundary(tmax)});
    }

    bool firstSurface(const Ray& ray, double tmin, double tmax, TraceContext& ctx, Boundary& hit,
                      bool& entering) const override {
        ++ctx.stats.primitiveTests;
        thread_local std::vector<LevelSetCrossing> crossings;
        mGrid->walk(ray, tmin, tmax, true, crossings);
        if (crossings.empty()) return false;
        hit = rootBoundary(crossings[0].t, normal(ray, crossings[0]), ctx);
        entering = crossings[0].entering;
        return true;
    }

    double value(const Vec3& p) const override { return mGrid->value(p); }
    Interval valueInterval(const IntervalVec3& box) const override {
        return mGrid->range(box.x, box.y, box.z);
    }
    long double valueExtended(const LVec3& p) const override { return mGrid->valueExtended(p); }
    ExprId implicitExpr(ExprGraph& g, ExprId x, ExprId y, ExprId z) const override {
        return g.field(x, y, z, mGrid);
    }
    double lipschitz() const override { return mGrid->lipschitz(); }

    NodeKind kind() const override { return NodeKind::Volume; }
    NodeParams params() const override { return VolumeParams{mGrid}; }

private:
    /// The outward normal: the interpolant's gradient, or against the ray where it vanishes
    /// (a flat spot of the samples), so shading still faces the right way.
    static Vec3 normal(const Ray& ray, const LevelSetCrossing& c) {
        if (c.gradient != Vec3(0.0)) return c.gradient;
        return c.entering ? -ray.dir : ray.dir;
    }

    std::shared_ptr<const LevelSetGrid> mGrid;
};

}  // namespace

NodePtr levelSetLeaf(std::shared_ptr<const LevelSetGrid> grid) {
    return std::make_shared<const LevelSetLeaf>(std::move(grid));
}

NodePtr levelSetSolid(std::shared_ptr<const LevelSetGrid> grid) {
    const Affine worldFromIndex = grid->info().worldFromIndex;
    return makeTransform(levelSetLeaf(std::move(grid)), worldFromIndex);
}

}  // namespace kerf
