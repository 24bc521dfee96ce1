// The BVH's watertightness: rays through shared edges and vertices never slip between triangles,
// closed meshes are entered as often as left, and entering follows the geometric normal.
#include "bvh_test_meshes.h"

using namespace kerf;
using namespace kerf::bvh_test;

TEST_CASE("triangle_bvh/watertight on a jittered grid's shared edges and vertices") {
    std::mt19937_64 rng(7);
    const int n = 12;
    const TriangleMesh m = jitteredGrid(n, rng);
    const TriangleBvh bvh(m);
    std::uniform_real_distribution<double> u(-3.0, 3.0);
    int rays = 0;
    // Targets: every interior vertex and every edge's midpoint and points along the edge.
    std::vector<Vec3> targets;
    for (const auto& t : m.triangles)
        for (int e = 0; e < 3; ++e) {
            const Vec3 p = m.positions[t[e]], q = m.positions[t[(e + 1) % 3]];
            targets.push_back(p);
            for (double s : {0.5, 1.0 / 3.0, 0.1, 0.999}) targets.push_back(p + s * (q - p));
        }
    for (const Vec3& target : targets) {
        // Only targets strictly inside the grid's square are sure to lie on the surface.
        if (!(target.x > 0 && target.y > 0 && target.x < n && target.y < n)) continue;
        for (int k = 0; k < 3; ++k) {
            const Vec3 origin(target.x + u(rng), target.y + u(rng), k == 2 ? -2.5 : 2.5);
            const Ray ray{origin, target - origin};
            BvhStats stats;
            TriangleHit hit;
            INFO("target (" << target.x << ", " << target.y << ")");
            REQUIRE(bvh.closestHit(ray, 0.0, kInf, hit, stats));
            // The plane z = 0 is crossed at t = 1 up to the rounding of the target.
            REQUIRE(hit.t == Approx(1.0).epsilon(1e-12));
            std::vector<TriangleCrossing> xs;
            bvh.allCrossings(ray, 0.0, kInf, xs, stats);
            REQUIRE(xs.size() == 1);
            ++rays;
        }
        // Axis-aligned rays, both signs, with −0 in the other components.
        for (double dz : {-1.0, 1.0}) {
            const Ray ray{{target.x, target.y, -4.0 * dz}, {-0.0, 0.0, dz}};
            const Ray ray2{{target.x, target.y, -4.0 * dz}, {0.0, -0.0, dz}};
            BvhStats stats;
            TriangleHit hit;
            INFO("axis ray at (" << target.x << ", " << target.y << ")");
            REQUIRE(bvh.closestHit(ray, 0.0, kInf, hit, stats));
            REQUIRE(hit.t == 4.0);
            REQUIRE(bvh.anyHit(ray2, 0.0, kInf, stats));
            // Through an edge or vertex of a flat sheet, exactly one triangle counts.
            std::vector<TriangleCrossing> xs;
            bvh.allCrossings(ray, 0.0, kInf, xs, stats);
            REQUIRE(xs.size() == 1);
            rays += 2;
        }
    }
    REQUIRE(rays > 1000);
}

TEST_CASE("triangle_bvh/watertight through the centre of a fan") {
    // 1000 thin triangles meet at the origin: rays through it from every side must hit.
    const TriangleMesh m = fan(1000);
    const TriangleBvh bvh(m);
    std::mt19937_64 rng(3);
    for (int i = 0; i < 2000; ++i) {
        Vec3 o = randomDirection(rng) * 3.0;
        if (std::fabs(o.z) < 0.1) o.z = 1.0;
        const Ray ray{o, -o};
        BvhStats stats;
        TriangleHit hit;
        REQUIRE(bvh.closestHit(ray, 0.0, kInf, hit, stats));
        REQUIRE(hit.t == Approx(1.0).epsilon(1e-12));
    }
    for (double s : {-1.0, 1.0}) {
        BvhStats stats;
        REQUIRE(bvh.anyHit({{0, 0, s}, {-0.0, -0.0, -s}}, 0.0, kInf, stats));
    }
}

TEST_CASE("triangle_bvh/closed meshes are entered as often as they are left") {
    std::mt19937_64 rng(11);
    for (int levels : {0, 3}) {
        const TriangleMesh m = icosphere(levels);
        const TriangleBvh bvh(m);
        std::vector<Vec3> targets = m.positions;
        for (const auto& t : m.triangles)
            for (int e = 0; e < 3; ++e)
                targets.push_back(0.5 * (m.positions[t[e]] + m.positions[t[(e + 1) % 3]]));
        int rays = 0;
        for (const Vec3& target : targets) {
            // Lines through the target and an interior point enter the solid there.
            std::vector<Ray> enter;
            for (int k = 0; k < 4; ++k) {
                const Vec3 inner = glm::normalize(randomDirection(rng)) * 0.3 * (k / 4.0);
                const Vec3 o = target + 3.0 * (target - inner);
                enter.push_back({o, target - o});
            }
            // Axis-aligned through the target, −0 in the other components: these may only
            // touch the surface there.
            std::vector<Ray> any = enter;
            for (int a = 0; a < 3; ++a)
                for (double s : {-1.0, 1.0}) {
                    Vec3 d(-0.0), o = target;
                    d[a] = s;
                    o[a] = target[a] - 5.0 * s;
                    any.push_back({o, d});
                }
            for (size_t r = 0; r < any.size(); ++r) {
                const Ray& ray = any[r];
                INFO("level " << levels << " target (" << target.x << ", " << target.y << ", "
                              << target.z << ") ray " << r);
                BvhStats stats;
                std::vector<TriangleCrossing> xs;
                bvh.allCrossings(ray, -kInf, kInf, xs, stats);
                if (r < enter.size()) REQUIRE(xs.size() == 2);  // convex: in once, out once
                const auto [in, out] = enterLeave(xs);
                REQUIRE(in == out);
                // Inside depth after each group of equal t never goes below 0 (crossings at
                // one t, like touching a vertex, come in any order).
                int inside = 0;
                for (size_t i = 0; i < xs.size(); ++i) {
                    inside += xs[i].entering ? 1 : -1;
                    if (i + 1 == xs.size() || xs[i + 1].t != xs[i].t) REQUIRE(inside >= 0);
                }
                ++rays;
            }
        }
        REQUIRE(rays > 20);
    }
}

TEST_CASE("triangle_bvh/entering follows the geometric normal") {
    const TriangleMesh m = icosphere(2);
    const TriangleBvh bvh(m);
    std::mt19937_64 rng(5);
    for (int i = 0; i < 500; ++i) {
        const Ray ray{glm::normalize(randomDirection(rng)) * 0.3, randomDirection(rng)};
        BvhStats stats;
        std::vector<TriangleCrossing> xs;
        bvh.allCrossings(ray, -kInf, kInf, xs, stats);
        REQUIRE(xs.size() == 2);  // a convex mesh, met from inside: once each way
        for (const auto& x : xs) {
            const auto& t = m.triangles[x.triangle];
            const Vec3 n = glm::cross(m.positions[t[1]] - m.positions[t[0]],
                                      m.positions[t[2]] - m.positions[t[0]]);
            const double d = glm::dot(ray.dir, n);
            if (std::fabs(d) > 1e-9 * glm::length(ray.dir) * glm::length(n))
                REQUIRE(x.entering == (d < 0.0));
        }
        // From inside: the ray leaves forward once and (backwards) was entered once.
        const auto [in, out] = enterLeave(xs);
        REQUIRE(in == out);
    }
}
