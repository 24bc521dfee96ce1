// The torus around the y axis: spans from the roots of its quartic along the ray.
//
// Conditioning: coordinates are divided by S = R + r (so every quantity is O(1) whatever the
// scene scale) and the ray is re-parameterised by arc length s from its point nearest the
// centre, p(s) = p0 + s·u with |u| = 1. The quartic in s then has coefficients of order 1 and
// no cancellation from a far-away origin. Every decision uses the better-conditioned
// h(p) = (ρ − R)² + (y − r)(y + r) (ρ = √(x² + z²)), which has the same sign as the quartic because
// the quartic is h times (ρ + R)² + y² − r² > 0.
//
// Default (closed) method: the ray within the bounding ball and the slab |y| ≤ r, a segment
// inside the hole rejected, then h piece by piece of one convexity (csg/primitives/torus_roots.h):
// tangents decide, steps to the root of h's local quadratic model locate; then one Newton step
// on h in the ray's own t. The interval method (for `kerf bench accuracy`, and
// the reference of the tests) isolates the quartic's roots by interval bisection with a
// Taylor-form enclosure at each sub-interval's midpoint (csg/primitives/root_isolation.h).
#include <algorithm>
#include <cmath>
#include <limits>

#include "csg/primitives/comparison_methods.h"
#include "csg/primitives/implicit_expr.h"
#include "csg/primitives/root_isolation.h"
#include "csg/primitives/torus_roots.h"
#include "csg/tree/solids.h"

namespace kerf {
namespace {

/// Absolute slack added to the enclosures (normalised units, where the coefficients are O(1)):
/// far above the rounding of the coefficients and of the Taylor terms, far below any value
/// that matters except within ~1e-13 of a tangency.
constexpr double kEnclosureSlack = 1e-13;
/// The largest relative move of t that the final Newton step in t may make.
constexpr double kRefineLimit = 1e-9;
/// Relative margin of the rejections and clips (ball, slab, hole) in normalised units: far
/// above the rounding of the squared distances compared, so no line near the surface is lost.
constexpr double kRejectMargin = 1e-9;

/// The quartic s⁴ + c3·s³ + c2·s² + c1·s + c0 along the normalised ray, and h along it.
struct TorusRay {
    double c3, c2, c1, c0;
    Vec3 p0, u;        ///< normalised ray: p(s) = p0 + s·u
    double c;          ///< |p0|²: the squared distance of the line from the centre
    double R, rm, r2;  ///< normalised major radius, minor radius and its square

    /// Taylor form at the midpoint: exact polynomial identity, so the enclosure holds the
    /// quartic (plus slack for rounding) over [a, b], and likewise its derivative.
    void range(double a, double b, Interval& f, Interval& dfds) const {
        const double m = 0.5 * (a + b), h = std::max(b - m, m - a);
        const double p0 = (((m + c3) * m + c2) * m + c1) * m + c0;
        const double p1 = ((4.0 * m + 3.0 * c3) * m + 2.0 * c2) * m + c1;
        const double p2 = (6.0 * m + 3.0 * c3) * m + c2;
        const double p3 = 4.0 * m + c3;
        const double h2 = h * h, h3 = h2 * h, h4 = h2 * h2;
        const double spread = std::fabs(p1) * h + std::fabs(p3) * h3;
        f = {p0 - spread + std::min(0.0, p2) * h2 - kEnclosureSlack,
             p0 + spread + std::max(0.0, p2) * h2 + h4 + kEnclosureSlack};
        const double dSpread = 2.0 * std::fabs(p2) * h + 4.0 * h3;
        dfds = {p1 - dSpread + std::min(0.0, 3.0 * p3) * h2 - kEnclosureSlack,
                p1 + dSpread + std::max(0.0, 3.0 * p3) * h2 + kEnclosureSlack};
    }
    double value(double s) const {
        const Vec3 q = p0 + s * u;
        const double rho = std::sqrt(q.x * q.x + q.z * q.z), e = rho - R;
        return e * e + (q.y - rm) * (q.y + rm);
    }
    double valueAndSlope(double s, double& dhds) const {
        const Vec3 q = p0 + s * u;
        const double rho = std::sqrt(q.x * q.x + q.z * q.z), e = rho - R;
        dhds = 2.0 * (e * (q.x * u.x + q.z * u.z) / rho + q.y * u.y);
        return e * e + (q.y - rm) * (q.y + rm);
    }
};

class Torus final : public Primitive {
public:
    Torus(double majorRadius, double minorRadius) : mR(majorRadius), mr(minorRadius) {
        const double e = mR + mr;
        mInv = 1.0 / e;
        mRn = mR * mInv;
        mrn = mr * mInv;
        mBounds = {Vec3(-e, -mr, -e), Vec3(e, mr, e)};
    }

