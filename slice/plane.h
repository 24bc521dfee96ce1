/// @file slice/plane.h
/// @brief A section plane and its in-plane axes. A point of the plane is
/// origin + u·U + v·V + w·N for the plane at offset w along its normal N (w = 0 for a plane
/// given by a point), with U × V = N, all three unit and orthogonal:
///   z = c: U = x, V = y, origin 0, w = c   (u, v are the model's x, y)
///   x = c: U = y, V = z, origin 0, w = c
///   y = c: U = z, V = x, origin 0, w = c
///   --point P --normal N: origin P, w = 0, U = normalize(e × N) where e is the coordinate
///   axis least aligned with N (the first of x, y, z on ties), V = N × U.
/// A stack of planes moves w and keeps origin, U, V, N, so every layer shares one tape.
#pragma once

#include "csg/types.h"

#include <string>

namespace kerf {

struct SlicePlane {
    Vec3 origin{0.0};
    Vec3 u{1.0, 0.0, 0.0};
    Vec3 v{0.0, 1.0, 0.0};
    Vec3 normal{0.0, 0.0, 1.0};
    double w = 0.0;  ///< offset along the normal from origin

    /// The plane axis = offset (axis 0, 1, 2 for x, y, z) with the axes above.
    static SlicePlane axisAligned(int axis, double offset);
    /// The plane through `point` with normal `normal` (any non-zero length).
    static SlicePlane throughPoint(const Vec3& point, const Vec3& normal);

    /// The model-space point of plane coordinates (u, v).
    Vec3 at(double pu, double pv) const { return origin + pu * u + pv * v + w * normal; }
};

/// A rectangle in plane coordinates.
struct PlaneRect {
    double minU = 0.0, minV = 0.0, maxU = 0.0, maxV = 0.0;
    bool empty() const { return !(minU <= maxU && minV <= maxV); }
};

/// The rectangle holding the plane's part of a finite box: the (u, v) extent of the polygon
/// where the plane cuts it. Empty when the plane misses the box.
PlaneRect planeSectionOfBox(const SlicePlane& plane, const Bounds3& box);

}  // namespace kerf
