/// @file csg/primitives/root_isolation.h
/// @brief Finds every sign change of f(t) on a finite [tmin, tmax]: recursive bisection driven
/// by interval enclosures of f and df/dt, then a guarded Newton / Illinois polish of each
/// isolated root. Used by the torus and the implicit primitive, whose first-surface search
/// stops early through FirstSurfaceTracker.
///
/// The problem type P supplies (all inline, no virtual calls):
///   void range(double a, double b, Interval& f, Interval& dfdt) — enclosures over [a, b];
///   double value(double t)                                  — f at a point;
///   double valueAndSlope(double t, double& dfdt)             — f and df/dt at a point.
/// "Inside" means value(t) ≤ 0. Crossings are reported only where the inside/outside state of
/// two evaluated points differs, so the reported crossings always alternate consistently with
/// the state at tmin, even where an enclosure is spoiled by rounding.
/// A problem type may also have `bool certifiedSteps`, `double minCertifiedShrink` and
///   void enclosuresAt(const double* t, int n, Interval* f) — rigorous f at n ≤ 4 points;
/// then each undecided piece first tries a certified step (csg/primitives/lipschitz_step.h).
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

#include "csg/interval/interval.h"
#include "csg/primitives/lipschitz_step.h"
#include "csg/trace_context.h"
#include "csg/tree/node.h"
#include "csg/tree/span.h"

namespace kerf {

/// Deepest bisection level: 2⁻⁶⁴ of a finite range is below any tolerance worth asking for.
constexpr int kRootMaxDepth = 64;
/// Iterations of the polish before it settles for the bracket it has.
constexpr int kRootMaxPolish = 60;

inline bool isInside(double f) { return f <= 0.0; }  // NaN counts as outside

/// Whether problem type P has a `certifiedSteps` member (csg/primitives/lipschitz_step.h); the
/// search tries a certified shrink before each bisection when it is true.
template <typename P, typename = void>
struct HasCertifiedSteps : std::false_type {};
template <typename P>
struct HasCertifiedSteps<P, std::void_t<decltype(std::declval<const P&>().certifiedSteps)>>
    : std::true_type {};

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
            // (A caller that needs only where the surface is stops here.)
            if (step <= ctx.relTolerance * std::fabs(t + tOffset) &&
                (ctx.occlusionOnly || ++extraSteps > 2))
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
///
/// stopBefore(a) is asked before each sub-interval [a, b] is examined; sub-intervals come in
/// increasing a, and every crossing not yet reported lies at or after a. Returning true ends
/// the search there (a caller that wants only the first crossings). The crossings reported
/// before the stop are bit-identical to those of a full search: each sub-interval is handled
/// alone, in the same order.
/// f0 is p.value(tmin), which the caller has already computed.
template <typename P, typename Sink, typename StopBefore>
bool isolateRootsFrom(P& p, double tmin, double tmax, double f0, double tOffset, TraceContext& ctx,
                      Sink&& sink, StopBefore&& stopBefore) {
    using Piece = RootPiece;
    Piece stack[kRootMaxDepth + 2];
    int top = 0;
    stack[top++] = {tmin, tmax, f0, tmax == tmin ? f0 : p.value(tmax), 0};
    while (top > 0) {
        Piece q = stack[--top];
        if (stopBefore(q.a)) break;
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
        if constexpr (HasCertifiedSteps<P>::value) {
            if (p.certifiedSteps) {
                Piece r = q;
                const ShrinkResult shrink =
                    certifiedShrink(p, f, slope, r, p.minCertifiedShrink, ctx);
                if (shrink == ShrinkResult::NoCrossing) continue;
                if (shrink == ShrinkResult::Shrunk) {
                    ++r.depth;  // bounds the shrinks too (each takes a fixed fraction or more)
                    stack[top++] = r;
                    continue;
                }
                q.ga = r.ga, q.gb = r.gb;  // margins found on the way stay with the halves
            }
        }
        const double m = 0.5 * (q.a + q.b);
        if (!(m > q.a && m < q.b)) {  // adjacent doubles
            if (inA != inB) sink(q.b, inB);
            continue;
        }
        ++ctx.stats.rootSteps;
        const double fm = p.value(m);
        // Right first, so left pops first; the ends keep their certified margins.
        stack[top++] = {m, q.b, fm, q.fb, q.depth + 1, 0.0, q.gb};
        stack[top++] = {q.a, m, q.fa, fm, q.depth + 1, q.ga, 0.0};
    }
    return isInside(f0);
}

template <typename P, typename Sink, typename StopBefore>
bool isolateRoots(P& p, double tmin, double tmax, double tOffset, TraceContext& ctx, Sink&& sink,
                  StopBefore&& stopBefore) {
    return isolateRootsFrom(p, tmin, tmax, p.value(tmin), tOffset, ctx, sink, stopBefore);
}

/// Every crossing (no early stop).
template <typename P, typename Sink>
bool isolateRoots(P& p, double tmin, double tmax, double tOffset, TraceContext& ctx, Sink&& sink) {
    return isolateRoots(p, tmin, tmax, tOffset, ctx, sink, [](double) { return false; });
}

/// Node::spans for a primitive whose spans are built from every crossing of isolateRoots over
/// [tmin, tmax]: surface(t) makes the boundary of a crossing, end(atStart) that of a range end
/// where the ray is inside (p.value(tmin) ≤ 0 at the start). Spans thinner than the tolerance,
/// left by touches (double roots), are dropped.
template <typename P, typename Surface, typename End>
void isolatedSpans(P& p, double tmin, double tmax, double tOffset, TraceContext& ctx,
                   Surface&& surface, End&& end, SpanList& out) {
    const double f0 = p.value(tmin);
    bool inside = isInside(f0);
    Boundary pending = inside ? end(true) : Boundary{};
    isolateRootsFrom(
        p, tmin, tmax, f0, tOffset, ctx,
        [&](double t, bool entering) {
            const Boundary b = surface(t);
            if (entering)
                pending = b;
            else
                out.push_back({pending, b});
            inside = entering;
        },
        [](double) { return false; });
    if (inside) out.push_back({pending, end(false)});
    dropThinSpans(out, ctx.relTolerance);
}

/// Node::firstSurface for a primitive whose spans are built from isolateRoots' crossings: it
/// takes the crossings as spans() turns them into spans and decides the first surface boundary
/// as soon as no later crossing can change it, so the search can stop there. The answer equals
/// firstSurfaceOf(spans after dropThinSpans) by construction: the same two functions run on the
/// leading spans once later crossings can no longer merge with them or make them thin.
class FirstSurfaceTracker {
public:
    FirstSurfaceTracker(double tmin, double tmax, double relTolerance)
        : mTmin(tmin),
          mTmax(tmax),
          mRelTolerance(relTolerance),
          mHorizonRel(2.0 * std::fmax(relTolerance, 1e-12)) {}

