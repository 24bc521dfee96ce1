// The default first-surface search: all spans, then the first surface boundary after tmin.
#include "csg/node.h"

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

bool Node::firstSurface(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
                        Boundary& hit, bool& entering) const {
    ScratchSpans spans(ctx.scratch);
    this->spans(ray, tmin, tmax, ctx, *spans);
    return firstSurfaceOf(*spans, tmin, tmax, hit, entering);
}

}  // namespace kerf
