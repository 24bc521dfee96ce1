// The default first-surface search (all spans, then the first surface boundary after tmin),
// and the Boolean kinds (the kinds' names: csg/tree/kind_registry.cpp).
#include "csg/tree/node.h"

namespace kerf {

bool firstSurfaceOf(const SpanList& spans, double tmin, double tmax, Boundary& hit,
                    bool& entering) {
    for (const Span& s : spans) {
        if (s.in.t > tmax) return false;
        if (!(s.in.t < s.out.t)) continue;  // a zero-width touch is not a crossing
        if (s.in.t > tmin && s.in.isSurface()) {
            hit = s.in;
            entering = true;
            return true;
        }
        if (s.out.t > tmin && s.out.t <= tmax && s.out.isSurface()) {
            hit = s.out;
            entering = false;
            return true;
        }
    }
    return false;
}

bool Node::firstSurface(const Ray& ray, double tmin, double tmax, TraceContext& ctx, Boundary& hit,
                        bool& entering) const {
    ScratchSpans spans(ctx.scratch);
    this->spans(ray, tmin, tmax, ctx, *spans);
    return firstSurfaceOf(*spans, tmin, tmax, hit, entering);
}

}  // namespace kerf

namespace kerf {

NodeKind booleanKind(BoolOp op) {
    switch (op) {
        case BoolOp::Union: return NodeKind::Union;
        case BoolOp::Intersection: return NodeKind::Intersection;
        case BoolOp::Difference: return NodeKind::Difference;
        case BoolOp::Xor: return NodeKind::Xor;
    }
    return NodeKind::Union;
}

BoolOp booleanOp(NodeKind kind) {
    switch (kind) {
        case NodeKind::Intersection: return BoolOp::Intersection;
        case NodeKind::Difference: return BoolOp::Difference;
        case NodeKind::Xor: return BoolOp::Xor;
        default: return BoolOp::Union;
    }
}

}  // namespace kerf
