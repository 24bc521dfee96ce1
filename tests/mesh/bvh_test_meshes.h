/// @file tests/mesh/bvh_test_meshes.h
/// @brief Meshes, brute-force references and ray helpers shared by the BVH tests.
#pragma once

#include "mesh/triangle_bvh.h"
#include "mesh/watertight_triangle.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <random>

namespace kerf::bvh_test {

using namespace kerf;

inline TriangleMesh octahedron() {
    TriangleMesh m;
    m.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    // Counter-clockwise seen from outside.
    m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                   {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    return m;
}

// The octahedron subdivided `levels` times, vertices pushed onto the unit sphere (shared
// midpoints, so the mesh stays closed).
inline TriangleMesh icosphere(int levels) {
    TriangleMesh m = octahedron();
    for (int l = 0; l < levels; ++l) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> mids;
        auto mid = [&](uint32_t a, uint32_t b) {
            const auto key = std::minmax(a, b);
            auto it = mids.find(key);
            if (it != mids.end()) return it->second;
            m.positions.push_back(glm::normalize(m.positions[a] + m.positions[b]));
            const uint32_t i = uint32_t(m.positions.size() - 1);
            mids.emplace(key, i);
            return i;
        };
        std::vector<std::array<uint32_t, 3>> next;
        for (const auto& t : m.triangles) {
            const uint32_t a = mid(t[0], t[1]), b = mid(t[1], t[2]), c = mid(t[2], t[0]);
            next.push_back({t[0], a, c});
            next.push_back({a, t[1], b});
            next.push_back({c, b, t[2]});
            next.push_back({a, b, c});
        }
        m.triangles = std::move(next);
    }
    return m;
}

// An n×n grid of jittered vertices in the plane z = 0, each cell split into two triangles
// along an alternating diagonal.
inline TriangleMesh jitteredGrid(int n, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> jitter(-0.3, 0.3);
    TriangleMesh m;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const bool border = i == 0 || j == 0 || i == n || j == n;
            m.positions.push_back(
                {i + (border ? 0.0 : jitter(rng)), j + (border ? 0.0 : jitter(rng)), 0.0});
        }
    auto v = [n](int i, int j) { return uint32_t(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            if ((i + j) % 2) {
                m.triangles.push_back({v(i, j), v(i + 1, j), v(i + 1, j + 1)});
                m.triangles.push_back({v(i, j), v(i + 1, j + 1), v(i, j + 1)});
            } else {
                m.triangles.push_back({v(i, j), v(i + 1, j), v(i, j + 1)});
                m.triangles.push_back({v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)});
            }
        }
    return m;
}

// A fan of k thin triangles around the origin in the plane z = 0, closing the full circle.
inline TriangleMesh fan(int k) {
    TriangleMesh m;
    m.positions.push_back({0, 0, 0});
    for (int i = 0; i < k; ++i) {
        const double a = 2.0 * M_PI * i / k;
        m.positions.push_back({std::cos(a), std::sin(a), 0.0});
    }
    for (int i = 0; i < k; ++i)
        m.triangles.push_back({0, uint32_t(1 + i), uint32_t(1 + (i + 1) % k)});
    return m;
}

struct Brute {
    bool found = false;
    double t = kInf;
    uint32_t triangle = 0;
    double u = 0, v = 0;
    std::vector<TriangleCrossing> crossings;
};

// Every triangle in index order: the oracle of the walks.
inline Brute bruteForce(const TriangleMesh& m, const Ray& ray, double tmin, double tmax) {
    const ShearedRay sr(ray);
    Brute b;
    for (uint32_t i = 0; i < m.triangles.size(); ++i) {
        const auto& t = m.triangles[i];
        TriangleIntersection x;
        const Vec3 &p0 = m.positions[t[0]], &p1 = m.positions[t[1]], &p2 = m.positions[t[2]];
        if (!intersectWatertight(sr, p0, p1, p2, tmin, tmax, x)) continue;
        b.crossings.push_back({x.t, i, x.entering});
        if (x.t < b.t) {
            b = {true, x.t, i, x.u, x.v, std::move(b.crossings)};
        }
    }
    std::sort(b.crossings.begin(), b.crossings.end(), [](const auto& a, const auto& c) {
        return a.t < c.t || (a.t == c.t && a.triangle < c.triangle);
    });
    return b;
}

inline double tOf(const TriangleMesh& m, uint32_t tri, const Ray& ray) {
    const auto& t = m.triangles[tri];
    TriangleIntersection x;
    if (!intersectWatertight(ShearedRay(ray), m.positions[t[0]], m.positions[t[1]],
                             m.positions[t[2]], -kInf, kInf, x))
        return std::nan("");
    return x.t;
}

inline void checkAgainstBruteForce(const TriangleMesh& m, const TriangleBvh& bvh, const Ray& ray,
                                   double tmin, double tmax) {
    INFO("ray o=(" << ray.origin.x << ", " << ray.origin.y << ", " << ray.origin.z << ") d=("
                   << ray.dir.x << ", " << ray.dir.y << ", " << ray.dir.z << ") range (" << tmin
                   << ", " << tmax << ")");
    const Brute b = bruteForce(m, ray, tmin, tmax);
    BvhStats stats;
    TriangleHit hit;
    REQUIRE(bvh.closestHit(ray, tmin, tmax, hit, stats) == b.found);
    if (b.found) {
        REQUIRE(hit.t == b.t);  // bitwise: the same test on the same triangle
        if (hit.triangle == b.triangle) {
            REQUIRE(hit.u == b.u);
            REQUIRE(hit.v == b.v);
        } else {
            REQUIRE(tOf(m, hit.triangle, ray) == b.t);  // a tie at equal t
        }
    }
    REQUIRE(bvh.anyHit(ray, tmin, tmax, stats) == b.found);
    std::vector<TriangleCrossing> all;
    bvh.allCrossings(ray, tmin, tmax, all, stats);
    REQUIRE(all == b.crossings);
}

inline Vec3 randomDirection(std::mt19937_64& rng) {
    std::normal_distribution<double> g;
    Vec3 d;
    do d = {g(rng), g(rng), g(rng)};
    while (glm::length(d) < 1e-3);
    return d;
}

// Counts of entering and leaving crossings of a ray over the whole line.
inline std::pair<int, int> enterLeave(const std::vector<TriangleCrossing>& xs) {
    int in = 0, out = 0;
    for (const auto& x : xs) (x.entering ? in : out)++;
    return {in, out};
}

}  // namespace kerf::bvh_test
