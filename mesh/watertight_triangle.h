/// @file mesh/watertight_triangle.h
/// @brief The watertight ray–triangle test of Woop, Benthin and Wald (JCGT 2013), in double.
///
/// The ray is sheared once into a frame where it runs along +z from the origin; each vertex is
/// sheared the same way whatever triangle uses it. The three edge functions are then 2-D cross
/// products of sheared vertices. Their signs are exact for those coordinates: the rounded
/// value where it is clearly away from 0, Kahan's fma difference of products otherwise (the
/// paper falls back to higher precision only on an exact 0; this filter makes the signs exact,
/// not just consistent). A ray exactly on an edge's line takes the side it would see moved by
/// an infinitesimal (ε, ε²) (simulation of simplicity). Each sign depends only on the edge's two
/// endpoints and flips when they swap, so two triangles sharing an edge split the plane between
/// them exactly: no ray slips through an edge or vertex, and none is counted twice. No epsilon.
///
/// Compile without floating-point contraction (-ffp-contract=off, as the mesh module does): an
/// fma in place of one rounded product would invalidate the filter's error bound.
#pragma once

#include "csg/types.h"

#include <cmath>
#include <cstdint>

namespace kerf {

/// A ray in the sheared frame, computed once per ray.
struct ShearedRay {
    double origin[3];
    int kx, ky, kz;     ///< the permutation: kz is the dominant axis of the direction
    double sx, sy, sz;  ///< the shear: x' = x − sx·z, y' = y − sy·z, z' = sz·z

    explicit ShearedRay(const Ray& ray) : origin{ray.origin.x, ray.origin.y, ray.origin.z} {
        const Vec3 a = glm::abs(ray.dir);
        kz = a.x >= a.y ? (a.x >= a.z ? 0 : 2) : (a.y >= a.z ? 1 : 2);
        kx = (kz + 1) % 3;
        ky = (kx + 1) % 3;
        // Keep the frame right-handed (the map's determinant positive) when the ray runs
        // towards −z, so the sign of the projected area is the sign of −dot(dir, normal).
        if (std::signbit(ray.dir[kz])) std::swap(kx, ky);
        sx = ray.dir[kx] / ray.dir[kz];
        sy = ray.dir[ky] / ray.dir[kz];
        sz = 1.0 / ray.dir[kz];
    }
};

/// A hit in one triangle: t and the weights of vertices 1 and 2 (vertex 0 has 1 − u − v).
struct TriangleIntersection {
    double t, u, v;
    bool entering;  ///< dot(dir, (p1 − p0) × (p2 − p0)) < 0: the ray meets the front face
};

namespace detail {
/// a·d − b·c with the sign of the exact value (relative error ≤ 2 ulp, so 0 only when exactly
/// 0, barring underflow), by Kahan's fma algorithm.
inline double exactSignDiffOfProducts(double a, double d, double b, double c) {
    const double w = b * c;
    const double e = std::fma(-b, c, w);
    const double f = std::fma(a, d, -w);
    return f + e;
}
/// The edge function of the sheared edge p → q at the ray (the origin): q × p. Its sign is
/// the exact sign for these (already sheared and rounded) coordinates: the rounded value when
/// it is clearly away from 0, else Kahan's. An exact 0 (the ray on the edge's line) takes the
/// sign the ray would see moved by (ε, ε²), returned as a signed zero; a zero-length edge gives
/// NaN. Antisymmetric in (p, q), so every point of the plane belongs to exactly one side.
inline double edgeFunction(double px, double py, double qx, double qy) {
    const double m = qx * py, n = qy * px;
    const double r = m - n;
    // |error of r| ≤ 2u(|m| + |n|) with u = 2^-53; the margin is generous.
    if (std::fabs(r) > 0x1p-50 * (std::fabs(m) + std::fabs(n))) return r;
    const double x = exactSignDiffOfProducts(qx, py, qy, px);
    if (x != 0.0) return x;
    // Moved by δ = (ε, ε²): q×p becomes q×p + δx·(qy − py) + δy·(px − qx).
    if (qy != py) return qy > py ? 0.0 : -0.0;
    if (px != qx) return px > qx ? 0.0 : -0.0;
    return std::nan("");
}
}  // namespace detail

/// The ray's crossing of triangle (p0, p1, p2) with t in the open range (tmin, tmax). A ray in
/// the triangle's plane never hits (the projected area is 0). A ray through an edge or vertex
/// hits the triangles it would hit moved sideways by an infinitesimal (ε, ε²) in the sheared
/// frame: over a closed mesh it is entered exactly as often as it is left. Vertices as plain
/// arrays: the permuted axes are then indexed without glm's switch.
/// Always inlined: the BVH's walks call it in their innermost loop.
__attribute__((always_inline)) inline bool intersectWatertight(const ShearedRay& r,
                                                               const double* p0, const double* p1,
                                                               const double* p2, double tmin,
                                                               double tmax,
                                                               TriangleIntersection& out) {
    const double a[3] = {p0[0] - r.origin[0], p0[1] - r.origin[1], p0[2] - r.origin[2]};
    const double b[3] = {p1[0] - r.origin[0], p1[1] - r.origin[1], p1[2] - r.origin[2]};
    const double c[3] = {p2[0] - r.origin[0], p2[1] - r.origin[1], p2[2] - r.origin[2]};
    const double ax = a[r.kx] - r.sx * a[r.kz], ay = a[r.ky] - r.sy * a[r.kz];
    const double bx = b[r.kx] - r.sx * b[r.kz], by = b[r.ky] - r.sy * b[r.kz];
    const double cx = c[r.kx] - r.sx * c[r.kz], cy = c[r.ky] - r.sy * c[r.kz];
    const double u = detail::edgeFunction(bx, by, cx, cy);  // edge p1 → p2: weight of p0
    const double v = detail::edgeFunction(cx, cy, ax, ay);  // edge p2 → p0: weight of p1
    const double w = detail::edgeFunction(ax, ay, bx, by);  // edge p0 → p1: weight of p2
    // Inside when the three signs agree (signed zeros count by their sign); NaN never agrees.
    const bool neg = std::signbit(u);
    if (std::signbit(v) != neg || std::signbit(w) != neg || std::isnan(u + v + w)) return false;
    const double det = u + v + w;
    if (det == 0.0) return false;  // the projection has no area: the ray lies in the plane
    const double az = r.sz * a[r.kz], bz = r.sz * b[r.kz], cz = r.sz * c[r.kz];
    const double t = (u * az + v * bz + w * cz) / det;
    if (!(t > tmin && t < tmax)) return false;
    out.t = t;
    out.u = v / det;
    out.v = w / det;
    out.entering = det > 0.0;
    return true;
}

/// The same for vertices as vectors.
inline bool intersectWatertight(const ShearedRay& r, const Vec3& p0, const Vec3& p1, const Vec3& p2,
                                double tmin, double tmax, TriangleIntersection& out) {
    const double a[3] = {p0.x, p0.y, p0.z}, b[3] = {p1.x, p1.y, p1.z}, c[3] = {p2.x, p2.y, p2.z};
    return intersectWatertight(r, a, b, c, tmin, tmax, out);
}

}  // namespace kerf
