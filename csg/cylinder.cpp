// The capped cylinder around an arbitrary axis: a 2-D Haines-style quadratic across the axis
// intersected with the slab between the caps.
#include "csg/axial_frame.h"
#include "csg/closed_primitive.h"
#include "csg/implicit_expr.h"
#include "csg/quadratic.h"
#include "csg/solids.h"

#include <algorithm>

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
            const double e = radius * std::sqrt(std::max(0.0, 1.0 - u[i] * u[i])) *
                             (1.0 + 0x1p-50);
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
        const double fx = f.x, fy = f.y, dx = dl.x, dy = dl.y;
        double tin = slab.tin, tout = slab.tout;

        // Across the axis: |(fx, fy) + t·(dx, dy)|² ≤ r².
        const double a = dx * dx + dy * dy;
        const double h = fx * dx + fy * dy;
        if (a <= kParallel2 * glm::dot(ray.dir, ray.dir)) {
            if (fx * fx + fy * fy > mRadius2) return;
            if (!(tin < tout)) return;
            out.push_back({capBoundary(tin, slab.capIn), capBoundary(tout, slab.capOut)});
            return;
        }
        // (lx, ly): the point of the ray's shadow closest to the axis; a·(r² − |l|²) is the
        // discriminant without the cancellation of h² − a·c for far-away origins.
        const double invA = 1.0 / a;
        const double tc = -h * invA;
        const double lx = fx + tc * dx, ly = fy + tc * dy;
        const double disc = a * (mRadius2 - (lx * lx + ly * ly));
        if (!(disc > 0.0)) return;
        const double sq = std::sqrt(disc);
        const double c = fx * fx + fy * fy - mRadius2;
        const QuadraticRoots r = solveQuadraticHalf(a, h, c, sq);
        const double w = sq * invA;  // the hits lie at l ∓ w·(dx, dy) across the axis
        const bool sideIn = r.t0 > tin, sideOut = r.t1 < tout;
        if (sideIn) tin = r.t0;
        if (sideOut) tout = r.t1;
        if (!(tin < tout)) return;
        const Boundary bin = sideIn ? boundary(tin, mFrame.across(lx - w * dx, ly - w * dy))
                                    : capBoundary(tin, slab.capIn);
        const Boundary bout = sideOut ? boundary(tout, mFrame.across(lx + w * dx, ly + w * dy))
                                      : capBoundary(tout, slab.capOut);
        out.push_back({bin, bout});
    }

    Boundary capBoundary(double t, int cap) const { return boundary(t, mFrame.capNormal(cap)); }

    AxialFrame mFrame;  // from the base towards the top
    Vec3 mTop;  ///< the given end point, for valueExtended
    double mRadius;
    double mRadius2;
};

}  // namespace

NodePtr makeCylinder(const Vec3& a, const Vec3& b, double radius) {
    return std::make_shared<Cylinder>(a, b, radius);
}

}  // namespace kerf
