// Crossings of low-degree polynomials along a ray, by interval root isolation.
#include "csg/polynomial_isolation.h"

namespace kerf {

void findCrossings(const QuadraticAlongRay& q, double lo, double hi, double sOffset,
                   TraceContext& ctx, Crossings& out) {
    out.count = 0;
    QuadraticAlongRay p = q;
    out.insideAtStart = isolateRoots(p, lo, hi, sOffset, ctx, [&](double s, bool entering) {
        if (out.count == Crossings::kMax) {
            --out.count;  // drop the last crossing with this one: states keep alternating
            return;
        }
        out.s[out.count] = s;
        out.entering[out.count] = entering;
        ++out.count;
    });
}

bool clipToLinear(const QuadraticAlongRay& linear, int face, double sOffset, TraceContext& ctx,
                  FacedRange& r) {
    Crossings c;
    findCrossings(linear, r.lo, r.hi, sOffset, ctx, c);
    // A linear function crosses at most once; take the first entry and the first exit after
    // it should rounding ever report more.
    int i = 0;
    if (!c.insideAtStart) {
        if (c.count == 0) return false;
        r.lo = c.s[0];
        r.loFace = face;
        i = 1;
    }
    if (i < c.count) {
        r.hi = c.s[i];
        r.hiFace = face;
    }
    return r.lo < r.hi;
}

}  // namespace kerf