    void spans(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
               SpanList& out) const override {
        if (ctx.method == TraceMethod::SphereTrace)
            return comparisonSpans(*this, ray, tmin, tmax, ctx, out);  // a distance: Lipschitz 1
        out.clear();
        ++ctx.stats.primitiveTests;
        Setup st;
        if (!setUp(ray, tmin, tmax, st, ctx.method == TraceMethod::Interval)) return;
        if (ctx.method == TraceMethod::Interval)
            return isolatedSpans(
                st.q, st.sA, st.sB, st.tc * st.sPerT, ctx,
                [&](double s) { return crossingBoundary(ray, st, s, ctx); },
                [&](bool atStart) { return endBoundary(ray, st, atStart); }, out);
        Boundary pending;
        bool inside = false;
        closedCrossings(
            st, ctx,
            [&](bool insideAtStart) {
                inside = insideAtStart;
                if (inside) pending = endBoundary(ray, st, true);
            },
            [&](double s, bool entering) {
                const Boundary b = crossingBoundary(ray, st, s, ctx);
                if (entering)
                    pending = b;
                else
                    out.push_back({pending, b});
                inside = entering;
            },
            [](double) { return false; });
        if (inside) out.push_back({pending, endBoundary(ray, st, false)});
        dropThinSpans(out, ctx.relTolerance);
    }

    /// The same crossings as spans(), but the search stops once the first surface is decided.
    bool firstSurface(const Ray& ray, double tmin, double tmax, TraceContext& ctx, Boundary& hit,
                      bool& entering) const override {
        if (ctx.method == TraceMethod::SphereTrace)
            return Node::firstSurface(ray, tmin, tmax, ctx, hit, entering);
        ++ctx.stats.primitiveTests;
        Setup st;
        if (!setUp(ray, tmin, tmax, st, ctx.method == TraceMethod::Interval)) return false;
        FirstSurfaceTracker tracker(tmin, tmax, ctx.relTolerance);
        // Crossings at s ≥ sNext map to t ≥ tc + sNext/sPerT (rounding is monotone), less what
        // refine() may move them.
        const auto horizon = [&](double sNext) {
            const double t = st.tc + sNext / st.sPerT;
            return t - 2.0 * kRefineLimit * std::fabs(t);
        };
        const auto surface = [&](double s) { return crossingBoundary(ray, st, s, ctx); };
        if (ctx.method == TraceMethod::Interval) {
            tracker.search(
                st.q, st.sA, st.sB, st.tc * st.sPerT, ctx, surface,
                [&](bool atStart) { return endBoundary(ray, st, atStart); }, horizon);
            return tracker.result(hit, entering);
        }
        bool stopped = false;
        closedCrossings(
            st, ctx,
            [&](bool inside) {
                tracker.start(inside, inside ? endBoundary(ray, st, true) : Boundary{});
            },
            [&](double s, bool enters) { tracker.crossing(surface(s), enters); },
            [&](double sNext) { return stopped = tracker.settledBefore(horizon(sNext)); });
        if (!stopped) tracker.finish(endBoundary(ray, st, false));
        return tracker.result(hit, entering);
    }

    double value(const Vec3& p) const override {
        const double rho = std::sqrt(p.x * p.x + p.z * p.z);
        return std::hypot(rho - mR, p.y) - mr;
    }

    long double valueExtended(const LVec3& p) const override {
        const long double rho = std::sqrt(p.x * p.x + p.z * p.z) - mR;
        return std::sqrt(rho * rho + p.y * p.y) - mr;
    }

    Interval valueInterval(const IntervalVec3& box) const override {
        const Interval rho = sqrt(nonNegative(sqr(box.x) + sqr(box.z)));
        return sqrt(nonNegative(sqr(rho - Interval(mR)) + sqr(box.y))) - Interval(mr);
    }

    NodeKind kind() const override { return NodeKind::Torus; }
    NodeParams params() const override { return TorusParams{mR, mr}; }

    ExprId implicitExpr(ExprGraph& g, ExprId x, ExprId y, ExprId z) const override {
        ExprBuilder e{g};
        const ExprId rho = e.sqrt(e.add(e.sqr(x), e.sqr(z)));
        return e.sub(e.sqrt(e.add(e.sqr(e.sub(rho, e.c(mR))), e.sqr(y))), e.c(mr));
    }

private:
    /// The normalised quartic along one ray and the range it is searched on.
    struct Setup {
        TorusRay q;
        double t0, t1;        ///< the caller's range clipped to the ball and slab around the torus
        bool t0Clip, t1Clip;  ///< t0 is the caller's tmin, t1 its tmax: not on the surface
        double sA, sB;        ///< the same in the normalised parameter s
        double tc;            ///< t of the point nearest the centre, where s = 0
        double sPerT;         ///< s = (t − tc)·sPerT
        double inv;           ///< 1/S
    };

