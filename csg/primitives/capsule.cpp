// The capsule: the points within radius r of the segment a–b. Closed-form spans: the body (the
// cylinder's across-axis quadratic, clipped to the slab between the end points) and the two
// end spheres (the sphere's cancellation-free discriminant); the capsule is convex, so the
// span is the earliest entry to the latest exit of the three. Its value evaluations are the
// ones Primitive derives from implicitExpr().
#include "csg/primitives/axial_frame.h"
#include "csg/primitives/closed_primitive.h"
#include "csg/primitives/implicit_expr.h"
#include "csg/primitives/quadratic.h"
#include "csg/tree/solids.h"

#include <algorithm>
#include <climits>

namespace kerf {
namespace {

// Directions closer to the axis than 2^-52 rad are parallel to it (as for the cylinder): the
// end spheres then give both ends of the span.
constexpr double kAlongAxis2 = 0x1p-104;

/// The earliest entry and the latest exit seen so far, with their local normals.
struct Extremes {
    double tin = kInf, tout = -kInf;
    Vec3 nin{0.0}, nout{0.0};

    void enter(double t, const Vec3& n) {
        if (t < tin) tin = t, nin = n;
    }
    void leave(double t, const Vec3& n) {
        if (t > tout) tout = t, nout = n;
    }
};

class Capsule final : public ClosedFormPrimitive<Capsule> {
public:
    Capsule(const Vec3& a, const Vec3& b, double radius) : mFrame(a, b), mTop(b), mRadius(radius) {
        // The end spheres' boxes, one ulp outward: a ± r is rounded.
        for (int i = 0; i < 3; ++i) {
            mBounds.lo[i] = roundDown(std::min(a[i], b[i]) - radius);
            mBounds.hi[i] = roundUp(std::max(a[i], b[i]) + radius);
        }
    }

    NodeKind kind() const override { return NodeKind::Capsule; }
    NodeParams params() const override { return CapsuleParams{mFrame.base, mTop, mRadius}; }

    /// |p − nearest point of the segment| − r: the distance beyond either end along the axis
    /// (max(−z, 0) + max(z − L, 0), one of them 0) joins the distance across it.
    ExprId implicitExpr(ExprGraph& g, ExprId x, ExprId y, ExprId z) const override {
        ExprBuilder e{g};
        ExprId lx, ly, lz;
        mFrame.toLocal(e, x, y, z, lx, ly, lz);
        const ExprId zero = e.c(0.0);
        const ExprId beyond =
            e.add(e.max(e.neg(lz), zero), e.max(e.sub(lz, e.c(mFrame.length)), zero));
        const ExprId d2 = e.add(e.add(e.sqr(lx), e.sqr(ly)), e.sqr(beyond));
        return e.sub(e.sqrt(d2), e.c(mRadius));
    }

private:
    friend class ClosedFormPrimitive<Capsule>;

    /// Squares of numbers between 1/kSquareSafe and kSquareSafe neither overflow nor lose
    /// precision to underflow; outside it the ray is rescaled first (as the sphere does).
    static constexpr double kSquareSafe = 0x1p250;

    /// TraceMethod::Closed.
    void closedSpans(const Ray& ray, SpanList& out) const {
        const Vec3 f = mFrame.localPoint(ray.origin), d = mFrame.localDirection(ray.dir);
        const double m =
            std::max({std::fabs(f.x), std::fabs(f.y), std::fabs(f.z), mRadius, mFrame.length});
        const double dm = std::max({std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)});
        if (!(m <= kSquareSafe && m >= 1.0 / kSquareSafe && dm <= kSquareSafe &&
              dm >= 1.0 / kSquareSafe))
            return rescaledSpans(f, d, out);
        localSpans(f, d, mRadius, mFrame.length, 0, out);
    }

