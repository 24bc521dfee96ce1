// The half-space dot(n, p) ≤ offset: one plane crossing per ray, computed with compensated
// dot products so the hit is exact to a few ulps even for nearly parallel rays.
#include "csg/primitives/closed_primitive.h"
#include "csg/primitives/implicit_expr.h"
#include "csg/tree/solids.h"

#include <algorithm>
#include <cmath>

namespace kerf {
namespace {

// Error-free transformations (Ogita, Rump and Oishi, "Accurate sum and dot product", 2005).
// Written without std::fma: without hardware FMA enabled it becomes a slow library call.
inline void twoSum(double a, double b, double& s, double& err) {
    s = a + b;
    const double bb = s - a;
    err = (a - (s - bb)) + (b - bb);
}

// Veltkamp split: hi + lo == v exactly, each half with at most 26 significant bits.
inline void split(double v, double& hi, double& lo) {
    const double c = 134217729.0 * v;  // 2^27 + 1
    hi = c - (c - v);
    lo = v - hi;
}

inline void twoProduct(double a, double b, double& p, double& err) {
    p = a * b;
    double ah, al, bh, bl;
    split(a, ah, al);
    split(b, bh, bl);
    err = al * bl - (((p - ah * bh) - al * bh) - ah * bl);
}

/// n·v + extra, evaluated as if in twice the working precision (Dot2).
inline double dot2Slow(const Vec3& n, const Vec3& v, double extra) {
    double s = extra, c = 0.0;
    for (int i = 0; i < 3; ++i) {
        double p, ep, es;
        twoProduct(n[i], v[i], p, ep);
        twoSum(s, p, s, es);
        c += ep + es;
    }
    return s + c;
}

/// n·v + extra to a few ulps: the plain sum when it cannot have cancelled much (its error is
/// at most ~3 ulps of Σ|terms|, so ≤ 6 ulps of the result here), else Dot2.
inline double dot2(const Vec3& n, const Vec3& v, double extra) {
    const double x = n.x * v.x, y = n.y * v.y, z = n.z * v.z;
    const double sum = x + y + z + extra;
    const double magnitude = std::fabs(x) + std::fabs(y) + std::fabs(z) + std::fabs(extra);
    if (std::fabs(sum) >= 0.5 * magnitude) return sum;
    // The Veltkamp split overflows above ~1e292 and the error terms underflow below ~1e-290:
    // outside [2^-300, 2^300] the factors are scaled by powers of two first (exact, and the
    // error-free transformations commute with it), as for a half-space at 1e±300.
    const double bigN = std::max({std::fabs(n.x), std::fabs(n.y), std::fabs(n.z)});
    const double bigV =
        std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z), std::fabs(extra)});
    const auto safe = [](double m) { return m == 0.0 || (m >= 0x1p-300 && m <= 0x1p300); };
    if ((safe(bigN) && safe(bigV)) || !std::isfinite(bigN) || !std::isfinite(bigV))
        return dot2Slow(n, v, extra);
    const int kn = bigN > 0.0 ? std::ilogb(bigN) : 0, kv = bigV > 0.0 ? std::ilogb(bigV) : 0;
    const Vec3 ns(std::ldexp(n.x, -kn), std::ldexp(n.y, -kn), std::ldexp(n.z, -kn));
    const Vec3 vs(std::ldexp(v.x, -kv), std::ldexp(v.y, -kv), std::ldexp(v.z, -kv));
    return std::ldexp(dot2Slow(ns, vs, std::ldexp(extra, -kn - kv)), kn + kv);
}

