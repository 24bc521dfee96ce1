// The sphere: closed-form spans with the cancellation-free discriminant of Haines et al.
#include "csg/primitive.h"
#include "csg/quadratic.h"
#include "csg/solids.h"

namespace kerf {
namespace {

class Sphere final : public Primitive {
public:
    Sphere(const Vec3& center, double radius)
        : mCenter(center), mRadius(radius), mRadius2(radius * radius) {
        // One ulp outward: c ± r is rounded and the bounds must never cut the solid.
        for (int a = 0; a < 3; ++a) {
            mBounds.lo[a] = roundDown(center[a] - radius);
            mBounds.hi[a] = roundUp(center[a] + radius);
        }
    }

    void spans(const Ray& ray, double, double, TraceContext& ctx, SpanList& out) const override {
        out.clear();
        ++ctx.stats.primitiveTests;
        const Vec3& d = ray.dir;
        const Vec3 f = ray.origin - mCenter;
        const double a = glm::dot(d, d);
        const double h = glm::dot(f, d);
        // l: the centre-relative point of the line closest to the centre. h² − a·c would
        // subtract two numbers of size |f|²·a; a·(r² − |l|²) only loses what |l| loses.
        const double tc = -h / a;
        const Vec3 l = f + tc * d;
        const double disc = a * (mRadius2 - glm::dot(l, l));
        if (!(disc > 0.0)) return;  // miss, tangent, or NaN input
        const double sq = std::sqrt(disc);
        const double c = glm::dot(f, f) - mRadius2;
        const QuadraticRoots r = solveQuadraticHalf(a, h, c, sq);
        // Normals relative to l: the hits lie at l ∓ (√disc/a)·d from the centre, which
        // avoids f + t·d, a difference of two long vectors when the origin is far away.
        const Vec3 half = (sq / a) * d;
        out.push_back({boundary(r.t0, l - half), boundary(r.t1, l + half)});
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
        return sqrt(sqr(x) + sqr(y) + sqr(z)) - mRadius;
    }

private:
    Vec3 mCenter;
    double mRadius;
    double mRadius2;
};

}  // namespace

NodePtr makeSphere(const Vec3& center, double radius) {
    return std::make_shared<Sphere>(center, radius);
}

}  // namespace kerf