    /// The closed method on [sA, sB]: start(inside at sA), then crossing(s, entering) for each
    /// crossing in increasing s; stopBefore(s) is asked before each piece from s on, and true
    /// ends the search (every crossing not yet reported lies at or after s).
    template <typename Start, typename Crossing, typename StopBefore>
    void closedCrossings(const Setup& st, TraceContext& ctx, Start&& start, Crossing&& crossing,
                         StopBefore&& stopBefore) const {
        const TorusRay& q = st.q;
        // (setUp has rejected lines outside the unit ball.) A segment inside the hole's cylinder
        // ρ < R − r misses: ρ² is convex along the line, so it is below (R − r)² throughout
        // when it is at both ends.
        const double hole = (q.R - q.rm) * (q.R - q.rm) * (1.0 - kRejectMargin);
        const auto rho2 = [&](double s) {  // from the point itself: no cancellation
            const double x = q.p0.x + s * q.u.x, z = q.p0.z + s * q.u.z;
            return x * x + z * z;
        };
        if (q.R > q.rm && rho2(st.sA) < hole && rho2(st.sB) < hole) {
            start(false);
            return;
        }
        const TorusLine line(q.p0, q.u, q.R, q.rm);
        double cuts[4];
        bool concave[3];
        const int n = line.pieces(st.sA, st.sB, cuts, concave);
        double hLo = line.value(cuts[0]);
        bool inside = isInside(hLo);
        start(inside);
        // Crossings to the rounding of t, not of s: s + tc·sPerT is proportional to t.
        const double absTol = std::numeric_limits<double>::epsilon() * std::fabs(st.tc * st.sPerT);
        long steps = 0;
        for (int i = 0; i < n; ++i) {
            if (stopBefore(cuts[i])) break;
            const double hHi = line.value(cuts[i + 1]);
            double s[2];
            TorusLine::Pending later;
            const int k = line.pieceCrossings(cuts[i], cuts[i + 1], hLo, hHi, concave[i], absTol, s,
                                              steps, &later);
            if (k > 0) crossing(s[0], inside = !inside);
            if (k == 2) {
                // The second crossing lies after later.x: often not needed to decide.
                if (stopBefore(later.x)) break;
                crossing(line.secondCrossing(later, absTol, steps), inside = !inside);
            }
            hLo = hHi;
        }
        ctx.stats.rootSteps += static_cast<uint64_t>(steps);
    }

