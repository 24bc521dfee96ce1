// The surface nodes over other nodes: `surface SOLID` (the solid's boundary as crossings),
// `clip SURFACE by SOLID` (the crossings inside a solid) and the `interior` modifier.
#include "csg/primitives/surfaces.h"

#include <utility>

namespace kerf {
namespace {

/// Whether a span of the sorted list holds t (ends included).
bool holds(const SpanList& spans, double t) {
    for (const Span& s : spans) {
        if (s.in.t > t) return false;
        if (t <= s.out.t) return true;
    }
    return false;
}

/// A solid's boundary as a surface crossing: the normal turned to face the ray (the outward
/// normal already does where the ray enters), and the back (where it leaves) marked.
Boundary asCrossing(Boundary b, bool entering) {
    if (!entering) {
        b.normal = -b.normal;
        if (!b.hasMaterial()) b.material = Boundary::kNoMaterialBack;
    }
    return b;
}

/// The empty solid's implicit form, shared by the surface nodes.
class SurfaceNode : public Node {
public:
    double value(const Vec3&) const final { return 1.0; }
    /// Deliberately loose where the box meets the bounds: ambiguous, so interval culling
    /// (primary beams) never proves a region that holds the sheet empty.
    Interval valueInterval(const IntervalVec3& box) const final {
        const Bounds3 b{Vec3(box.x.lo, box.y.lo, box.z.lo), Vec3(box.x.hi, box.y.hi, box.z.hi)};
        return Bounds3::overlap(b, mBounds).empty() ? Interval(1.0) : Interval(-1.0, 1.0);
    }
    long double valueExtended(const LVec3&) const final { return 1.0L; }
    NodeParams params() const final { return SurfaceParams{}; }
};

class SurfaceOf final : public SurfaceNode {
public:
    explicit SurfaceOf(NodePtr solid) : mSolid(std::move(solid)) { mBounds = mSolid->bounds(); }

    void spans(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
               SpanList& out) const override {
        ScratchSpans solid(ctx.scratch);
        mSolid->spans(ray, tmin, tmax, ctx, *solid);
        out.clear();
        for (const Span& s : *solid) {
            if (!(s.in.t < s.out.t)) continue;  // a touch is not a crossing
            if (s.in.isSurface()) {
                const Boundary b = asCrossing(s.in, true);
                out.push_back({b, b});
            }
            if (s.out.isSurface()) {
                const Boundary b = asCrossing(s.out, false);
                out.push_back({b, b});
            }
        }
    }

    bool firstSurface(const Ray& ray, double tmin, double tmax, TraceContext& ctx, Boundary& hit,
                      bool& entering) const override {
        bool in = true;
        if (!mSolid->firstSurface(ray, tmin, tmax, ctx, hit, in)) return false;
        hit = asCrossing(hit, in);
        entering = true;
        return true;
    }

    NodeKind kind() const override { return NodeKind::SurfaceOf; }
    NodeSpan children() const override { return {&mSolid, 1}; }
    NodePtr withChildren(std::vector<NodePtr> children) const override {
        return std::make_shared<const SurfaceOf>(std::move(children.at(0)));
    }

private:
    NodePtr mSolid;
};

class Clip final : public SurfaceNode {
public:
    Clip(NodePtr surface, NodePtr solid) : mChildren{std::move(surface), std::move(solid)} {
        mBounds = Bounds3::overlap(mChildren[0]->bounds(), mChildren[1]->bounds());
    }

    void spans(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
               SpanList& out) const override {
        ScratchSpans inside(ctx.scratch);
        mChildren[1]->spans(ray, tmin, tmax, ctx, *inside);
        out.clear();
        if (inside->empty()) return;
        ScratchSpans sheet(ctx.scratch);
        mChildren[0]->spans(ray, tmin, tmax, ctx, *sheet);
        for (const Span& s : *sheet)
            if (holds(*inside, s.in.t)) out.push_back(s);
    }

    /// The surface's crossings one after the other until one lies inside the solid.
    bool firstSurface(const Ray& ray, double tmin, double tmax, TraceContext& ctx, Boundary& hit,
                      bool& entering) const override {
        ScratchSpans inside(ctx.scratch);
        mChildren[1]->spans(ray, tmin, tmax, ctx, *inside);
        if (inside->empty()) return false;
        const double last = std::min(tmax, inside->back().out.t);  // nothing inside past it
        double from = tmin;
        while (mChildren[0]->firstSurface(ray, from, last, ctx, hit, entering)) {
            if (holds(*inside, hit.t)) return true;
            from = hit.t;
        }
        return false;
    }

    NodeKind kind() const override { return NodeKind::Clip; }
    NodeSpan children() const override { return {mChildren, 2}; }
    NodePtr withChildren(std::vector<NodePtr> children) const override {
        return std::make_shared<const Clip>(std::move(children.at(0)), std::move(children.at(1)));
    }

private:
    NodePtr mChildren[2];  // the surface, the solid that keeps its crossings
};

class Interior final : public Node {
public:
    Interior(NodePtr child, int32_t material) : mChild(std::move(child)), mMaterial(material) {
        mBounds = mChild->bounds();
    }

    void spans(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
               SpanList& out) const override {
        mChild->spans(ray, tmin, tmax, ctx, out);
        for (Span& s : out) {
            if (s.in.t == s.out.t) {  // a surface's crossing (or a solid's touch)
                fill(s.in, false);
                fill(s.out, false);
            } else {
                fill(s.out, true);  // a solid, left here
            }
        }
    }

    bool firstSurface(const Ray& ray, double tmin, double tmax, TraceContext& ctx, Boundary& hit,
                      bool& entering) const override {
        if (!mChild->firstSurface(ray, tmin, tmax, ctx, hit, entering)) return false;
        fill(hit, !entering);
        return true;
    }

    double value(const Vec3& p) const override { return mChild->value(p); }
    long double valueExtended(const LVec3& p) const override { return mChild->valueExtended(p); }
    Interval valueInterval(const IntervalVec3& box) const override {
        return mChild->valueInterval(box);
    }

    NodeKind kind() const override { return NodeKind::Interior; }
    NodeParams params() const override { return InteriorParams{mMaterial}; }
    NodeSpan children() const override { return {&mChild, 1}; }
    NodePtr withChildren(std::vector<NodePtr> children) const override {
        return std::make_shared<const Interior>(std::move(children.at(0)), mMaterial);
    }

private:
    /// leaving: a solid's boundary met from inside, which has no material yet; else only a
    /// surface's back side.
    void fill(Boundary& b, bool leaving) const {
        if (b.material == Boundary::kNoMaterialBack || (leaving && !b.hasMaterial()))
            b.material = mMaterial;
    }

    NodePtr mChild;
    int32_t mMaterial;
};

}  // namespace

NodePtr makeSurfaceOf(NodePtr solid) { return std::make_shared<const SurfaceOf>(std::move(solid)); }

NodePtr makeClip(NodePtr surface, NodePtr solid) {
    return std::make_shared<const Clip>(std::move(surface), std::move(solid));
}

NodePtr makeInterior(NodePtr child, int32_t material) {
    return std::make_shared<const Interior>(std::move(child), material);
}

bool isSurfaceTree(const Node& node) {
    const Node* n = &node;
    for (;;) {
        const NodeKind k = n->kind();
        if (isSurfaceKind(k)) return true;
        if (k != NodeKind::Transform && k != NodeKind::Material && k != NodeKind::Motion &&
            k != NodeKind::Interior)
            return false;
        n = n->children()[0].get();
    }
}

}  // namespace kerf
