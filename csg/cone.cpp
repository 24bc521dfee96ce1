// The capped cone (frustum) around an arbitrary axis. The lateral surface is the quadric
// |p⊥|² = (r1 + k·z)², which has two nappes; the slab between the caps keeps only the real one,
// since r1 + k·z ≥ 0 for 0 ≤ z ≤ L.
#include "csg/polynomial_isolation.h"
#include "csg/primitive.h"
#include "csg/quadratic.h"
#include "csg/solids.h"
#include "csg/sphere_trace.h"

#include <algorithm>

namespace kerf {
namespace {

/// A range of t where the ray is inside; `side*` says whether an end lies on the lateral
/// surface (else on a cap, or at ±inf).
struct Piece {
    double lo, hi;
    bool sideLo, sideHi;
};

class Cone final : public Primitive {
public:
    Cone(const Vec3& a, const Vec3& b, double r1, double r2) : mBase(a), mTop(b), mR1(r1), mR2(r2) {
        const Vec3 axis = b - a;
        mLength = glm::length(axis);
        mAxis = axis / mLength;
        orthonormalFrame(mAxis, mE1, mE2);
        mSlope = (r2 - r1) / mLength;
        mLateralScale = 1.0 / std::sqrt(1.0 + mSlope * mSlope);
        for (int i = 0; i < 3; ++i) {
            // Each cap disc reaches r·√(1 − u_i²) along world axis i; widened a few ulps
            // (the factor and mAxis are rounded), then one ulp outward.
            const double s = std::sqrt(std::max(0.0, 1.0 - mAxis[i] * mAxis[i])) * (1.0 + 0x1p-50);
            const double lo = std::min(a[i] - r1 * s, b[i] - r2 * s);
            const double hi = std::max(a[i] + r1 * s, b[i] + r2 * s);
            mBounds.lo[i] = roundDown(lo);
            mBounds.hi[i] = roundUp(hi);
        }
    }

    void spans(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
               SpanList& out) const override {
        out.clear();
        ++ctx.stats.primitiveTests;
        if (ctx.method == TraceMethod::Interval) return intervalSpans(ray, tmin, tmax, ctx, out);
        if (ctx.method == TraceMethod::SphereTrace)
            return sphereTracedSpans(ray, tmin, tmax, ctx, out);
        const Vec3& d = ray.dir;
        const Vec3 f = ray.origin - mBase;
        // Local coordinates: x, y across the axis, z along it from the base.
        const double fx = glm::dot(f, mE1), fy = glm::dot(f, mE2), fz = glm::dot(f, mAxis);
        const double dx = glm::dot(d, mE1), dy = glm::dot(d, mE2), dz = glm::dot(d, mAxis);

        // The slab 0 ≤ z ≤ L between the caps.
        double tin = -kInf, tout = kInf;
        int capIn = 0, capOut = 0;
        if (dz == 0.0) {  // +0 or −0: parallel to the caps
            if (!(fz >= 0.0 && fz <= mLength)) return;
        } else {
            const double inv = 1.0 / dz;
            const double tBase = -fz * inv, tTop = (mLength - fz) * inv;
            if (dz > 0.0) { tin = tBase; capIn = -1; tout = tTop; capOut = 1; }
            else { tin = tTop; capIn = 1; tout = tBase; capOut = -1; }
        }

        // The quadric along the ray: A·t² + 2B·t + C ≤ 0 inside either nappe, with
        // w0 + w1·t the signed cone radius at the ray's axial position.
        const double w0 = mR1 + mSlope * fz, w1 = mSlope * dz;
        const double a = dx * dx + dy * dy - w1 * w1;
        const double h = fx * dx + fy * dy - w0 * w1;
        const double c = fx * fx + fy * fy - w0 * w0;
        // B² − A·C = |w0·d⊥ − w1·f⊥|² − (f⊥ × d⊥)² (Lagrange's identity), and it does not change
        // when the origin slides along the ray: evaluate it from the ray's point nearest the
        // middle of the axis, where the terms are small (Haines et al.'s idea for the sphere).
        const double ts = -(fx * dx + fy * dy + (fz - 0.5 * mLength) * dz) / glm::dot(d, d);
        const double gx = fx + ts * dx, gy = fy + ts * dy, gz = fz + ts * dz;
        const double v0 = mR1 + mSlope * gz;
        const double ex = v0 * dx - w1 * gx, ey = v0 * dy - w1 * gy, cross = gx * dy - gy * dx;
        const double disc = ex * ex + ey * ey - cross * cross;

        Piece pieces[2];
        int count = 0;
        if (a > 0.0) {  // one nappe crossed: inside between the roots
            if (!(disc > 0.0)) return;
            const QuadraticRoots r = solveQuadraticHalf(a, h, c, std::sqrt(disc));
            pieces[count++] = {r.t0, r.t1, true, true};
        } else if (a < 0.0) {  // steeper than the slant: inside outside the roots
            if (std::isnan(disc)) return;
            if (!(disc > 0.0)) {
                pieces[count++] = {-kInf, kInf, false, false};  // inside everywhere (touching)
            } else {
                const QuadraticRoots r = solveQuadraticHalf(a, h, c, std::sqrt(disc));
                pieces[count++] = {-kInf, r.t0, false, true};
                pieces[count++] = {r.t1, kInf, true, false};
            }
        } else if (h != 0.0) {  // parallel to the slant: 2B·t + C ≤ 0 is linear
            const double t = -c / (2.0 * h);
            pieces[count++] = h > 0.0 ? Piece{-kInf, t, false, true} : Piece{t, kInf, true, false};
        } else {
            if (!(c <= 0.0)) return;
            pieces[count++] = {-kInf, kInf, false, false};
        }

        // Clip to the slab. The frustum is convex, so at most one piece survives; rounding
        // near the apex can leave two touching ones, which are joined.
        bool found = false;
        Boundary bin, bout;
        for (int i = 0; i < count; ++i) {
            const Piece& p = pieces[i];
            const bool sideIn = p.lo > tin, sideOut = p.hi < tout;
            const double lo = sideIn ? p.lo : tin, hi = sideOut ? p.hi : tout;
            if (!(lo < hi)) continue;
            if (!found) bin = sideIn ? sideBoundary(lo, fx, fy, dx, dy) : capBoundary(lo, capIn);
            bout = sideOut ? sideBoundary(hi, fx, fy, dx, dy) : capBoundary(hi, capOut);
            found = true;
        }
        if (found) out.push_back({bin, bout});
    }

