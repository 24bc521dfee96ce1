// Split references of thin triangles: every point of a triangle lies in one of its references'
// boxes, and a BVH built over split references answers as brute force does, each triangle
// reported once.
#include "bvh_test_meshes.h"

#include "mesh/bvh_split.h"

using namespace kerf;
using namespace kerf::bvh_test;

namespace {

TriangleMesh needles(int count, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    TriangleMesh m;
    for (int i = 0; i < count; ++i) {
        const Vec3 a(unit(rng), unit(rng), unit(rng)), b(unit(rng), unit(rng), unit(rng));
        const Vec3 w = 1e-3 * Vec3(unit(rng), unit(rng), unit(rng));
        m.positions.insert(m.positions.end(), {a, b, a + w});
        const uint32_t k = uint32_t(m.positions.size() - 3);
        m.triangles.push_back({k, k + 1, k + 2});
    }
    return m;
}

}  // namespace

TEST_CASE("bvh_split/the pieces' boxes cover their triangle") {
    std::mt19937_64 rng(21);
    TriangleMesh m = needles(300, rng);
    const TriangleMesh f = fan(200);
    for (const auto& t : f.triangles)
        m.triangles.push_back({t[0] + uint32_t(m.positions.size()),
                               t[1] + uint32_t(m.positions.size()),
                               t[2] + uint32_t(m.positions.size())});
    m.positions.insert(m.positions.end(), f.positions.begin(), f.positions.end());
    const std::vector<TriangleRef> refs = triangleReferences(m, 6, 16.0);
    REQUIRE(refs.size() > 4 * m.triangles.size());  // thin triangles do split
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    size_t r = 0;
    for (uint32_t i = 0; i < m.triangles.size(); ++i) {
        const size_t first = r;
        while (r < refs.size() && refs[r].triangle == i) ++r;
        REQUIRE(r > first);  // consecutive, in triangle order
        const Vec3 p0 = m.positions[m.triangles[i][0]], p1 = m.positions[m.triangles[i][1]],
                   p2 = m.positions[m.triangles[i][2]];
        Bounds3 whole;
        for (const Vec3& p : {p0, p1, p2}) whole.extend(p);
        for (size_t k = first; k < r; ++k) {
            REQUIRE(refs[k].box.lo.x >= whole.lo.x);
            REQUIRE(refs[k].box.hi.x <= whole.hi.x);
            REQUIRE(refs[k].box.lo.z >= whole.lo.z);
            REQUIRE(refs[k].box.hi.z <= whole.hi.z);
        }
        // Points of the triangle: its corners, points along its edges and inside.
        std::vector<Vec3> points{p0, p1, p2};
        for (int s = 0; s < 60; ++s) {
            double a = u01(rng), b = u01(rng);
            if (a + b > 1.0) a = 1.0 - a, b = 1.0 - b;
            if (s % 3 == 0) b = 0.0;  // on an edge
            points.push_back(p0 + a * (p1 - p0) + b * (p2 - p0));
        }
        for (const Vec3& p : points) {
            bool inside = false;
            for (size_t k = first; k < r && !inside; ++k) inside = refs[k].box.contains(p);
            INFO("triangle " << i << " point (" << p.x << ", " << p.y << ", " << p.z << ")");
            REQUIRE(inside);
        }
    }
}

TEST_CASE("bvh_split/split walks equal brute force and report each triangle once") {
    std::mt19937_64 rng(22);
    const std::vector<std::pair<const char*, TriangleMesh>> meshes{{"needles", needles(1500, rng)},
                                                                   {"fan", fan(3000)}};
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (const auto& [name, m] : meshes)
        for (bool useSimd : {false, true}) {
            BvhBuildOptions opts;
            opts.splitDepth = 6;
            opts.simd = useSimd;
            const TriangleBvh bvh(m, opts);
            INFO(name << (useSimd ? " simd" : " scalar"));
            REQUIRE(bvh.triangleCount() == m.triangles.size());
            for (int i = 0; i < 400; ++i) {
                const auto& t = m.triangles[size_t(rng() % m.triangles.size())];
                // Rays at corners, edges and random points; some over the whole line.
                const Vec3 target = i % 3 == 0   ? m.positions[t[0]]
                                    : i % 3 == 1 ? 0.5 * (m.positions[t[1]] + m.positions[t[2]])
                                                 : Vec3(unit(rng), unit(rng), unit(rng));
                const Vec3 origin = 2.5 * Vec3(unit(rng), unit(rng), unit(rng));
                const double tmin = i % 4 == 0 ? -kInf : 0.0;
                checkAgainstBruteForce(m, bvh, {origin, target - origin}, tmin, kInf);
            }
        }
}

TEST_CASE("bvh_split/splitting a fan's references cuts the triangles tested") {
    const TriangleMesh m = fan(20000);
    BvhBuildOptions none, split;
    none.splitDepth = 0;
    split.splitDepth = 5;
    const TriangleBvh a(m, none), b(m, split);
    std::mt19937_64 rng(23);
    BvhStats sa, sb;
    for (int i = 0; i < 200; ++i) {
        Vec3 o = randomDirection(rng) * 3.0;
        if (std::fabs(o.z) < 0.5) o.z = 1.0;
        const Ray ray{o, Vec3(0.3 * o.y / 3.0, -0.3 * o.x / 3.0, 0.0) - o};
        TriangleHit ha, hb;
        REQUIRE(a.closestHit(ray, 0.0, kInf, ha, sa) == b.closestHit(ray, 0.0, kInf, hb, sb));
        REQUIRE(ha.t == hb.t);
    }
    REQUIRE(sb.trianglesTested * 4 < sa.trianglesTested);
}
