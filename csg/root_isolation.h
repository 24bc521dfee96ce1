/// @file csg/root_isolation.h
/// @brief Finds every sign change of f(t) on a finite [tmin, tmax]: recursive bisection driven
/// by interval enclosures of f and df/dt, then a guarded Newton / Illinois polish of each
/// isolated root. Used by the torus and the implicit primitive.
///
/// The problem type P supplies (all inline, no virtual calls):
///   void range(double a, double b, Interval& f, Interval& dfdt) — enclosures over [a, b];
///   double value(double t)                                  — f at a point;
///   double valueAndSlope(double t, double& dfdt)             — f and df/dt at a point.
/// "Inside" means value(t) ≤ 0. Crossings are reported only where the inside/outside state of
/// two evaluated points differs, so the reported crossings always alternate consistently with
/// the state at tmin, even where an enclosure is spoiled by rounding.
#pragma once

#include <cmath>
#include <limits>

#include "csg/interval.h"
#include "csg/trace_context.h"

namespace kerf {

/// Deepest bisection level: 2⁻⁶⁴ of a finite range is below any tolerance worth asking for.
constexpr int kRootMaxDepth = 64;
/// Iterations of the polish before it settles for the bracket it has.
constexpr int kRootMaxPolish = 60;

inline bool isInside(double f) { return f <= 0.0; }  // NaN counts as outside

/// True when [a, b] is narrower than the tolerance near it. The tolerance is relative to the
/// ray's own parameter t, proportional to (a + tOffset) when the problem uses a shifted one.
inline bool narrowerThanTolerance(double a, double b, double relTolerance, double tOffset) {
    return b - a <= relTolerance * std::fmax(std::fabs(a + tOffset), std::fabs(b + tOffset));
}

/// The one sign change of f inside [a, b], where f(a) = fa and f(b) = fb differ in state and f
/// is monotone. Newton steps that stay inside the bracket are taken; otherwise an Illinois
/// (modified regula-falsi) step. Stops when Newton converges to full double precision, or when
/// the bracket is below the tolerance and Newton is not converging.
template <typename P>
double polishRoot(P& p, double a, double b, double fa, double fb, double tOffset,
                  TraceContext& ctx) {
    if (fa == 0.0) return a;  // an end exactly on the surface is the crossing
    if (fb == 0.0) return b;
    const bool insideA = isInside(fa);
    double t = a - fa * (b - a) / (fb - fa);
    if (!(t > a && t < b)) t = 0.5 * (a + b);
    int extraSteps = 0;
    int staleSide = 0;  // which end the Illinois rule has kept twice in a row (−1 a, +1 b)
    for (int it = 0; it < kRootMaxPolish; ++it) {
        ++ctx.stats.rootSteps;
        double slope = 0.0;
        const double f = p.valueAndSlope(t, slope);
        if (f == 0.0) return t;
        if (isInside(f) == insideA) {
            a = t, fa = f;
            if (staleSide == -1) fb *= 0.5;  // Illinois: halve the end that keeps staying
            staleSide = -1;
        } else {
            b = t, fb = f;
            if (staleSide == 1) fa *= 0.5;
            staleSide = 1;
        }
        const double newton = t - f / slope;
        const double step = std::fabs(newton - t);
        // Converged to double precision (the step may round onto a bracket end: still done).
        const double scale = std::fmax(std::fabs(t), std::fabs(t + tOffset));
        if (step <= 4.0 * std::numeric_limits<double>::epsilon() * scale)
            return std::fmin(std::fmax(newton, a), b);
        if (newton > a && newton < b) {
            // Within the tolerance already: two more quadratic steps reach double precision
            // when Newton converges; stop there if it does not.
            if (step <= ctx.relTolerance * std::fabs(t + tOffset) && ++extraSteps > 2)
                return newton;
            t = newton;
            continue;
        }
        if (narrowerThanTolerance(a, b, ctx.relTolerance, tOffset) || !(b > a)) break;
        t = a - fa * (b - a) / (fb - fa);
        if (!(t > a && t < b)) t = 0.5 * (a + b);
    }
    return 0.5 * (a + b);
}

/// Calls sink(t, entering) for every crossing of f between tmin and tmax (finite, tmin ≤ tmax),
/// in increasing t; `entering` is true where the ray goes from outside to inside. Returns
/// whether tmin itself is inside. A touch (f reaches 0 without changing sign: tangency,
/// double root) makes no crossing, or a pair of crossings closer than the tolerance.
/// tOffset: (parameter + tOffset) is proportional to the ray's t, to which tolerances refer.
template <typename P, typename Sink>
bool isolateRoots(P& p, double tmin, double tmax, double tOffset, TraceContext& ctx, Sink&& sink) {
    struct Piece {
        double a, b, fa, fb;
        int depth;
    };
    Piece stack[kRootMaxDepth + 2];
    int top = 0;
    const double f0 = p.value(tmin);
    stack[top++] = {tmin, tmax, f0, tmax == tmin ? f0 : p.value(tmax), 0};
    while (top > 0) {
        const Piece q = stack[--top];
        const bool inA = isInside(q.fa), inB = isInside(q.fb);
        Interval f, slope;
        p.range(q.a, q.b, f, slope);
        ++ctx.stats.intervalEvals;
        const Classification c = f.classify();
        // One state throughout, agreeing with both ends: nothing here.
        if (c == Classification::Empty && !inA && !inB) continue;
        if (c == Classification::Filled && inA && inB) continue;
        const bool monotone = !slope.maybeNan && (slope.lo > 0.0 || slope.hi < 0.0);
        if (monotone) {
            if (inA != inB) sink(polishRoot(p, q.a, q.b, q.fa, q.fb, tOffset, ctx), inB);
            continue;  // strictly monotone with equal states at the ends: no crossing
        }
        if (q.depth >= kRootMaxDepth ||
            narrowerThanTolerance(q.a, q.b, ctx.relTolerance, tOffset)) {
            // Undecided and below the tolerance: a crossing if the states differ (polished
            // anyway: cheap, and it stays in the bracket), else a touch.
            if (inA != inB) sink(polishRoot(p, q.a, q.b, q.fa, q.fb, tOffset, ctx), inB);
            continue;
        }
        const double m = 0.5 * (q.a + q.b);
        if (!(m > q.a && m < q.b)) {  // adjacent doubles
            if (inA != inB) sink(q.b, inB);
            continue;
        }
        ++ctx.stats.rootSteps;
        const double fm = p.value(m);
        stack[top++] = {m, q.b, fm, q.fb, q.depth + 1};  // right first, so left pops first
        stack[top++] = {q.a, m, q.fa, fm, q.depth + 1};
    }
    return isInside(f0);
}

}  // namespace kerf