    /// False when the ray misses the bounds within the range (or has no direction). The
    /// quartic's coefficients are computed only when `quartic` is set (the interval method).
    bool setUp(const Ray& ray, double tmin, double tmax, Setup& st, bool quartic) const {
        st.t0 = tmin, st.t1 = tmax;
        // A direction whose squared length would overflow or underflow (a torus scaled by
        // 1e±300 sees rays of length 1e∓300) is scaled by a power of two first: d = 2^kd·dir,
        // exact, and tc and len are scaled back. Same bits as before for other rays.
        Vec3 dir = ray.dir;
        int kd = 0;
        if (const double dd0 = glm::dot(dir, dir); !(dd0 >= 0x1p-500 && dd0 <= 0x1p500)) {
            const double big = std::max({std::fabs(dir.x), std::fabs(dir.y), std::fabs(dir.z)});
            if (!(big > 0.0) || !std::isfinite(big)) return false;
            kd = std::ilogb(big);
            dir = Vec3(std::ldexp(dir.x, -kd), std::ldexp(dir.y, -kd), std::ldexp(dir.z, -kd));
        }
        const double dd = glm::dot(dir, dir);
        if (!(dd > 0.0)) return false;

        // Normalise: lengths by S, the parameter by arc length from the point nearest the centre.
        // (ldexp is a library call: skipped in the common case kd = 0, where it is exact anyway.)
        double len = std::sqrt(dd), tc = -glm::dot(ray.origin, dir) / dd;
        if (kd != 0) len = std::ldexp(len, kd), tc = std::ldexp(tc, -kd);
        const double inv = mInv;
        TorusRay& q = st.q;
        q.p0 = (ray.origin + tc * ray.dir) * inv;
        const double c = glm::dot(q.p0, q.p0);
        // The torus lies in the unit ball (normalised): a line farther from the centre misses.
        if (!(c <= 1.0 + kRejectMargin)) return false;
        q.u = dir / std::sqrt(dd);
        q.R = mRn;
        q.rm = mrn;
        q.r2 = q.rm * q.rm;
        q.c = c;
        if (quartic) {  // only the interval method uses the polynomial
            // |p|² = s² + 2b·s + c, x² + z² = a2·s² + a1·s + a0; b ≈ 0 but kept for consistency.
            const double a2 = q.u.x * q.u.x + q.u.z * q.u.z;
            const double a1 = 2.0 * (q.p0.x * q.u.x + q.p0.z * q.u.z);
            const double a0 = q.p0.x * q.p0.x + q.p0.z * q.p0.z;
            const double b = glm::dot(q.p0, q.u);
            const double k = c + q.R * q.R - q.r2, fourR2 = 4.0 * q.R * q.R;
            // (s² + 2bs + k)² − 4R²(a2·s² + a1·s + a0)
            q.c3 = 4.0 * b;
            q.c2 = 4.0 * b * b + 2.0 * k - fourR2 * a2;
            q.c1 = 4.0 * b * k - fourR2 * a1;
            q.c0 = k * k - fourR2 * a0;
        }

        st.tc = tc;
        st.sPerT = len * inv;
        st.inv = inv;
        // Search the ray within the ball and the slab |y| ≤ r (both a little enlarged, so no
        // end of the range lies on the surface but where the caller's range ends there).
        const double half = std::sqrt(1.0 + kRejectMargin - c), slab = q.rm * (1.0 + kRejectMargin);
        double lo = -half, hi = half;
        if (q.u.y != 0.0) {
            const double y0 = (-slab - q.p0.y) / q.u.y, y1 = (slab - q.p0.y) / q.u.y;
            lo = std::fmax(lo, std::fmin(y0, y1));
            hi = std::fmin(hi, std::fmax(y0, y1));
        } else if (!(std::fabs(q.p0.y) <= slab)) {
            return false;
        }
        // The caller's range where it is tighter: its ends are clips, not surface.
        const double sMin = (tmin - tc) * st.sPerT, sMax = (tmax - tc) * st.sPerT;
        st.t0Clip = sMin >= lo;
        st.t1Clip = sMax <= hi;
        st.sA = st.t0Clip ? sMin : lo;
        st.sB = st.t1Clip ? sMax : hi;
        if (!(st.sA <= st.sB)) return false;
        st.t0 = st.t0Clip ? tmin : tc + lo / st.sPerT;
        st.t1 = st.t1Clip ? tmax : tc + hi / st.sPerT;
        return true;
    }

    /// The surface boundary of a crossing found at s.
    Boundary crossingBoundary(const Ray& ray, const Setup& st, double s,
                              const TraceContext& ctx) const {
        const double t = refine(ray, st.tc + s / st.sPerT, st.inv);
        return rootBoundary(t, normalAt(ray.at(t)), ctx);
    }

    /// An end of the clipped range: a clip of the caller's range, or (measure zero) a point of
    /// the surface where the box touches the torus.
    Boundary endBoundary(const Ray& ray, const Setup& st, bool atStart) const {
        const double t = atStart ? st.t0 : st.t1;
        if (atStart ? st.t0Clip : st.t1Clip) return clipBoundary(t);
        return boundary(t, normalAt(ray.at(t)));
    }

    /// Outward normal (not unit): ∇h/2 = ((ρ − R)·x/ρ, y, (ρ − R)·z/ρ).
    Vec3 normalAt(const Vec3& p) const {
        const double rho = std::sqrt(p.x * p.x + p.z * p.z);
        if (!(rho > 0.0)) return Vec3(0.0, p.y, 0.0);
        const double k = (rho - mR) / rho;
        return {k * p.x, p.y, k * p.z};
    }

    /// One Newton step on h in the ray's own parameter, which removes the rounding of
    /// t = tc + s/|d| when tc is large beside t. Taken only if it is a small correction.
    double refine(const Ray& ray, double t, double inv) const {
        const Vec3 p = ray.at(t) * inv, d = ray.dir * inv;
        const double rho = std::sqrt(p.x * p.x + p.z * p.z), e = rho - mR * inv, rn = mr * inv;
        const double h = e * e + (p.y - rn) * (p.y + rn);
        const double dh = 2.0 * (e * (p.x * d.x + p.z * d.z) / rho + p.y * d.y);
        const double step = h / dh;
        return std::fabs(step) <= kRefineLimit * std::fabs(t) ? t - step : t;
    }

    double mR, mr;
    double mInv;      ///< 1/(R + r): the normalising scale
    double mRn, mrn;  ///< R and r normalised
};

}  // namespace

NodePtr makeTorus(double majorRadius, double minorRadius) {
    return std::make_shared<Torus>(majorRadius, minorRadius);
}

}  // namespace kerf