    /// Capsules and rays at extreme scales (1e±300): positions, radius and length scaled by one
    /// power of two, the direction by another, both exact; roots scaled back.
    void rescaledSpans(const Vec3& f, const Vec3& d, SpanList& out) const {
        const int kp = std::ilogb(
            std::max({std::fabs(f.x), std::fabs(f.y), std::fabs(f.z), mRadius, mFrame.length}));
        const int kd = std::ilogb(std::max({std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)}));
        // An infinite or NaN origin or direction meets nothing, and kp − kd would overflow.
        if (kp == FP_ILOGBNAN || kd == FP_ILOGBNAN || kd == FP_ILOGB0 || kp == INT_MAX ||
            kd == INT_MAX)
            return;
        const auto scaled = [](const Vec3& v, int k) {
            return Vec3(std::ldexp(v.x, -k), std::ldexp(v.y, -k), std::ldexp(v.z, -k));
        };
        localSpans(scaled(f, kp), scaled(d, kd), std::ldexp(mRadius, -kp),
                   std::ldexp(mFrame.length, -kp), kp - kd, out);
    }

    /// The span of the local ray f + t·d (axis along z from 0 to length) in units where
    /// squares stay in range; t is scaled by 2^tExp (exact) on output.
    void localSpans(const Vec3& f, const Vec3& d, double r, double length, int tExp,
                    SpanList& out) const {
        Extremes x;
        const double r2 = r * r, dir2 = glm::dot(d, d);
        bodySpan(f, d, r2, dir2, length, x);
        capSpan(f, d, r2, dir2, 0.0, x);
        capSpan(f, d, r2, dir2, length, x);
        if (!(x.tin < x.tout)) return;
        out.push_back({boundary(std::ldexp(x.tin, tExp), world(x.nin)),
                       boundary(std::ldexp(x.tout, tExp), world(x.nout))});
    }

    /// The body: |(fx, fy) + t·(dx, dy)|² ≤ r² with 0 ≤ z ≤ length. Only roots inside the slab
    /// count; where the body's part ends on a cap plane, it ends inside an end sphere, which
    /// reaches further.
    static void bodySpan(const Vec3& f, const Vec3& d, double r2, double dir2, double length,
                         Extremes& x) {
        const double a = d.x * d.x + d.y * d.y;
        if (a <= kAlongAxis2 * dir2) return;  // along the axis: the end spheres decide
        const double h = f.x * d.x + f.y * d.y;
        const double invA = 1.0 / a;
        const double tc = -h * invA;
        const double lx = f.x + tc * d.x, ly = f.y + tc * d.y;  // the shadow's closest point
        const double disc = a * (r2 - (lx * lx + ly * ly));
        if (!(disc > 0.0)) return;
        const double sq = std::sqrt(disc);
        const QuadraticRoots roots = solveQuadraticHalf(a, h, f.x * f.x + f.y * f.y - r2, sq);
        const double w = sq * invA;
        const auto inSlab = [&](double t) {
            const double z = f.z + t * d.z;
            return z >= 0.0 && z <= length;
        };
        if (inSlab(roots.t0)) x.enter(roots.t0, Vec3(lx - w * d.x, ly - w * d.y, 0.0));
        if (inSlab(roots.t1)) x.leave(roots.t1, Vec3(lx + w * d.x, ly + w * d.y, 0.0));
    }

    /// The end sphere of radius² r2 at (0, 0, cz), as the sphere's closed form.
    static void capSpan(const Vec3& f, const Vec3& d, double r2, double dir2, double cz,
                        Extremes& x) {
        const Vec3 g(f.x, f.y, f.z - cz);
        const double h = glm::dot(g, d);
        const double tc = -h / dir2;
        const Vec3 l = g + tc * d;
        const double disc = dir2 * (r2 - glm::dot(l, l));
        if (!(disc > 0.0)) return;
        const double sq = std::sqrt(disc);
        const QuadraticRoots roots = solveQuadraticHalf(dir2, h, glm::dot(g, g) - r2, sq);
        const Vec3 half = (sq / dir2) * d;
        x.enter(roots.t0, l - half);
        x.leave(roots.t1, l + half);
    }

    /// A local vector in world coordinates.
    Vec3 world(const Vec3& v) const { return mFrame.across(v.x, v.y) + v.z * mFrame.axis; }

    AxialFrame mFrame;  // from a towards b
    Vec3 mTop;          ///< the given end point b, for params()
    double mRadius;
};

}  // namespace

NodePtr makeCapsule(const Vec3& a, const Vec3& b, double radius) {
    return std::make_shared<Capsule>(a, b, radius);
}

}  // namespace kerf
