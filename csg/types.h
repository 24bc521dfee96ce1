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

/// A ray o + t·d. The direction is not necessarily unit length: transforms map it into object
/// space without renormalising, so the parameter t means the same point in every space.
struct Ray {
    Vec3 origin{0.0};
    Vec3 dir{0.0, 0.0, 1.0};
    Vec3 at(double t) const { return origin + t * dir; }
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
    void extend(const Vec3& p) { lo = glm::min(lo, p); hi = glm::max(hi, p); }
    void extend(const Bounds3& b) { lo = glm::min(lo, b.lo); hi = glm::max(hi, b.hi); }
    static Bounds3 hull(const Bounds3& a, const Bounds3& b);
    static Bounds3 overlap(const Bounds3& a, const Bounds3& b);
    bool contains(const Vec3& p) const;

    /// Clips [tmin, tmax] to the parameters where the ray is inside the box (slab test).
    /// Exact zero and negative-zero direction components are handled per axis, without 0·inf.
    /// Returns false when the clipped range is empty.
    bool clipRay(const Ray& ray, double& tmin, double& tmax) const;
};

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
