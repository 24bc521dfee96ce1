// The surface leaves: disc (ring), triangle and the open side of a cone or cylinder, each by
// its closed form. A leaf lists its crossings with the whole line; spans and firstSurface keep
// the ones in range. Surfaces trace by their closed form whatever the comparison method.
#include "csg/primitives/surfaces.h"

#include "csg/primitives/axial_frame.h"
#include "csg/primitives/implicit_expr.h"
#include "csg/primitives/primitive.h"
#include "csg/primitives/quadratic.h"

#include <algorithm>
#include <cmath>

namespace kerf {
namespace {

/// What the three leaves share: range filtering, the two-sided boundary and the empty
/// implicit form.
class SurfaceLeaf : public Primitive {
public:
    void spans(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
               SpanList& out) const final {
        out.clear();
        ++ctx.stats.primitiveTests;
        Boundary b[2];
        const int n = crossings(ray, b);
        for (int i = 0; i < n; ++i)
            if (b[i].t >= tmin && b[i].t <= tmax) out.push_back({b[i], b[i]});
    }

    bool firstSurface(const Ray& ray, double tmin, double tmax, TraceContext& ctx, Boundary& hit,
                      bool& entering) const final {
        ++ctx.stats.primitiveTests;
        Boundary b[2];
        const int n = crossings(ray, b);
        for (int i = 0; i < n; ++i)
            if (b[i].t > tmin && b[i].t <= tmax) {
                hit = b[i];
                entering = true;
                return true;
            }
        return false;
    }

    // No inside: the empty solid's form.
    double value(const Vec3&) const final { return 1.0; }
    /// Deliberately loose where the box meets the bounds: ambiguous, so interval culling
    /// (primary beams) never proves a region that holds the sheet empty.
    Interval valueInterval(const IntervalVec3& box) const final {
        const Bounds3 b{Vec3(box.x.lo, box.y.lo, box.z.lo), Vec3(box.x.hi, box.y.hi, box.z.hi)};
        return Bounds3::overlap(b, mBounds).empty() ? Interval(1.0) : Interval(-1.0, 1.0);
    }
    long double valueExtended(const LVec3&) const final { return 1.0L; }
    ExprId implicitExpr(ExprGraph& g, ExprId, ExprId, ExprId) const final {
        return g.constant(1.0);
    }

protected:
    /// The crossings with the whole line, sorted by t (at most two).
    virtual int crossings(const Ray& ray, Boundary out[2]) const = 0;

    /// The crossing at t of a sheet with geometric (front) normal n: the normal turned to
    /// face the ray, and the back marked for `interior`.
    Boundary twoSided(double t, const Vec3& n, const Vec3& dir) const {
        const bool back = glm::dot(n, dir) > 0.0;
        Boundary b = boundary(t, back ? -n : n);
        if (back) b.material = Boundary::kNoMaterialBack;
        return b;
    }

    /// Bounds of points, one ulp outward after widening by `pad` (rounding of the inputs).
    void setBounds(const Vec3& lo, const Vec3& hi) {
        for (int i = 0; i < 3; ++i) {
            mBounds.lo[i] = roundDown(lo[i]);
            mBounds.hi[i] = roundUp(hi[i]);
        }
    }
};

class Disc final : public SurfaceLeaf {
public:
    Disc(const Vec3& c, const Vec3& n, double radius, double inner)
        : mCenter(c), mNormal(glm::normalize(n)), mGiven(n), mRadius(radius), mInner(inner) {
        Vec3 lo, hi;
        for (int i = 0; i < 3; ++i) {
            // The circle reaches r·√(1 − n_i²) along axis i; a few ulps more for the rounding.
            const double s =
                std::sqrt(std::max(0.0, 1.0 - mNormal[i] * mNormal[i])) * (1.0 + 0x1p-50);
            lo[i] = c[i] - radius * s;
            hi[i] = c[i] + radius * s;
        }
        setBounds(lo, hi);
    }

    NodeKind kind() const override { return NodeKind::Disc; }
    NodeParams params() const override { return DiscParams{mCenter, mGiven, mRadius, mInner}; }

private:
    int crossings(const Ray& ray, Boundary out[2]) const override {
        const double dn = glm::dot(mNormal, ray.dir);
        if (dn == 0.0) return 0;  // parallel: the sheet has no thickness to meet
        const double t = glm::dot(mNormal, mCenter - ray.origin) / dn;
        if (!std::isfinite(t)) return 0;
        const Vec3 q = ray.at(t) - mCenter;
        const double r2 = glm::dot(q, q);
        if (r2 > mRadius * mRadius || r2 < mInner * mInner) return 0;
        out[0] = twoSided(t, mNormal, ray.dir);
        return 1;
    }

    Vec3 mCenter, mNormal, mGiven;
    double mRadius, mInner;
};

class Triangle final : public SurfaceLeaf {
public:
    Triangle(const Vec3& a, const Vec3& b, const Vec3& c)
        : mA(a), mB(b), mC(c), mE1(b - a), mE2(c - a), mNormal(glm::cross(b - a, c - a)) {
        setBounds(glm::min(a, glm::min(b, c)), glm::max(a, glm::max(b, c)));
    }

