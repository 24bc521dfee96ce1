/// @file mesh/triangle_distance.h
/// @brief The point of a triangle nearest to a point (by its Voronoi regions: a vertex, an
/// edge or the face), for the mesh's distance field and its gradient.
#pragma once

#include "csg/types.h"

#include <algorithm>

namespace kerf {

/// The point of triangle (a, b, c) nearest to p. A degenerate triangle gives the nearest
/// point of its edges.
inline Vec3 nearestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return a;
    const Vec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return b;
    const Vec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return c;
    // Barycentric-like areas: p projects outside the edge whose area term is negative.
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + (d1 / (d1 - d3)) * ab;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + (d2 / (d2 - d6)) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
        return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
    const double sum = va + vb + vc;
    if (!(sum > 0.0)) {  // zero area: the nearest of the three edges' points
        auto onSegment = [&](const Vec3& s, const Vec3& e) {
            const Vec3 d = e - s;
            const double len2 = glm::dot(d, d);
            const double t = len2 > 0.0 ? std::clamp(glm::dot(p - s, d) / len2, 0.0, 1.0) : 0.0;
            return s + t * d;
        };
        Vec3 best = onSegment(a, b);
        for (const Vec3& q : {onSegment(b, c), onSegment(c, a)})
            if (glm::dot(q - p, q - p) < glm::dot(best - p, best - p)) best = q;
        return best;
    }
    return a + (vb / sum) * ab + (vc / sum) * ac;
}

}  // namespace kerf