class HalfSpace final : public ClosedFormPrimitive<HalfSpace> {
public:
    HalfSpace(const Vec3& normal, double offset)
        : mNormal(normal), mOffset(offset), mInvLength(1.0 / glm::length(normal)) {
        mBounds = Bounds3::everything();
        int nonZero = 0, axis = 0;
        for (int a = 0; a < 3; ++a)
            if (normal[a] != 0.0) {
                ++nonZero;
                axis = a;
            }
        if (nonZero == 1) {
            // n_a·p_a ≤ offset: one side of a plane perpendicular to axis a. Round the
            // division outward unless it is exact, so the bound never cuts the solid.
            const double n = normal[axis], q = offset / n;
            double p, err;
            twoProduct(q, n, p, err);
            const bool exact = p == offset && err == 0.0;
            if (n > 0.0)
                mBounds.hi[axis] = exact ? q : roundUp(q);
            else
                mBounds.lo[axis] = exact ? q : roundDown(q);
        }
    }

    double value(const Vec3& p) const override {
        return (mNormal.x * p.x + mNormal.y * p.y + mNormal.z * p.z - mOffset) * mInvLength;
    }

    long double valueExtended(const LVec3& p) const override {
        const LVec3 n(mNormal);
        return (glm::dot(n, p) - mOffset) / std::sqrt(glm::dot(n, n));
    }

    Interval valueInterval(const IntervalVec3& b) const override {
        return (mNormal.x * b.x + mNormal.y * b.y + mNormal.z * b.z - mOffset) * mInvLength;
    }

    NodeKind kind() const override { return NodeKind::HalfSpace; }
    NodeParams params() const override { return HalfSpaceParams{mNormal, mOffset}; }

    ExprId implicitExpr(ExprGraph& g, ExprId x, ExprId y, ExprId z) const override {
        ExprBuilder e{g};
        return e.mul(e.sub(e.dot(mNormal, x, y, z), e.c(mOffset)), e.c(mInvLength));
    }

    /// The first surface of the one span closedSpans() makes, without making it: every ray
    /// meets the floor of a scene, camera and shadow rays alike, so the span list, the generic
    /// search and their copies were most of a half-space's cost. Same boundary, same count.
    bool firstSurface(const Ray& ray, double tmin, double tmax, TraceContext& ctx, Boundary& hit,
                      bool& entering) const override {
        if (ctx.method != TraceMethod::Closed)
            return Node::firstSurface(ray, tmin, tmax, ctx, hit, entering);
        ++ctx.stats.primitiveTests;
        const double nd = dot2(mNormal, ray.dir, 0.0);
        const double g0 = dot2(mNormal, ray.origin, -mOffset);
        if (nd == 0.0) return false;  // no span, or one between two clips: no surface
        const double t = -g0 / nd;
        if (nd > 0.0) {
            // The span (−inf, t): its exit, as firstSurfaceOf takes it.
            if (!(-kInf < t) || !(t > tmin && t <= tmax)) return false;
            hit = boundary(t, mNormal);
            entering = false;
            return true;
        }
        // The span (t, +inf) (nd < 0 or NaN): its entry; the clip at +inf is no surface.
        if (t > tmax || !(t < kInf) || !(t > tmin)) return false;
        hit = boundary(t, mNormal);
        entering = true;
        return true;
    }

private:
    friend class ClosedFormPrimitive<HalfSpace>;

    /// TraceMethod::Closed.
    void closedSpans(const Ray& ray, SpanList& out) const {
        const double nd = dot2(mNormal, ray.dir, 0.0);
        const double g0 = dot2(mNormal, ray.origin, -mOffset);  // n·o − offset: > 0 outside
        if (nd == 0.0) {  // +0 or −0: parallel to the plane, inside everywhere or nowhere
            if (g0 <= 0.0) out.push_back({endless(-kInf), endless(kInf)});
            return;
        }
        const double t = -g0 / nd;
        if (nd > 0.0)  // heading outward: inside before the plane
            out.push_back({endless(-kInf), boundary(t, mNormal)});
        else
            out.push_back({boundary(t, mNormal), endless(kInf)});
    }

    /// An end of an unbounded span: not a surface, like a clip of the parameter range.
    static Boundary endless(double t) { return clipBoundary(t); }

    Vec3 mNormal;
    double mOffset;
    double mInvLength;
};

}  // namespace

NodePtr makeHalfSpace(const Vec3& normal, double offset) {
    return std::make_shared<HalfSpace>(normal, offset);
}

}  // namespace kerf
