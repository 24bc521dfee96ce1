// The capped cylinder around an arbitrary axis: a 2-D Haines-style quadratic across the axis
// intersected with the slab between the caps.
#include "csg/primitives/axial_frame.h"
#include "csg/primitives/closed_primitive.h"
#include "csg/primitives/implicit_expr.h"
#include "csg/primitives/quadratic.h"
#include "csg/tree/solids.h"

#include <algorithm>
#include <climits>

namespace kerf {
namespace {

// Directions closer to the axis than 2^-52 rad are treated as parallel: the rounding of the
// local coordinates is larger than their sideways drift, and the roots would overflow.
constexpr double kParallel2 = 0x1p-104;

class Cylinder final : public ClosedFormPrimitive<Cylinder> {
public:
    Cylinder(const Vec3& a, const Vec3& b, double radius)
        : mFrame(a, b), mTop(b), mRadius(radius), mRadius2(radius * radius) {
        const Vec3& u = mFrame.axis;
        for (int i = 0; i < 3; ++i) {
            // The cap discs reach r·√(1 − u_i²) along world axis i; one ulp outward if inexact.
            // e is widened by a few ulps first, since it and u are themselves rounded.
            const double e = radius * std::sqrt(std::max(0.0, 1.0 - u[i] * u[i])) * (1.0 + 0x1p-50);
            const double lo = std::min(a[i], b[i]), hi = std::max(a[i], b[i]);
            mBounds.lo[i] = e == 0.0 ? lo : roundDown(lo - e);
            mBounds.hi[i] = e == 0.0 ? hi : roundUp(hi + e);
        }
    }

    /// max(distance from the axis − r, slab distance): Lipschitz-1.
    double value(const Vec3& p) const override {
        double x, y, z;
        mFrame.toLocal(p, x, y, z);
        const double side = std::sqrt(x * x + y * y) - mRadius;
        return std::max(side, std::max(-z, z - mFrame.length));
    }

    long double valueExtended(const LVec3& p) const override {
        const ExactAxialPoint q(mFrame.base, mTop, p);  // not from the rounded frame
        return std::max(q.radial - (long double)mRadius, std::max(-q.z, q.z - q.length));
    }

    Interval valueInterval(const IntervalVec3& b) const override {
        Interval x, y, z;
        mFrame.toLocal(b, x, y, z);
        const Interval side = sqrt(nonNegative(sqr(x) + sqr(y))) - mRadius;
        return max(side, max(-z, z - mFrame.length));
    }

    NodeKind kind() const override { return NodeKind::Cylinder; }
    NodeParams params() const override { return CylinderParams{mFrame.base, mTop, mRadius}; }

    ExprId implicitExpr(ExprGraph& g, ExprId x, ExprId y, ExprId z) const override {
        ExprBuilder e{g};
        ExprId lx, ly, lz;
        mFrame.toLocal(e, x, y, z, lx, ly, lz);
        const ExprId side = e.sub(e.sqrt(e.add(e.sqr(lx), e.sqr(ly))), e.c(mRadius));
        return e.max(side, e.max(e.neg(lz), e.sub(lz, e.c(mFrame.length))));
    }

private:
    friend class ClosedFormPrimitive<Cylinder>;

    /// TraceMethod::Closed.
    void closedSpans(const Ray& ray, SpanList& out) const {
        Vec3 f, dl;
        CapSlab slab;
        if (!mFrame.localRay(ray, f, dl, slab)) return;
        const double m = std::max({std::fabs(f.x), std::fabs(f.y), mRadius});
        const double dm = std::max({std::fabs(dl.x), std::fabs(dl.y), std::fabs(dl.z)});
        if (m > kSquareSafe || m < 1.0 / kSquareSafe || dm > kSquareSafe || dm < 1.0 / kSquareSafe)
            return rescaledSpans(f, dl, slab, out);
        sideSpans(f.x, f.y, dl.x, dl.y, mRadius2, glm::dot(ray.dir, ray.dir), 0, slab, out);
    }

