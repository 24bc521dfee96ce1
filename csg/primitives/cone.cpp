// The capped cone (frustum) around an arbitrary axis. The lateral surface is the quadric
// |p⊥|² = (r1 + k·z)², which has two nappes; the slab between the caps keeps only the real one,
// since r1 + k·z ≥ 0 for 0 ≤ z ≤ L.
#include "csg/primitives/axial_frame.h"
#include "csg/primitives/closed_primitive.h"
#include "csg/primitives/implicit_expr.h"
#include "csg/primitives/quadratic.h"
#include "csg/tree/solids.h"

#include <algorithm>
#include <climits>

namespace kerf {
namespace {

/// A range of t where the ray is inside; `side*` says whether an end lies on the lateral
/// surface (else on a cap, or at ±inf).
struct InsideSpan {
    double lo, hi;
    bool sideLo, sideHi;
};

class Cone final : public ClosedFormPrimitive<Cone> {
public:
    Cone(const Vec3& a, const Vec3& b, double r1, double r2)
        : mFrame(a, b), mTop(b), mR1(r1), mR2(r2) {
        const Vec3& u = mFrame.axis;
        mSlope = (r2 - r1) / mFrame.length;
        mLateralScale = 1.0 / std::sqrt(1.0 + mSlope * mSlope);
        for (int i = 0; i < 3; ++i) {
            // Each cap disc reaches r·√(1 − u_i²) along world axis i; widened a few ulps
            // (the factor and u are rounded), then one ulp outward.
            const double s = std::sqrt(std::max(0.0, 1.0 - u[i] * u[i])) * (1.0 + 0x1p-50);
            const double lo = std::min(a[i] - r1 * s, b[i] - r2 * s);
            const double hi = std::max(a[i] + r1 * s, b[i] + r2 * s);
            mBounds.lo[i] = roundDown(lo);
            mBounds.hi[i] = roundUp(hi);
        }
    }

    /// max(lateral, slab): the lateral term (|p⊥| − r(z))/√(1 + k²) keeps it Lipschitz-1.
    double value(const Vec3& p) const override {
        double x, y, z;
        mFrame.toLocal(p, x, y, z);
        const double side = (std::sqrt(x * x + y * y) - (mR1 + mSlope * z)) * mLateralScale;
        return std::max(side, std::max(-z, z - mFrame.length));
    }

    long double valueExtended(const LVec3& p) const override {
        // From the given end points and radii, not the rounded frame.
        const ExactAxialPoint q(mFrame.base, mTop, p);
        const long double slope = ((long double)mR2 - mR1) / q.length;
        const long double side = (q.radial - (mR1 + slope * q.z)) / std::sqrt(1.0L + slope * slope);
        return std::max(side, std::max(-q.z, q.z - q.length));
    }

    Interval valueInterval(const IntervalVec3& b) const override {
        Interval x, y, z;
        mFrame.toLocal(b, x, y, z);
        const Interval side =
            (sqrt(nonNegative(sqr(x) + sqr(y))) - (mR1 + mSlope * z)) * mLateralScale;
        return max(side, max(-z, z - mFrame.length));
    }

    NodeKind kind() const override { return NodeKind::Cone; }
    NodeParams params() const override { return ConeParams{mFrame.base, mTop, mR1, mR2}; }

    ExprId implicitExpr(ExprGraph& g, ExprId x, ExprId y, ExprId z) const override {
        ExprBuilder e{g};
        ExprId lx, ly, lz;
        mFrame.toLocal(e, x, y, z, lx, ly, lz);
        const ExprId radius = e.add(e.c(mR1), e.mul(e.c(mSlope), lz));
        const ExprId side =
            e.mul(e.sub(e.sqrt(e.add(e.sqr(lx), e.sqr(ly))), radius), e.c(mLateralScale));
        return e.max(side, e.max(e.neg(lz), e.sub(lz, e.c(mFrame.length))));
    }

private:
    friend class ClosedFormPrimitive<Cone>;