    /// max(lateral, slab): the lateral term (|p⊥| − r(z))/√(1 + k²) keeps it Lipschitz-1.
    double value(const Vec3& p) const override {
        const double px = p.x - mBase.x, py = p.y - mBase.y, pz = p.z - mBase.z;
        const double x = px * mE1.x + py * mE1.y + pz * mE1.z;
        const double y = px * mE2.x + py * mE2.y + pz * mE2.z;
        const double z = px * mAxis.x + py * mAxis.y + pz * mAxis.z;
        const double side = (std::sqrt(x * x + y * y) - (mR1 + mSlope * z)) * mLateralScale;
        return std::max(side, std::max(-z, z - mLength));
    }

    long double valueExtended(const LVec3& p) const override {
        // From the given end points and radii, not the rounded frame.
        const LVec3 axis = LVec3(mTop) - LVec3(mBase), q = p - LVec3(mBase);
        const long double len = std::sqrt(glm::dot(axis, axis));
        const long double z = glm::dot(q, axis) / len;
        const long double radial = std::sqrt(std::max(0.0L, glm::dot(q, q) - z * z));
        const long double slope = ((long double)mR2 - mR1) / len;
        const long double side = (radial - (mR1 + slope * z)) / std::sqrt(1.0L + slope * slope);
        return std::max(side, std::max(-z, z - len));
    }

    Interval valueInterval(const IntervalVec3& b) const override {
        const Interval px = b.x - mBase.x, py = b.y - mBase.y, pz = b.z - mBase.z;
        const Interval x = px * mE1.x + py * mE1.y + pz * mE1.z;
        const Interval y = px * mE2.x + py * mE2.y + pz * mE2.z;
        const Interval z = px * mAxis.x + py * mAxis.y + pz * mAxis.z;
        const Interval side = (sqrt(sqr(x) + sqr(y)) - (mR1 + mSlope * z)) * mLateralScale;
        return max(side, max(-z, z - mLength));
    }

private:
    Boundary capBoundary(double t, int cap) const {
        return boundary(t, cap > 0 ? mAxis : -mAxis);  // cap 0 (±inf) never occurs with dz ≠ 0
    }

    /// Outward normal of |p⊥| − (r1 + k·z) at the ray's point t: p̂⊥ − k·u, scaled by |p⊥|.
    Boundary sideBoundary(double t, double fx, double fy, double dx, double dy) const {
        return boundary(t, sideNormal(fx + t * dx, fy + t * dy));
    }
    /// p̂⊥ − k·u scaled by |p⊥|, at local (px, py) across the axis (any common scale).
    Vec3 sideNormal(double px, double py) const {
        const double rho = std::sqrt(px * px + py * py);
        if (rho == 0.0) return mSlope > 0.0 ? -mAxis : mAxis;  // the apex: out of the tip
        return px * mE1 + py * mE2 - (mSlope * rho) * mAxis;
    }

