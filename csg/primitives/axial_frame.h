/// @file csg/primitives/axial_frame.h
/// @brief The local frame of a solid of revolution between two end points (the cylinder and
/// the cone): x, y across the axis, z along it from the base; and the slab between its caps.
#pragma once

#include "csg/tree/node.h"

#include <algorithm>
#include <cmath>

namespace kerf {

/// e1, e2 with (e1, e2, u) right-handed orthonormal (Duff et al., JCGT 2017); exact
/// permutations of the world axes when u is axis-aligned, so such solids stay exact.
inline void orthonormalFrame(const Vec3& u, Vec3& e1, Vec3& e2) {
    const double s = std::copysign(1.0, u.z);
    const double a = -1.0 / (s + u.z);
    const double b = u.x * u.y * a;
    e1 = Vec3(1.0 + s * u.x * u.x * a, s * b, -s * u.x);
    e2 = Vec3(b, s + u.y * u.y * a, -u.y);
}

/// The part of a ray (local origin z fz, direction z dz) in the slab 0 ≤ z ≤ length between
/// the caps, with the cap each end lies on (−1 base, +1 top, 0 none: ±inf).
struct CapSlab {
    double tin = -kInf, tout = kInf;
    int capIn = 0, capOut = 0;

    /// False when the ray runs parallel to the caps outside the slab.
    bool clip(double fz, double dz, double length) {
        if (dz == 0.0) return fz >= 0.0 && fz <= length;  // +0 or −0: parallel to the caps
        const double inv = 1.0 / dz;
        const double tBase = -fz * inv, tTop = (length - fz) * inv;
        if (dz > 0.0) {
            tin = tBase;
            capIn = -1;
            tout = tTop;
            capOut = 1;
        } else {
            tin = tTop;
            capIn = 1;
            tout = tBase;
            capOut = -1;
        }
        return true;
    }
};

/// An orthonormal frame whose z axis runs from the base a towards the other end b.
struct AxialFrame {
    Vec3 base;
    Vec3 axis;  ///< unit, from the base towards the other end
    Vec3 e1, e2;
    double length;

    AxialFrame(const Vec3& a, const Vec3& b) : base(a) {
        // b − a scaled by a power of two (exact) first: its squared length would overflow for
        // axes longer than 1e154 and underflow below 1e-154. Same bits in between.
        const Vec3 d = b - a;
        const double big = std::max({std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)});
        const int e = big > 0 && std::isfinite(big) ? std::ilogb(big) : 0;
        const Vec3 ds(std::ldexp(d.x, -e), std::ldexp(d.y, -e), std::ldexp(d.z, -e));
        const double scaledLength = glm::length(ds);
        length = std::ldexp(scaledLength, e);
        axis = ds / scaledLength;
        orthonormalFrame(axis, e1, e2);
    }

    /// Local coordinates of a point, or of a box of points (IntervalVec3 → Interval).
    template <class Point, class Scalar>
    void toLocal(const Point& p, Scalar& x, Scalar& y, Scalar& z) const {
        const Scalar px = p.x - base.x, py = p.y - base.y, pz = p.z - base.z;
        x = px * e1.x + py * e1.y + pz * e1.z;
        y = px * e2.x + py * e2.y + pz * e2.z;
        z = px * axis.x + py * axis.y + pz * axis.z;
    }
    /// Local coordinates as expressions over x, y, z (an implicit form:
    /// csg/primitives/implicit_expr.h), in the order of operations of the point version.
    template <class Builder, class Id>
    void toLocal(Builder& e, Id x, Id y, Id z, Id& lx, Id& ly, Id& lz) const {
        const Id px = e.sub(x, e.c(base.x)), py = e.sub(y, e.c(base.y)), pz = e.sub(z, e.c(base.z));
        lx = e.dot(e1, px, py, pz);
        ly = e.dot(e2, px, py, pz);
        lz = e.dot(axis, px, py, pz);
    }
    Vec3 localPoint(const Vec3& p) const {
        Vec3 q;
        toLocal(p, q.x, q.y, q.z);
        return q;
    }
    Vec3 localDirection(const Vec3& d) const {
        return {glm::dot(d, e1), glm::dot(d, e2), glm::dot(d, axis)};
    }
    /// The ray's origin f and direction dl in local coordinates, and its part between the caps;
    /// false when it has none (parallel to the caps, outside them).
    bool localRay(const Ray& ray, Vec3& f, Vec3& dl, CapSlab& slab) const {
        f = localPoint(ray.origin);
        dl = localDirection(ray.dir);
        return slab.clip(f.z, dl.z, length);
    }
    /// The world vector of local components (x, y) across the axis.
    Vec3 across(double x, double y) const { return x * e1 + y * e2; }
    /// The outward normal of a cap: cap −1 the base (−axis), +1 the other end (+axis).
    Vec3 capNormal(int cap) const { return cap > 0 ? axis : -axis; }
};

/// Local coordinates of p from the given end points a, b in long double, for valueExtended:
/// not from the rounded frame, since the reference must be exact.
struct ExactAxialPoint {
    long double radial;  ///< distance from the axis
    long double z;       ///< along the axis from a
    long double length;  ///< |b − a|

    ExactAxialPoint(const Vec3& a, const Vec3& b, const LVec3& p) {
        const LVec3 axis = LVec3(b) - LVec3(a), q = p - LVec3(a);
        length = std::sqrt(glm::dot(axis, axis));
        z = glm::dot(q, axis) / length;
        radial = std::sqrt(std::max(0.0L, glm::dot(q, q) - z * z));
    }
};

}  // namespace kerf