    /// TraceMethod::Closed.
    void closedSpans(const Ray& ray, SpanList& out) const {
        Vec3 f, dl;
        CapSlab slab;
        if (!mFrame.localRay(ray, f, dl, slab)) return;
        const double m =
            std::max({std::fabs(f.x), std::fabs(f.y), std::fabs(f.z), mR1, mFrame.length});
        const double dm = std::max({std::fabs(dl.x), std::fabs(dl.y), std::fabs(dl.z)});
        if (m > kSquareSafe || m < 1.0 / kSquareSafe || dm > kSquareSafe || dm < 1.0 / kSquareSafe)
            return rescaledSpans(f, dl, slab, out);
        conicSpans(f, dl, mR1, mFrame.length, glm::dot(ray.dir, ray.dir), 0, slab, out);
    }

    /// Squares of numbers between 1/kSquareSafe and kSquareSafe neither overflow nor lose
    /// precision to underflow; outside it the ray is rescaled first (as the sphere does).
    static constexpr double kSquareSafe = 0x1p250;

    /// Cones and rays at extreme scales (1e±300): lengths (origin, r1, axis length) scaled by
    /// one power of two, the direction by another; the slope is a ratio and stays. Exact.
    void rescaledSpans(const Vec3& f, const Vec3& dl, const CapSlab& slab, SpanList& out) const {
        const int kp = std::ilogb(
            std::max({std::fabs(f.x), std::fabs(f.y), std::fabs(f.z), mR1, mFrame.length}));
        const int kd = std::ilogb(std::max({std::fabs(dl.x), std::fabs(dl.y), std::fabs(dl.z)}));
        // An infinite origin or direction (ilogb gives INT_MAX) meets nothing, and kp − kd
        // would overflow an int.
        if (kp == FP_ILOGBNAN || kd == FP_ILOGBNAN || kd == FP_ILOGB0 || kp == INT_MAX ||
            kd == INT_MAX)
            return;
        const Vec3 fs(std::ldexp(f.x, -kp), std::ldexp(f.y, -kp), std::ldexp(f.z, -kp));
        const Vec3 ds(std::ldexp(dl.x, -kd), std::ldexp(dl.y, -kd), std::ldexp(dl.z, -kd));
        conicSpans(fs, ds, std::ldexp(mR1, -kp), std::ldexp(mFrame.length, -kp), glm::dot(ds, ds),
                   kp - kd, slab, out);
    }

