/// @file csg/types.h
/// @brief The value types every module shares: vectors, rays, bounding boxes and affine maps.
#pragma once

#include <glm/glm.hpp>

#include <cmath>
#include <limits>

namespace kerf {

using Vec3 = glm::dvec3;
using Mat3 = glm::dmat3;  ///< column-major, as GLM: m[col][row]

constexpr double kInf = std::numeric_limits<double>::infinity();

/// True when every component is finite (no NaN, no ±inf).
inline bool allFinite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// True when no component is negative (NaN counts as negative: it fails the test).
inline bool allNonNegative(const Vec3& v) { return v.x >= 0 && v.y >= 0 && v.z >= 0; }

/// A ray o + t·d. The direction is not necessarily unit length: transforms map it into object
/// space without renormalising, so the parameter t means the same point in every space.
struct Ray {
    Vec3 origin{0.0};
    Vec3 dir{0.0, 0.0, 1.0};
    Vec3 at(double t) const { return origin + t * dir; }
};

/// A ray's reciprocal direction, computed once for the many box tests of one ray (in one
/// space). Exact zero directions give 1/±0 = ±inf, so −0 gives −inf and the slab test needs no
/// branch per axis. Plain arrays: the per-axis code then unrolls without glm's index switch.
struct RayReciprocal {
    double origin[3], dir[3];
    /// 1/d with its magnitude rounded down (for near planes) and up (for far planes) by more
    /// than the four roundings of (plane − o)·(1/d), so slab distances at t ≥ 0 come out no
    /// later (near) and no earlier (far) than exact: culling never loses a box.
    double invNear[3], invFar[3];
    bool negative[3];  ///< the sign bit of each direction component (also set for −0)
    /// False when 1/d overflows, or nearly, for a nonzero subnormal d: box tests then fall
    /// back to Bounds3::clipRay.
    bool finite = true;

    explicit RayReciprocal(const Ray& ray)
        : origin{ray.origin.x, ray.origin.y, ray.origin.z},
          dir{ray.dir.x, ray.dir.y, ray.dir.z},
          negative{std::signbit(ray.dir.x), std::signbit(ray.dir.y), std::signbit(ray.dir.z)} {
        constexpr double kOverflows = 0x1p-1020, kMargin = 0x1p-50;
        for (int a = 0; a < 3; ++a) {
            const double inv = 1.0 / dir[a];
            invNear[a] = inv * (1.0 - kMargin);
            invFar[a] = inv * (1.0 + kMargin);
            if (dir[a] != 0.0 && std::fabs(dir[a]) < kOverflows) finite = false;
        }
    }
};

/// Axis-aligned box; may be empty (lo > hi) or unbounded (±inf components).
struct Bounds3 {
    Vec3 lo{kInf};
    Vec3 hi{-kInf};

    static Bounds3 everything() { return {Vec3(-kInf), Vec3(kInf)}; }
    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    bool finite() const;
    Vec3 center() const { return 0.5 * (lo + hi); }
    Vec3 extent() const { return hi - lo; }
    void extend(const Vec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void extend(const Bounds3& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    static Bounds3 hull(const Bounds3& a, const Bounds3& b);
    static Bounds3 overlap(const Bounds3& a, const Bounds3& b);
    bool contains(const Vec3& p) const;

    /// Clips [tmin, tmax] to the parameters where the ray is inside the box (slab test).
    /// Exact zero and negative-zero direction components are handled per axis, without 0·inf.
    /// Returns false when the clipped range is empty.
    bool clipRay(const Ray& ray, double& tmin, double& tmax) const;

    /// For culling: clips [tmin, tmax] to a range that holds every parameter where the ray is
    /// inside the box, widened past the rounding of the slab products, with the precomputed
    /// reciprocal direction (no division). Never false when the exact segment meets the box.
    bool clipRayConservative(const RayReciprocal& r, double& tmin, double& tmax) const {
        const double l[3] = {lo.x, lo.y, lo.z}, h[3] = {hi.x, hi.y, hi.z};
        return clipRayConservative(r, l, h, tmin, tmax);
    }
    /// The same for a box given as lo[3], hi[3] of any floating type (the BVH's float nodes).
    template <class T>
    static bool clipRayConservative(const RayReciprocal& r, const T* lo, const T* hi, double& tmin,
                                    double& tmax);

private:
    /// clipRay for a box given as lo[3], hi[3], widened by a few ulps of t: the fallback of
    /// clipRayConservative.
    static bool clipRayDividing(const RayReciprocal& r, const float* lo, const float* hi,
                                double& tmin, double& tmax);
    static bool clipRayDividing(const RayReciprocal& r, const double* lo, const double* hi,
                                double& tmin, double& tmax);
};

template <class T>
inline bool Bounds3::clipRayConservative(const RayReciprocal& r, const T* lo, const T* hi,
                                         double& tmin, double& tmax) {
    // The margins of invNear/invFar hold for t ≥ 0 (the sign of (plane − o) is exact, so a
    // slab behind the origin stays behind); a range reaching below 0 takes the exact test.
    if (!r.finite || !(tmin >= 0.0)) return clipRayDividing(r, lo, hi, tmin, tmax);
    for (int a = 0; a < 3; ++a) {
        const bool neg = r.negative[a];
        const double near = (double(neg ? hi[a] : lo[a]) - r.origin[a]) * r.invNear[a];
        const double far = (double(neg ? lo[a] : hi[a]) - r.origin[a]) * r.invFar[a];
        // A NaN (0·inf: the origin on a plane of a slab the ray runs parallel to, which counts
        // as inside) fails the comparison and so narrows nothing.
        if (near > tmin) tmin = near;
        if (far < tmax) tmax = far;
        if (tmin > tmax) return false;
    }
    // A ray parallel to a slab it lies outside of gets +inf at both ends of that slab.
    return tmin < kInf;
}

/// An affine map p ↦ linear·p + offset (a 3×4 matrix).
struct Affine {
    Mat3 linear{1.0};
    Vec3 offset{0.0};

    Vec3 point(const Vec3& p) const { return linear * p + offset; }
    Vec3 vector(const Vec3& v) const { return linear * v; }
    Affine inverse() const;
    /// (*this) ∘ inner: apply inner first.
    Affine after(const Affine& inner) const;
    /// The box that holds this map's image of b (conservative for unbounded boxes).
    Bounds3 map(const Bounds3& b) const;

    static Affine translate(const Vec3& t);
    static Affine scale(const Vec3& s);
    /// Rotation by angles in degrees about x, then y, then z (right-handed).
    static Affine rotateDegrees(const Vec3& xyz);
    /// From 12 numbers, row-major 3×4: [m00 m01 m02 m03; m10 … m13; m20 … m23].
    static Affine fromRowMajor(const double m[12]);
};

}  // namespace kerf
