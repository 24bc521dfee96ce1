// The capped cylinder around an arbitrary axis: a 2-D Haines-style quadratic across the axis
// intersected with the slab between the caps.
#include "csg/polynomial_isolation.h"
#include "csg/primitive.h"
#include "csg/quadratic.h"
#include "csg/solids.h"
#include "csg/sphere_trace.h"

#include <algorithm>

namespace kerf {
namespace {

// Directions closer to the axis than 2^-52 rad are treated as parallel: the rounding of the
// local coordinates is larger than their sideways drift, and the roots would overflow.
constexpr double kParallel2 = 0x1p-104;

class Cylinder final : public Primitive {
public:
    Cylinder(const Vec3& a, const Vec3& b, double radius)
        : mBase(a), mTop(b), mRadius(radius), mRadius2(radius * radius) {
        const Vec3 axis = b - a;
        mLength = glm::length(axis);
        mAxis = axis / mLength;
        orthonormalFrame(mAxis, mE1, mE2);
        for (int i = 0; i < 3; ++i) {
            // The cap discs reach r·√(1 − u_i²) along world axis i; one ulp outward if inexact.
            // e is widened by a few ulps first, since it and mAxis are themselves rounded.
            const double e = radius * std::sqrt(std::max(0.0, 1.0 - mAxis[i] * mAxis[i])) *
                             (1.0 + 0x1p-50);
            const double lo = std::min(a[i], b[i]), hi = std::max(a[i], b[i]);
            mBounds.lo[i] = e == 0.0 ? lo : roundDown(lo - e);
            mBounds.hi[i] = e == 0.0 ? hi : roundUp(hi + e);
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

        // The slab 0 ≤ z ≤ L between the caps; cap flags: -1 base (normal −u), +1 top (+u).
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

        // Across the axis: |(fx, fy) + t·(dx, dy)|² ≤ r².
        const double a = dx * dx + dy * dy;
        const double h = fx * dx + fy * dy;
        if (a <= kParallel2 * glm::dot(d, d)) {
            if (fx * fx + fy * fy > mRadius2) return;
            if (!(tin < tout)) return;
            out.push_back({capBoundary(tin, capIn), capBoundary(tout, capOut)});
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
        const Boundary bin = sideIn ? boundary(tin, (lx - w * dx) * mE1 + (ly - w * dy) * mE2)
                                    : capBoundary(tin, capIn);
        const Boundary bout = sideOut ? boundary(tout, (lx + w * dx) * mE1 + (ly + w * dy) * mE2)
                                      : capBoundary(tout, capOut);
        out.push_back({bin, bout});
    }

    /// max(distance from the axis − r, slab distance): Lipschitz-1.
    double value(const Vec3& p) const override {
        const double px = p.x - mBase.x, py = p.y - mBase.y, pz = p.z - mBase.z;
        const double x = px * mE1.x + py * mE1.y + pz * mE1.z;
        const double y = px * mE2.x + py * mE2.y + pz * mE2.z;
        const double z = px * mAxis.x + py * mAxis.y + pz * mAxis.z;
        const double side = std::sqrt(x * x + y * y) - mRadius;
        return std::max(side, std::max(-z, z - mLength));
    }

    long double valueExtended(const LVec3& p) const override {
        // From the given end points, not the rounded frame: the reference must be exact.
        const LVec3 axis = LVec3(mTop) - LVec3(mBase), q = p - LVec3(mBase);
        const long double len = std::sqrt(glm::dot(axis, axis));
        const long double z = glm::dot(q, axis) / len;
        const long double radial = std::sqrt(std::max(0.0L, glm::dot(q, q) - z * z));
        return std::max(radial - (long double)mRadius, std::max(-z, z - len));
    }

    Interval valueInterval(const IntervalVec3& b) const override {
        const Interval px = b.x - mBase.x, py = b.y - mBase.y, pz = b.z - mBase.z;
        const Interval x = px * mE1.x + py * mE1.y + pz * mE1.z;
        const Interval y = px * mE2.x + py * mE2.y + pz * mE2.z;
        const Interval z = px * mAxis.x + py * mAxis.y + pz * mAxis.z;
        const Interval side = sqrt(sqr(x) + sqr(y)) - mRadius;
        return max(side, max(-z, z - mLength));
    }

private:
    Boundary capBoundary(double t, int cap) const {
        return boundary(t, cap > 0 ? mAxis : -mAxis);
    }

    /// Interval isolation of the cap slab's two linear functions and the radial quadratic
    /// (csg/polynomial_isolation.h), normalised by the radius of the ball around the axis'
    /// middle that holds the cylinder, s measured from the ray's point nearest that middle.
    void intervalSpans(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
                       SpanList& out) const {
        const Vec3& d = ray.dir;
        const double dd = glm::dot(d, d);
        if (!(dd > 0.0)) return;
        const Vec3 f = ray.origin - mBase;
        const Vec3 fl(glm::dot(f, mE1), glm::dot(f, mE2), glm::dot(f, mAxis));
        const Vec3 dl(glm::dot(d, mE1), glm::dot(d, mE2), glm::dot(d, mAxis));
        const double half = 0.5 * mLength;
        const double ts = -(fl.x * dl.x + fl.y * dl.y + (fl.z - half) * dl.z) / dd;
        const double scale = std::sqrt(half * half + mRadius2), inv = 1.0 / scale;
        const double len = std::sqrt(dd), sPerT = len * inv;
        const FrustumAlongRay fr{(fl + ts * dl) * inv, dl / len, mRadius * inv, 0.0,
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
            return rootBoundary(t, p.x * mE1 + p.y * mE2, ctx);
        };
        frustumSpans(fr, sMin, sMax, ts * sPerT, ctx,
                     [&](double sIn, int fIn, double sOut, int fOut) {
                         out.push_back({at(sIn, fIn, sIn == sMin ? tmin : ts + sIn / sPerT),
                                        at(sOut, fOut, sOut == sMax ? tmax : ts + sOut / sPerT)});
                     });
        dropThinSpans(out, ctx.relTolerance);
    }

    /// Sphere tracing of value() (Lipschitz 1) within the bounds.
    void sphereTracedSpans(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
                           SpanList& out) const {
        double t0 = tmin, t1 = tmax;
        if (!mBounds.clipRay(ray, t0, t1) || !std::isfinite(t0)) return;
        sphereTraceSpans([this](const Vec3& p) { return Cylinder::value(p); }, ray, t0, t1, 1.0,
                         t0 > tmin,
                         ctx, [&](double t) { return rootBoundary(t, gradient(ray.at(t)), ctx); },
                         [](double t, bool) {
                             Boundary b;
                             b.t = t;
                             return b;
                         },
                         out);
    }

    /// The gradient of value()'s largest term at p: across the axis, or a cap's normal.
    Vec3 gradient(const Vec3& p) const {
        const Vec3 q = p - mBase;
        const double x = glm::dot(q, mE1), y = glm::dot(q, mE2), z = glm::dot(q, mAxis);
        const double side = std::sqrt(x * x + y * y) - mRadius;
        if (side >= -z && side >= z - mLength) return x * mE1 + y * mE2;
        return -z > z - mLength ? -mAxis : mAxis;
    }

    /// e1, e2 with (e1, e2, u) right-handed orthonormal (Duff et al., JCGT 2017); exact
    /// permutations of the world axes when u is axis-aligned, so such cylinders stay exact.
    static void orthonormalFrame(const Vec3& u, Vec3& e1, Vec3& e2) {
        const double s = std::copysign(1.0, u.z);
        const double a = -1.0 / (s + u.z);
        const double b = u.x * u.y * a;
        e1 = Vec3(1.0 + s * u.x * u.x * a, s * b, -s * u.x);
        e2 = Vec3(b, s + u.y * u.y * a, -u.y);
    }

    Vec3 mBase;
    Vec3 mTop;  ///< the given end point, for valueExtended
    Vec3 mAxis;  // unit, from the base towards the top
    Vec3 mE1, mE2;
    double mLength;
    double mRadius;
    double mRadius2;
};

}  // namespace

NodePtr makeCylinder(const Vec3& a, const Vec3& b, double radius) {
    return std::make_shared<Cylinder>(a, b, radius);
}

}  // namespace kerf