    /// The frustum along the local ray f + t·dl (|dl|² = dir2), radius r1 at the base and axis
    /// length `length` in the units of f; roots are scaled by 2^tExp (exact) to the slab's t.
    void conicSpans(const Vec3& f, const Vec3& dl, double r1, double length, double dir2, int tExp,
                    const CapSlab& slab, SpanList& out) const {
        const double fx = f.x, fy = f.y, fz = f.z, dx = dl.x, dy = dl.y, dz = dl.z;
        const double tin = slab.tin, tout = slab.tout;

        // The quadric along the ray: A·t² + 2B·t + C ≤ 0 inside either nappe, with
        // w0 + w1·t the signed cone radius at the ray's axial position.
        const double w0 = r1 + mSlope * fz, w1 = mSlope * dz;
        const double a = dx * dx + dy * dy - w1 * w1;
        const double h = fx * dx + fy * dy - w0 * w1;
        const double c = fx * fx + fy * fy - w0 * w0;
        // B² − A·C = |w0·d⊥ − w1·f⊥|² − (f⊥ × d⊥)² (Lagrange's identity), and it does not change
        // when the origin slides along the ray: evaluate it from the ray's point nearest the
        // middle of the axis, where the terms are small (Haines et al.'s idea for the sphere).
        const double ts = -(fx * dx + fy * dy + (fz - 0.5 * length) * dz) / dir2;
        const double gx = fx + ts * dx, gy = fy + ts * dy, gz = fz + ts * dz;
        const double v0 = r1 + mSlope * gz;
        const double ex = v0 * dx - w1 * gx, ey = v0 * dy - w1 * gy, cross = gx * dy - gy * dx;
        const double disc = ex * ex + ey * ey - cross * cross;

        InsideSpan pieces[2];
        int count = 0;
        if (a > 0.0) {  // one nappe crossed: inside between the roots
            if (!(disc > 0.0)) return;
            const QuadraticRoots r = solveQuadraticHalf(a, h, c, std::sqrt(disc));
            pieces[count++] = {std::ldexp(r.t0, tExp), std::ldexp(r.t1, tExp), true, true};
        } else if (a < 0.0) {  // steeper than the slant: inside outside the roots
            if (std::isnan(disc)) return;
            if (!(disc > 0.0)) {
                pieces[count++] = {-kInf, kInf, false, false};  // inside everywhere (touching)
            } else {
                const QuadraticRoots r = solveQuadraticHalf(a, h, c, std::sqrt(disc));
                pieces[count++] = {-kInf, std::ldexp(r.t0, tExp), false, true};
                pieces[count++] = {std::ldexp(r.t1, tExp), kInf, true, false};
            }
        } else if (h != 0.0) {  // parallel to the slant: 2B·t + C ≤ 0 is linear
            const double t = std::ldexp(-c / (2.0 * h), tExp);
            pieces[count++] =
                h > 0.0 ? InsideSpan{-kInf, t, false, true} : InsideSpan{t, kInf, true, false};
        } else {
            if (!(c <= 0.0)) return;
            pieces[count++] = {-kInf, kInf, false, false};
        }

        // Clip to the slab. The frustum is convex, so at most one piece survives; rounding
        // near the apex can leave two touching ones, which are joined.
        bool found = false;
        Boundary bin, bout;
        for (int i = 0; i < count; ++i) {
            const InsideSpan& p = pieces[i];
            const bool sideIn = p.lo > tin, sideOut = p.hi < tout;
            const double lo = sideIn ? p.lo : tin, hi = sideOut ? p.hi : tout;
            if (!(lo < hi)) continue;
            if (!found)
                bin = sideIn ? sideBoundary(lo, tExp, fx, fy, dx, dy) : capBoundary(lo, slab.capIn);
            bout = sideOut ? sideBoundary(hi, tExp, fx, fy, dx, dy) : capBoundary(hi, slab.capOut);
            found = true;
        }
        if (found) out.push_back({bin, bout});
    }

    Boundary capBoundary(double t, int cap) const {
        return boundary(t, mFrame.capNormal(cap));  // cap 0 (±inf) never occurs with dz ≠ 0
    }

    /// Outward normal of |p⊥| − (r1 + k·z) at the ray's point t: p̂⊥ − k·u, scaled by |p⊥|.
    /// t is the slab's; f and d are in the units where t·2^-tExp is the parameter.
    Boundary sideBoundary(double t, int tExp, double fx, double fy, double dx, double dy) const {
        const double ts = std::ldexp(t, -tExp);
        return boundary(t, sideNormal(fx + ts * dx, fy + ts * dy));
    }
    /// p̂⊥ − k·u scaled by |p⊥|, at local (px, py) across the axis (any common scale).
    Vec3 sideNormal(double px, double py) const {
        const double rho = std::sqrt(px * px + py * py);
        if (rho == 0.0) return mFrame.capNormal(mSlope > 0.0 ? -1 : 1);  // the apex: out of the tip
        return mFrame.across(px, py) - (mSlope * rho) * mFrame.axis;
    }

    AxialFrame mFrame;  // from the base (radius r1) towards the top (radius r2)
    Vec3 mTop;          ///< the given end point, for valueExtended
    double mR1, mR2;
    double mSlope;         // k = (r2 − r1)/L: the radius grows by k per unit along the axis
    double mLateralScale;  // 1/√(1 + k²)
};

}  // namespace

NodePtr makeCone(const Vec3& a, const Vec3& b, double r1, double r2) {
    return std::make_shared<Cone>(a, b, r1, r2);
}

}  // namespace kerf
