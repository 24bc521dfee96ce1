// The triangle BVH: the three walks against brute force over every triangle, degenerate
// inputs, the work counters, scaling, and the build's independence of its task split (the
// watertightness tests are in watertight_triangle_test.cpp).
#include "bvh_test_meshes.h"

using namespace kerf;
using namespace kerf::bvh_test;

TEST_CASE("triangle_bvh/walks equal brute force on random meshes") {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    struct Case {
        const char* name;
        TriangleMesh mesh;
    };
    std::vector<Case> cases;
    {
        TriangleMesh soup;  // random triangles of random sizes
        for (int i = 0; i < 3000; ++i) {
            const Vec3 c(unit(rng), unit(rng), unit(rng));
            const double s = std::pow(10.0, -2.0 + 1.5 * (unit(rng) + 1.0) / 2.0);
            for (int k = 0; k < 3; ++k)
                soup.positions.push_back(c + s * Vec3(unit(rng), unit(rng), unit(rng)));
            const uint32_t b = uint32_t(soup.positions.size() - 3);
            soup.triangles.push_back({b, b + 1, b + 2});
        }
        cases.push_back({"soup", soup});
    }
    {
        TriangleMesh needles;  // long thin triangles crossing the cube
        for (int i = 0; i < 2000; ++i) {
            const Vec3 a(unit(rng), unit(rng), unit(rng)), b(unit(rng), unit(rng), unit(rng));
            const Vec3 w = 1e-3 * Vec3(unit(rng), unit(rng), unit(rng));
            needles.positions.insert(needles.positions.end(), {a, b, a + w});
            const uint32_t k = uint32_t(needles.positions.size() - 3);
            needles.triangles.push_back({k, k + 1, k + 2});
        }
        cases.push_back({"needles", needles});
    }
    cases.push_back({"sphere", icosphere(5)});  // 8192 triangles, shared vertices
    cases.push_back({"fan", fan(3000)});

    for (const auto& c : cases) {
        for (const BvhBuildOptions& opts :
             {BvhBuildOptions{}, BvhBuildOptions{2, 1, 64}, BvhBuildOptions{8, 4, 1 << 30}}) {
            const TriangleBvh bvh(c.mesh, opts);
            INFO(c.name << " bins " << opts.bins << " leaf " << opts.maxLeafSize);
            REQUIRE(bvh.triangleCount() == c.mesh.triangles.size());
            REQUIRE(bvh.depth() <= TriangleBvh::kMaxDepth);
            for (int i = 0; i < 300; ++i) {
                Ray ray{2.0 * Vec3(unit(rng), unit(rng), unit(rng)), randomDirection(rng)};
                if (i % 10 == 0) {  // axis-aligned with signed zeros
                    Vec3 d(i % 20 ? 0.0 : -0.0);
                    d[i / 10 % 3] = unit(rng) < 0 ? -1.0 : 1.0;
                    ray.dir = d;
                }
                if (i % 7 == 0) ray.origin = 0.2 * ray.origin;  // from inside the cloud
                double tmin = 0.0, tmax = kInf;
                if (i % 3 == 1) tmin = 0.5 + unit(rng);
                if (i % 4 == 2) tmax = 1.0 + unit(rng);
                checkAgainstBruteForce(c.mesh, bvh, ray, tmin, tmax);
            }
        }
    }
}

TEST_CASE("triangle_bvh/degenerate inputs build and trace") {
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    SECTION("no triangles") {
        TriangleMesh m;
        const TriangleBvh bvh(m);
        REQUIRE(bvh.nodeCount() == 0);
        REQUIRE(bvh.depth() == 0);
        BvhStats stats;
        TriangleHit hit;
        REQUIRE(!bvh.closestHit({{0, 0, -1}, {0, 0, 1}}, 0.0, kInf, hit, stats));
        REQUIRE(!bvh.anyHit({{0, 0, -1}, {0, 0, 1}}, 0.0, kInf, stats));
        std::vector<TriangleCrossing> xs{{1.0, 0, true}};
        bvh.allCrossings({{0, 0, -1}, {0, 0, 1}}, 0.0, kInf, xs, stats);
        REQUIRE(xs.empty());
    }
    SECTION("a zero direction meets nothing") {
        const TriangleMesh m = icosphere(1);
        const TriangleBvh bvh(m);
        for (const Vec3& o : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(3, 0, 0)}) {
            BvhStats stats;
            TriangleHit hit;
            const Ray ray{o, {0.0, -0.0, 0.0}};
            REQUIRE(!bvh.closestHit(ray, 0.0, kInf, hit, stats));
            REQUIRE(!bvh.anyHit(ray, 0.0, kInf, stats));
            std::vector<TriangleCrossing> xs;
            bvh.allCrossings(ray, -kInf, kInf, xs, stats);
            REQUIRE(xs.empty());
        }
    }
    SECTION("every triangle the same") {
        TriangleMesh m;
        m.positions = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
        m.triangles.assign(5000, {0, 1, 2});
        const TriangleBvh bvh(m);
        REQUIRE(bvh.depth() <= TriangleBvh::kMaxDepth);
        const Ray ray{{0.1, 0.2, -2.0}, {0, 0, 1}};
        BvhStats stats;
        TriangleHit hit;
        REQUIRE(bvh.closestHit(ray, 0.0, kInf, hit, stats));
        REQUIRE(hit.t == 2.0);
        std::vector<TriangleCrossing> xs;
        bvh.allCrossings(ray, 0.0, kInf, xs, stats);
        REQUIRE(xs.size() == 5000);
        for (uint32_t i = 0; i < xs.size(); ++i) {
            REQUIRE(xs[i].triangle == i);
            REQUIRE(xs[i].entering == false);  // normal +z, ray along +z: leaving
        }
        for (int i = 0; i < 50; ++i)
            checkAgainstBruteForce(m, bvh, {{unit(rng), unit(rng), -2.0}, randomDirection(rng)},
                                   0.0, kInf);
    }
    SECTION("zero-area triangles among good ones") {
        TriangleMesh m;
        for (int i = 0; i < 2000; ++i) {
            const Vec3 a(unit(rng), unit(rng), unit(rng)), b(unit(rng), unit(rng), unit(rng));
            const uint32_t k = uint32_t(m.positions.size());
            switch (i % 4) {
                case 0:  // a point
                    m.positions.insert(m.positions.end(), {a, a, a});
                    break;
                case 1:  // collinear: a, its mirror through b's midpoint, and b
                    m.positions.insert(m.positions.end(), {a, 0.5 * (a + b), b});
                    break;
                case 2:  // two equal corners
                    m.positions.insert(m.positions.end(), {a, b, b});
                    break;
                default:
                    m.positions.insert(m.positions.end(), {a, b, Vec3(unit(rng), 0.0, unit(rng))});
            }
            m.triangles.push_back({k, k + 1, k + 2});
        }
        const TriangleBvh bvh(m);
        for (int i = 0; i < 300; ++i) {
            // Half the rays aimed straight at a degenerate triangle's corner.
            Ray ray{2.0 * Vec3(unit(rng), unit(rng), unit(rng)), randomDirection(rng)};
            if (i % 2) ray.dir = m.positions[3 * ((i * 4) % 2000)] - ray.origin;
            checkAgainstBruteForce(m, bvh, ray, 0.0, kInf);
        }
        // A point triangle alone is never hit, even dead on.
        TriangleMesh point;
        point.positions = {{0.5, 0.5, 0.5}};
        point.triangles = {{0, 0, 0}};
        BvhStats stats;
        REQUIRE(!TriangleBvh(point).anyHit({{0, 0, 0}, {1, 1, 1}}, 0.0, kInf, stats));
    }
}

