/// @file tests/mesh/geodesic_sphere.h
/// @brief A closed triangle mesh approximating a sphere (an icosahedron subdivided, vertices
/// pushed onto the sphere), and how far it strays from the sphere: the oracle for mesh solids.
#pragma once

#include "mesh/triangle_distance.h"
#include "mesh/triangle_mesh.h"

#include <cmath>
#include <map>
#include <utility>

namespace kerf::test {

/// Vertices on the sphere (center, radius); 20·4^levels triangles, counter-clockwise outside.
inline TriangleMesh geodesicSphere(const Vec3& center, double radius, int levels) {
    const double g = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<Vec3> v = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0},
                           {0, -1, g}, {0, 1, g}, {0, -1, -g}, {0, 1, -g},
                           {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    for (Vec3& p : v) p = glm::normalize(p);
    std::vector<std::array<uint32_t, 3>> f = {
        {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
        {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
        {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int l = 0; l < levels; ++l) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
        auto middle = [&](uint32_t a, uint32_t b) {
            const auto key = std::minmax(a, b);
            auto it = mid.find(key);
            if (it != mid.end()) return it->second;
            v.push_back(glm::normalize(v[a] + v[b]));
            return mid[key] = uint32_t(v.size() - 1);
        };
        std::vector<std::array<uint32_t, 3>> next;
        for (const auto& t : f) {
            const uint32_t ab = middle(t[0], t[1]), bc = middle(t[1], t[2]),
                           ca = middle(t[2], t[0]);
            next.push_back({t[0], ab, ca});
            next.push_back({t[1], bc, ab});
            next.push_back({t[2], ca, bc});
            next.push_back({ab, bc, ca});
        }
        f.swap(next);
    }
    TriangleMesh m;
    for (const Vec3& p : v) m.positions.push_back(center + radius * p);
    m.triangles = f;
    for (const Vec3& p : v) m.normals.push_back(p);
    return m;
}

/// The radius of a sphere (same centre) that every triangle of the mesh lies outside: the
/// nearest any triangle comes to the centre (its own nearest point, by its plane or edges).
inline double innerRadius(const TriangleMesh& m, const Vec3& center) {
    double r = kInf;
    for (const auto& t : m.triangles) {
        const Vec3 q =
            nearestPointOnTriangle(center, m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]);
        r = std::min(r, glm::length(q - center));
    }
    return r;
}

}  // namespace kerf::test