    /// Squares of numbers between 1/kSquareSafe and kSquareSafe neither overflow nor lose
    /// precision to underflow; outside it the ray is rescaled first (as the sphere does).
    static constexpr double kSquareSafe = 0x1p250;

    /// Cylinders and rays at extreme scales (1e±300): the across-axis origin and the radius
    /// scaled by one power of two, the direction by another; both exact, roots scaled back.
    void rescaledSpans(const Vec3& f, const Vec3& dl, const CapSlab& slab, SpanList& out) const {
        const int kp = std::ilogb(std::max({std::fabs(f.x), std::fabs(f.y), mRadius}));
        const int kd = std::ilogb(std::max({std::fabs(dl.x), std::fabs(dl.y), std::fabs(dl.z)}));
        // An infinite origin or direction (ilogb gives INT_MAX) meets nothing, and kp − kd
        // would overflow an int.
        if (kp == FP_ILOGBNAN || kd == FP_ILOGBNAN || kd == FP_ILOGB0 || kp == INT_MAX ||
            kd == INT_MAX)
            return;
        const Vec3 ds(std::ldexp(dl.x, -kd), std::ldexp(dl.y, -kd), std::ldexp(dl.z, -kd));
        const double rs = std::ldexp(mRadius, -kp);
        sideSpans(std::ldexp(f.x, -kp), std::ldexp(f.y, -kp), ds.x, ds.y, rs * rs, glm::dot(ds, ds),
                  kp - kd, slab, out);
    }

    /// The side |(fx, fy) + t·(dx, dy)|² ≤ r2 clipped to the slab; dir2 is |d|² in the same
    /// units as dx, dy. Roots are scaled by 2^tExp (exact) back to the slab's units.
    void sideSpans(double fx, double fy, double dx, double dy, double r2, double dir2, int tExp,
                   const CapSlab& slab, SpanList& out) const {
        double tin = slab.tin, tout = slab.tout;
        // Across the axis: |(fx, fy) + t·(dx, dy)|² ≤ r².
        const double a = dx * dx + dy * dy;
        const double h = fx * dx + fy * dy;
        if (a <= kParallel2 * dir2) {
            if (fx * fx + fy * fy > r2) return;
            if (!(tin < tout)) return;
            out.push_back({capBoundary(tin, slab.capIn), capBoundary(tout, slab.capOut)});
            return;
        }
        // (lx, ly): the point of the ray's shadow closest to the axis; a·(r² − |l|²) is the
        // discriminant without the cancellation of h² − a·c for far-away origins.
        const double invA = 1.0 / a;
        const double tc = -h * invA;
        const double lx = fx + tc * dx, ly = fy + tc * dy;
        const double disc = a * (r2 - (lx * lx + ly * ly));
        if (!(disc > 0.0)) return;
        const double sq = std::sqrt(disc);
        const double c = fx * fx + fy * fy - r2;
        const QuadraticRoots r = solveQuadraticHalf(a, h, c, sq);
        const double t0 = std::ldexp(r.t0, tExp), t1 = std::ldexp(r.t1, tExp);
        const double w = sq * invA;  // the hits lie at l ∓ w·(dx, dy) across the axis
        const bool sideIn = t0 > tin, sideOut = t1 < tout;
        if (sideIn) tin = t0;
        if (sideOut) tout = t1;
        if (!(tin < tout)) return;
        const Boundary bin = sideIn ? boundary(tin, mFrame.across(lx - w * dx, ly - w * dy))
                                    : capBoundary(tin, slab.capIn);
        const Boundary bout = sideOut ? boundary(tout, mFrame.across(lx + w * dx, ly + w * dy))
                                      : capBoundary(tout, slab.capOut);
        out.push_back({bin, bout});
    }

    Boundary capBoundary(double t, int cap) const { return boundary(t, mFrame.capNormal(cap)); }

    AxialFrame mFrame;  // from the base towards the top
    Vec3 mTop;          ///< the given end point, for valueExtended
    double mRadius;
    double mRadius2;
};

}  // namespace

NodePtr makeCylinder(const Vec3& a, const Vec3& b, double radius) {
    return std::make_shared<Cylinder>(a, b, radius);
}

}  // namespace kerf