    NodeKind kind() const override { return NodeKind::Triangle; }
    NodeParams params() const override { return TriangleParams{mA, mB, mC}; }

private:
    /// Möller–Trumbore: barycentric u, v and t from one determinant; edges inclusive.
    int crossings(const Ray& ray, Boundary out[2]) const override {
        const Vec3 p = glm::cross(ray.dir, mE2);
        const double det = glm::dot(mE1, p);
        if (det == 0.0 || !std::isfinite(det)) return 0;
        const double inv = 1.0 / det;
        const Vec3 s = ray.origin - mA;
        const double u = glm::dot(s, p) * inv;
        if (u < 0.0 || u > 1.0) return 0;
        const Vec3 q = glm::cross(s, mE1);
        const double v = glm::dot(ray.dir, q) * inv;
        if (v < 0.0 || u + v > 1.0) return 0;
        const double t = glm::dot(mE2, q) * inv;
        if (!std::isfinite(t)) return 0;
        out[0] = twoSided(t, mNormal, ray.dir);
        return 1;
    }

    Vec3 mA, mB, mC, mE1, mE2, mNormal;
};

/// The lateral quadric |p⊥|² = (r1 + k·z)² between the cap planes, without the caps: both
/// roots of the line, each kept where 0 ≤ z ≤ L (where r1 + k·z ≥ 0, so on the real nappe).
class OpenCone final : public SurfaceLeaf {
public:
    OpenCone(const Vec3& a, const Vec3& b, double r1, double r2)
        : mFrame(a, b), mTop(b), mR1(r1), mR2(r2), mSlope((r2 - r1) / mFrame.length) {
        Vec3 lo, hi;
        const Vec3& u = mFrame.axis;
        for (int i = 0; i < 3; ++i) {
            const double s = std::sqrt(std::max(0.0, 1.0 - u[i] * u[i])) * (1.0 + 0x1p-50);
            lo[i] = std::min(a[i] - r1 * s, b[i] - r2 * s);
            hi[i] = std::max(a[i] + r1 * s, b[i] + r2 * s);
        }
        setBounds(lo, hi);
    }

    NodeKind kind() const override { return NodeKind::OpenCone; }
    NodeParams params() const override { return OpenConeParams{mFrame.base, mTop, mR1, mR2}; }

private:
    int crossings(const Ray& ray, Boundary out[2]) const override {
        const Vec3 f = mFrame.localPoint(ray.origin);
        const Vec3 d = mFrame.localDirection(ray.dir);
        const double w0 = mR1 + mSlope * f.z, w1 = mSlope * d.z;
        const double a = d.x * d.x + d.y * d.y - w1 * w1;
        const double h = f.x * d.x + f.y * d.y - w0 * w1;
        const double c = f.x * f.x + f.y * f.y - w0 * w0;
        // h² − a·c from the ray's point nearest the axis' middle, where the terms are small
        // (Lagrange's identity, as the capped cone computes it).
        const double dir2 = glm::dot(d, d);
        const double ts = -(f.x * d.x + f.y * d.y + (f.z - 0.5 * mFrame.length) * d.z) / dir2;
        const double gx = f.x + ts * d.x, gy = f.y + ts * d.y, gz = f.z + ts * d.z;
        const double v0 = mR1 + mSlope * gz;
        const double ex = v0 * d.x - w1 * gx, ey = v0 * d.y - w1 * gy, cross = gx * d.y - gy * d.x;
        const double disc = ex * ex + ey * ey - cross * cross;
        double roots[2];
        int n = 0;
        if (a != 0.0) {
            if (!(disc > 0.0)) return 0;  // misses, or touches: a tangent line does not cross
            const QuadraticRoots r = solveQuadraticHalf(a, h, c, std::sqrt(disc));
            roots[n++] = r.t0;
            roots[n++] = r.t1;
        } else if (h != 0.0) {
            roots[n++] = -c / (2.0 * h);  // parallel to the slant: one crossing
        }
        int k = 0;
        for (int i = 0; i < n; ++i) {
            const double t = roots[i];
            const double z = f.z + t * d.z;
            if (!std::isfinite(t) || z < 0.0 || z > mFrame.length) continue;
            const double px = f.x + t * d.x, py = f.y + t * d.y;
            out[k++] = twoSided(t, sideNormal(px, py), ray.dir);
        }
        return k;
    }

    /// p̂⊥ − k·u scaled by |p⊥|: the outward normal of the side at local (px, py).
    Vec3 sideNormal(double px, double py) const {
        const double rho = std::sqrt(px * px + py * py);
        if (rho == 0.0) return mFrame.capNormal(mSlope > 0.0 ? -1 : 1);  // the apex
        return mFrame.across(px, py) - (mSlope * rho) * mFrame.axis;
    }

    AxialFrame mFrame;
    Vec3 mTop;
    double mR1, mR2, mSlope;
};

}  // namespace

NodePtr makeDisc(const Vec3& center, const Vec3& normal, double radius, double inner) {
    return std::make_shared<const Disc>(center, normal, radius, inner);
}

NodePtr makeTriangle(const Vec3& a, const Vec3& b, const Vec3& c) {
    return std::make_shared<const Triangle>(a, b, c);
}

NodePtr makeOpenCone(const Vec3& a, const Vec3& b, double r1, double r2) {
    return std::make_shared<const OpenCone>(a, b, r1, r2);
}

}  // namespace kerf