    /// Interval isolation of the cap slab's two linear functions and the lateral quadric
    /// (csg/polynomial_isolation.h), normalised by the radius of the ball around the axis'
    /// middle that holds the frustum, s measured from the ray's point nearest that middle.
    void intervalSpans(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
                       SpanList& out) const {
        const Vec3& d = ray.dir;
        const double dd = glm::dot(d, d);
        if (!(dd > 0.0)) return;
        const Vec3 f = ray.origin - mBase;
        const Vec3 fl(glm::dot(f, mE1), glm::dot(f, mE2), glm::dot(f, mAxis));
        const Vec3 dl(glm::dot(d, mE1), glm::dot(d, mE2), glm::dot(d, mAxis));
        const double half = 0.5 * mLength, rMax = std::max(mR1, mR2);
        const double ts = -(fl.x * dl.x + fl.y * dl.y + (fl.z - half) * dl.z) / dd;
        const double scale = std::sqrt(half * half + rMax * rMax), inv = 1.0 / scale;
        const double len = std::sqrt(dd), sPerT = len * inv;
        const FrustumAlongRay fr{(fl + ts * dl) * inv, dl / len, mR1 * inv, mSlope,
                                 mLength * inv};
        const double sMin = (tmin - ts) * sPerT, sMax = (tmax - ts) * sPerT;
        const auto at = [&](double sv, int face, double windowT) {
            if (face == kFrustumWindow) {
                Boundary b;
                b.t = windowT;
                return b;
            }
            const double t = ts + sv / sPerT;
            if (face != kFrustumLateral)
                return rootBoundary(t, face == kFrustumTop ? mAxis : -mAxis, ctx);
            const Vec3 p = fr.g + sv * fr.u;
            return rootBoundary(t, sideNormal(p.x, p.y), ctx);
        };
        frustumSpans(fr, sMin, sMax, ts * sPerT, ctx,
                     [&](double sIn, int fIn, double sOut, int fOut) {
                         out.push_back({at(sIn, fIn, sIn == sMin ? tmin : ts + sIn / sPerT),
                                        at(sOut, fOut, sOut == sMax ? tmax : ts + sOut / sPerT)});
                     });
        dropThinSpans(out, ctx.relTolerance);
    }

    /// Sphere tracing of value() within the bounds: Lipschitz 1, since the lateral term's
    /// gradient (p̂⊥, −k) has length √(1 + k²) and is divided by it.
    void sphereTracedSpans(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
                           SpanList& out) const {
        double t0 = tmin, t1 = tmax;
        if (!mBounds.clipRay(ray, t0, t1) || !std::isfinite(t0)) return;
        sphereTraceSpans([this](const Vec3& p) { return Cone::value(p); }, ray, t0, t1, 1.0,
                         t0 > tmin, ctx,
                         [&](double t) { return rootBoundary(t, gradient(ray.at(t)), ctx); },
                         [](double t, bool) {
                             Boundary b;
                             b.t = t;
                             return b;
                         },
                         out);
    }

    /// The gradient of value()'s largest term at p: the lateral normal, or a cap's normal.
    Vec3 gradient(const Vec3& p) const {
        const Vec3 q = p - mBase;
        const double x = glm::dot(q, mE1), y = glm::dot(q, mE2), z = glm::dot(q, mAxis);
        const double side = (std::sqrt(x * x + y * y) - (mR1 + mSlope * z)) * mLateralScale;
        if (side >= -z && side >= z - mLength) return sideNormal(x, y);
        return -z > z - mLength ? -mAxis : mAxis;
    }

    /// e1, e2 with (e1, e2, u) right-handed orthonormal (Duff et al., JCGT 2017); exact
    /// permutations of the world axes when u is axis-aligned.
    static void orthonormalFrame(const Vec3& u, Vec3& e1, Vec3& e2) {
        const double s = std::copysign(1.0, u.z);
        const double a = -1.0 / (s + u.z);
        const double b = u.x * u.y * a;
        e1 = Vec3(1.0 + s * u.x * u.x * a, s * b, -s * u.x);
        e2 = Vec3(b, s + u.y * u.y * a, -u.y);
    }

    Vec3 mBase;
    Vec3 mTop;  ///< the given end point, for valueExtended
    Vec3 mAxis;  // unit, from the base (radius r1) towards the top (radius r2)
    Vec3 mE1, mE2;
    double mLength;
    double mR1, mR2;
    double mSlope;         // k = (r2 − r1)/L: the radius grows by k per unit along the axis
    double mLateralScale;  // 1/√(1 + k²)
};

}  // namespace

NodePtr makeCone(const Vec3& a, const Vec3& b, double r1, double r2) {
    return std::make_shared<Cone>(a, b, r1, r2);
}

}  // namespace kerf
