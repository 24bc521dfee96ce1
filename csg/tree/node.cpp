// The default first-surface search (all spans, then the first surface boundary after tmin),
// and the names of the node kinds.
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

const char* nodeKindName(NodeKind kind) {
    switch (kind) {
        case NodeKind::Sphere: return "sphere";
        case NodeKind::Box: return "box";
        case NodeKind::Cylinder: return "cylinder";
        case NodeKind::Cone: return "cone";
        case NodeKind::Torus: return "torus";
        case NodeKind::HalfSpace: return "halfspace";
        case NodeKind::Implicit: return "implicit";
        case NodeKind::Volume: return "volume";
        case NodeKind::Mesh: return "mesh";
        case NodeKind::Transform: return "transform";
        case NodeKind::Material: return "material";
        case NodeKind::Motion: return "motion";
        case NodeKind::Union: return "union";
        case NodeKind::Intersection: return "intersection";
        case NodeKind::Difference: return "difference";
        case NodeKind::Xor: return "xor";
        case NodeKind::Disc: return "disc";
        case NodeKind::Triangle: return "triangle";
        case NodeKind::OpenCone: return "open cone";
        case NodeKind::SurfaceOf: return "surface";
        case NodeKind::Clip: return "clip";
        case NodeKind::Interior: return "interior";
    }
    return "?";
}

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
