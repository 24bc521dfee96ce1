// The sphere: closed-form spans with the cancellation-free discriminant of Haines et al.
#include "csg/primitives/closed_primitive.h"
#include "csg/primitives/implicit_expr.h"
#include "csg/primitives/quadratic.h"
#include "csg/tree/solids.h"

#include <algorithm>
#include <climits>
#include <cmath>

namespace kerf {
namespace {

class Sphere final : public ClosedFormPrimitive<Sphere> {
public:
    Sphere(const Vec3& center, double radius)
        : mCenter(center), mRadius(radius), mRadius2(radius * radius) {
        // One ulp outward: c ± r is rounded and the bounds must never cut the solid.
        for (int a = 0; a < 3; ++a) {
            mBounds.lo[a] = roundDown(center[a] - radius);
            mBounds.hi[a] = roundUp(center[a] + radius);
        }
    }

    double value(const Vec3& p) const override {
        const double x = p.x - mCenter.x, y = p.y - mCenter.y, z = p.z - mCenter.z;
        return std::sqrt(x * x + y * y + z * z) - mRadius;
    }

    long double valueExtended(const LVec3& p) const override {
        const LVec3 q = p - LVec3(mCenter);
        return std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z) - (long double)mRadius;
    }

    Interval valueInterval(const IntervalVec3& b) const override {
        const Interval x = b.x - mCenter.x, y = b.y - mCenter.y, z = b.z - mCenter.z;
        return sqrt(nonNegative(sqr(x) + sqr(y) + sqr(z))) - mRadius;
    }

    NodeKind kind() const override { return NodeKind::Sphere; }
    NodeParams params() const override { return SphereParams{mCenter, mRadius}; }

    ExprId implicitExpr(ExprGraph& g, ExprId x, ExprId y, ExprId z) const override {
        ExprBuilder e{g};
        const ExprId dx = e.sub(x, e.c(mCenter.x)), dy = e.sub(y, e.c(mCenter.y));
        const ExprId dz = e.sub(z, e.c(mCenter.z));
        return e.sub(e.sqrt(e.add(e.add(e.sqr(dx), e.sqr(dy)), e.sqr(dz))), e.c(mRadius));
    }

private:
    friend class ClosedFormPrimitive<Sphere>;

    /// TraceMethod::Closed.
    void closedSpans(const Ray& ray, SpanList& out) const {
        const Vec3 f = ray.origin - mCenter;
        const double m = std::max({std::fabs(f.x), std::fabs(f.y), std::fabs(f.z), mRadius});
        const double dm =
            std::max({std::fabs(ray.dir.x), std::fabs(ray.dir.y), std::fabs(ray.dir.z)});
        if (m > kSquareSafe || m < 1.0 / kSquareSafe || dm > kSquareSafe || dm < 1.0 / kSquareSafe)
            return rescaledSpans(f, ray.dir, out);
        centredSpans(f, ray.dir, mRadius2, 0, out);
    }

    /// Squares of numbers between 1/kSquareSafe and kSquareSafe neither overflow nor lose
    /// precision to underflow; outside it the ray is rescaled first.
    static constexpr double kSquareSafe = 0x1p250;

    /// The closed form for the ray f + t·d against the centred sphere of radius² r2. Roots are
    /// scaled by 2^tExp (exact), for rays that were rescaled to keep squares in range.
    void centredSpans(const Vec3& f, const Vec3& d, double r2, int tExp, SpanList& out) const {
        const double a = glm::dot(d, d);
        const double h = glm::dot(f, d);
        // l: the centre-relative point of the line closest to the centre. h² − a·c would
        // subtract two numbers of size |f|²·a; a·(r² − |l|²) only loses what |l| loses.
        const double tc = -h / a;
        const Vec3 l = f + tc * d;
        const double disc = a * (r2 - glm::dot(l, l));
        if (!(disc > 0.0)) return;  // miss, tangent, or NaN input
        const double sq = std::sqrt(disc);
        const double c = glm::dot(f, f) - r2;
        const QuadraticRoots r = solveQuadraticHalf(a, h, c, sq);
        // Normals relative to l: the hits lie at l ∓ (√disc/a)·d from the centre, which
        // avoids f + t·d, a difference of two long vectors when the origin is far away.
        const Vec3 half = (sq / a) * d;
        out.push_back({boundary(std::ldexp(r.t0, tExp), l - half),
                       boundary(std::ldexp(r.t1, tExp), l + half)});
    }

    /// Spheres and rays at extreme scales (1e±300): positions and radius scaled by one power
    /// of two, the direction by another, so every square stays in range; both are exact.
    void rescaledSpans(const Vec3& f, const Vec3& d, SpanList& out) const {
        const int kp =
            std::ilogb(std::max({std::fabs(f.x), std::fabs(f.y), std::fabs(f.z), mRadius}));
        const int kd = std::ilogb(std::max({std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)}));
        // An infinite origin or direction (ilogb gives INT_MAX) meets nothing, and kp − kd
        // would overflow an int.
        if (kp == FP_ILOGBNAN || kd == FP_ILOGBNAN || kd == FP_ILOGB0 || kp == INT_MAX ||
            kd == INT_MAX)
            return;
        const Vec3 fs(std::ldexp(f.x, -kp), std::ldexp(f.y, -kp), std::ldexp(f.z, -kp));
        const Vec3 ds(std::ldexp(d.x, -kd), std::ldexp(d.y, -kd), std::ldexp(d.z, -kd));
        const double rs = std::ldexp(mRadius, -kp);
        // f + t·d = 2^kp·(fs + t·2^(kd−kp)·ds): the scaled root t' gives t = 2^(kp−kd)·t'.
        centredSpans(fs, ds, rs * rs, kp - kd, out);
    }

    Vec3 mCenter;
    double mRadius;
    double mRadius2;
};

}  // namespace

NodePtr makeSphere(const Vec3& center, double radius) {
    return std::make_shared<Sphere>(center, radius);
}

}  // namespace kerf