    /// The state where the searched range starts: inside, with `entry` the boundary there.
    void start(bool inside, const Boundary& entry) {
        mInside = inside;
        if (inside) mPending = entry, mHorizon = horizonAfter(entry.t);
    }

    /// The next crossing (they come in increasing t).
    void crossing(const Boundary& b, bool entering) {
        if (entering)
            mPending = b;
        else
            mTail.push_back({mPending, b});
        mInside = entering;
        mHorizon = horizonAfter(b.t);
    }

    /// For isolateRoots' stopBefore: every crossing still to come lies at t ≥ tNext. True once
    /// the answer is decided (the search can stop).
    bool settledBefore(double tNext) {
        if (!(tNext > mHorizon)) return false;
        mHorizon = kInf;
        if (mInside) {
            // The open span ends beyond the horizon, so it is not thin, whatever its real end;
            // a placeholder end (not a surface) stands in for it.
            Boundary openEnd;
            openEnd.t = tNext;
            mTail.push_back({mPending, openEnd});
        }
        dropThinSpans(mTail, mRelTolerance);
        mDone = firstSurfaceOf(mTail, mTmin, mTmax, mHit, mEntering);
        // Undecided: only the open span's entry (merged with thin gaps before it) still matters.
        if (!mDone && mInside) mPending = mTail.back().in;
        mTail.clear();
        return mDone;
    }

    /// After a search that ran to the end of the range: the range ends at `end`, which closes
    /// the open span if the ray is inside there.
    void finish(const Boundary& end) {
        if (mDone) return;
        if (mInside) mTail.push_back({mPending, end});
        dropThinSpans(mTail, mRelTolerance);
        mDone = firstSurfaceOf(mTail, mTmin, mTmax, mHit, mEntering);
    }

    /// The whole search, as isolatedSpans makes spans: p's crossings on [a, b] (isolateRoots),
    /// surface(x) the boundary of a crossing at x, end(atStart) that of an end of [a, b].
    /// horizon(xNext): a t before every crossing at x ≥ xNext, for stopping early.
    template <typename P, typename Surface, typename End, typename Horizon>
    void search(P& p, double a, double b, double offset, TraceContext& ctx, Surface&& surface,
                End&& end, Horizon&& horizon) {
        const double f0 = p.value(a);
        const bool inside = isInside(f0);
        start(inside, inside ? end(true) : Boundary{});
        isolateRootsFrom(
            p, a, b, f0, offset, ctx, [&](double x, bool enters) { crossing(surface(x), enters); },
            [&](double xNext) { return settledBefore(horizon(xNext)); });
        finish(end(false));
    }

    /// The first surface boundary, if there is one.
    bool result(Boundary& hit, bool& entering) const {
        if (!mDone) return false;
        hit = mHit;
        entering = mEntering;
        return true;
    }

private:
    /// A t beyond which no crossing can make a thin gap or span (dropThinSpans) with a
    /// boundary at t: the thin test with twice the tolerance, so rounding cannot matter.
    double horizonAfter(double t) const {
        if (!(mHorizonRel < 0.5)) return kInf;  // absurd tolerances: never stop early
        return t >= 0.0 ? t / (1.0 - mHorizonRel) : t - mHorizonRel * t;
    }

    double mTmin, mTmax;
    double mRelTolerance;  ///< as spans() passes it to dropThinSpans
    double mHorizonRel;
    SpanList mTail;  ///< closed spans that later crossings may still change
    Boundary mPending;
    bool mInside = false;
    double mHorizon = kInf;  ///< settle once the search has passed this t
    bool mDone = false;
    Boundary mHit;
    bool mEntering = false;
};

}  // namespace kerf
