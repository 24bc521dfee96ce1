// Crossings of polynomials of degree ≤ 2 along a ray: a cut at the vertex makes monotone
// pieces, decided by their end values, and a guarded Newton polish of each crossing.
#include "csg/polynomial_isolation.h"

namespace kerf {
namespace {

/// The one crossing of q inside [a, b], a monotone piece whose end values fa, fb differ in
/// state. Newton starts at the end where q·c2 > 0 (Fourier's condition): from there the
/// iterates approach the root from one side and stay in the bracket. For a quadratic the
/// error after a step of length d from x is exactly e = k·(d ± e)² with k = |c2 / q'(x)|,
/// and since the root lies on x's side of the vertex (|e| < 1/2k), 4·k·d ≤ 1 gives
/// e ≤ 4·k·d²; the iterate is returned as soon as that bound plus the rounding of q(x) is
/// within the tolerance, often one evaluation before the step itself is that small.
double polishCrossing(const QuadraticAlongRay& q, double a, double b, double fa, double fb,
                      double sOffset, TraceContext& ctx) {
    if (fa == 0.0) return a;  // an end exactly on the surface is the crossing
    if (fb == 0.0) return b;
    const bool insideA = isInside(fa);
    const bool fromA = q.c2 == 0.0 ? std::fabs(fa) <= std::fabs(fb) : (fa > 0.0) == (q.c2 > 0.0);
    double x = fromA ? a : b, fx = fromA ? fa : fb;
    double lastStep = std::numeric_limits<double>::infinity();
    for (int it = 0; it < kRootMaxPolish; ++it) {
        ++ctx.stats.rootSteps;
        const double slope = q.slope(x);
        const double step = -fx / slope;
        const double next = x + step;
        if (next > a && next < b) {
            const double d = std::fabs(step), k = std::fabs(q.c2 / slope);
            const double error = 4.0 * k * d * d + q.rounding(x) / std::fabs(slope);
            if (4.0 * k * d <= 1.0 && error <= ctx.relTolerance * std::fabs(next + sOffset)) {
                // One more step squares that error: near double precision for little cost.
                ++ctx.stats.rootSteps;
                const double last = next - q.value(next) / q.slope(next);
                return std::fmin(std::fmax(last, a), b);
            }
            // Newton's steps shrink until rounding noise takes over: stop there.
            if (!(d < lastStep)) return next;
            lastStep = d;
            x = next;
        } else {
            // Rounding (or a NaN) put the step outside the bracket: bisect instead.
            if (narrowerThanTolerance(a, b, ctx.relTolerance, sOffset)) break;
            x = 0.5 * (a + b);
            if (!(x > a && x < b)) break;  // adjacent doubles
            lastStep = std::numeric_limits<double>::infinity();
        }
        fx = q.value(x);
        if (fx == 0.0) return x;
        if (isInside(fx) == insideA)
            a = x;
        else
            b = x;
    }
    return 0.5 * (a + b);
}

}  // namespace

void findCrossings(const QuadraticAlongRay& q, double lo, double hi, double sOffset,
                   TraceContext& ctx, Crossings& out) {
    out.count = 0;
    ++ctx.stats.intervalEvals;
    // The derivative 2·c2·s + c1 is linear: where its zero (the vertex) lies inside the range,
    // its enclosure on the range holds 0, and one cut there makes two pieces on which it has
    // one sign. The vertex value is also q's extreme: when it lies beyond the rounding on
    // the side of c2's sign, q's enclosure on the whole range excludes 0 (one state).
    double cut = hi, fCut = 0.0;
    if (q.c2 != 0.0) {
        const double v = -q.c1 / (2.0 * q.c2);
        if (lo < v && v < hi) {
            fCut = q.value(v);
            const double slack = q.rounding(v);
            if (q.c2 > 0.0 ? fCut > slack : fCut < -slack) {
                out.insideAtStart = q.c2 < 0.0;
                return;
            }
            cut = v;
        }
    }
    const double fLo = q.value(lo);
    out.insideAtStart = isInside(fLo);
    if (!(lo < hi)) return;
    const double fHi = q.value(hi);
    const auto piece = [&](double a, double b, double fa, double fb) {
        // Monotone: q's exact range here is the hull of fa and fb.
        if (isInside(fa) == isInside(fb)) return;
        out.s[out.count] = polishCrossing(q, a, b, fa, fb, sOffset, ctx);
        out.entering[out.count] = isInside(fb);
        ++out.count;
    };
    if (cut < hi) {
        piece(lo, cut, fLo, fCut);
        piece(cut, hi, fCut, fHi);
    } else {
        piece(lo, hi, fLo, fHi);
    }
}

bool clipToLinear(const QuadraticAlongRay& linear, int face, double sOffset, TraceContext& ctx,
                  FacedRange& r) {
    Crossings c;
    findCrossings(linear, r.lo, r.hi, sOffset, ctx, c);
    // A linear function crosses at most once.
    if (!c.insideAtStart) {
        if (c.count == 0) return false;
        r.lo = c.s[0];
        r.loFace = face;
    } else if (c.count > 0) {
        r.hi = c.s[0];
        r.hiFace = face;
    }
    return r.lo < r.hi;
}

}  // namespace kerf