TEST_CASE("triangle_bvh/stats count the work") {
    const TriangleMesh m = icosphere(4);
    const TriangleBvh bvh(m);
    BvhStats stats;
    TriangleHit hit;
    REQUIRE(bvh.closestHit({{0.01, 0.02, -5}, {0, 0, 1}}, 0.0, kInf, hit, stats));
    REQUIRE(stats.nodesVisited >= uint64_t(bvh.depth()));
    REQUIRE(stats.trianglesTested >= 1);
    // The BVH tests far fewer triangles than there are.
    REQUIRE(stats.trianglesTested < m.triangles.size() / 20);
    // The hit is on the sphere's tessellation: between the inscribed and the unit sphere.
    REQUIRE(hit.t <= 5.0 - std::cos(M_PI / 32) + 1e-12);
    REQUIRE(hit.t >= 4.0);
}

TEST_CASE("triangle_bvh/scaling by a power of two changes nothing but the scale") {
    // Every operation of the build and the walks is exact under a power-of-two scale (no
    // overflow or underflow here), so the answers must scale bit for bit: no hidden epsilon.
    const TriangleMesh base = icosphere(3);
    const TriangleBvh bvh(base);
    std::mt19937_64 rng(13);
    for (double s : {0x1p-40, 0x1p40}) {
        TriangleMesh scaled = base;
        for (Vec3& p : scaled.positions) p *= s;
        const TriangleBvh sb(scaled);
        REQUIRE(sb.nodeCount() == bvh.nodeCount());
        for (int i = 0; i < 300; ++i) {
            const Ray ray{glm::normalize(randomDirection(rng)) * 2.0 * (i % 3 ? 1.0 : 0.2),
                          randomDirection(rng)};
            const Ray rs{ray.origin * s, ray.dir * s};
            BvhStats stats;
            std::vector<TriangleCrossing> a, b;
            bvh.allCrossings(ray, 0.0, kInf, a, stats);
            sb.allCrossings(rs, 0.0, kInf, b, stats);
            REQUIRE(a == b);  // t is scale-free: o + t·d scales with o and d
        }
    }
}

TEST_CASE("triangle_bvh/the tree does not depend on how the build is split into tasks") {
    // Built all in one task and with every split above 2 triangles a TBB task: the same nodes,
    // so the same answers, ties included.
    TriangleMesh m = icosphere(4);
    m.triangles.insert(m.triangles.end(), m.triangles.begin(), m.triangles.begin() + 500);
    BvhBuildOptions serial, tasks;
    serial.parallelAbove = 1 << 30;
    tasks.parallelAbove = 2;
    const TriangleBvh a(m, serial), b(m, tasks);
    REQUIRE(a.nodeCount() == b.nodeCount());
    REQUIRE(a.depth() == b.depth());
    std::mt19937_64 rng(17);
    for (int i = 0; i < 500; ++i) {
        const Ray ray{glm::normalize(randomDirection(rng)) * 2.0, randomDirection(rng)};
        BvhStats sa, sb;
        TriangleHit ha, hb;
        REQUIRE(a.closestHit(ray, 0.0, kInf, ha, sa) == b.closestHit(ray, 0.0, kInf, hb, sb));
        REQUIRE(ha.t == hb.t);
        REQUIRE(ha.triangle == hb.triangle);
        REQUIRE(sa.nodesVisited == sb.nodesVisited);
        REQUIRE(sa.trianglesTested == sb.trianglesTested);
    }
}
