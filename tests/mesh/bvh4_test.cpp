// The fast paths of the triangle BVH's walks against the reference decisions: the AVX2 box
// test against the scalar one (same answers and same counters, so the same boxes culled), and
// both against brute force over every triangle on random rays and on rays aimed exactly at
// vertices and edges (where the watertight test's tie rule decides).
#include "bvh_test_meshes.h"

using namespace kerf;
using namespace kerf::bvh_test;

namespace {

// Rays at the mesh's vertices and at points on its edges, from random origins, plus random
// rays; some with ranges reaching below 0 or cut short (the box test's other branches).
struct AimedRay {
    Ray ray;
    double tmin, tmax;
};

std::vector<AimedRay> aimedRays(const TriangleMesh& m, std::mt19937_64& rng, int count) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<AimedRay> rays;
    for (int i = 0; i < count; ++i) {
        const auto& t = m.triangles[size_t(rng() % m.triangles.size())];
        const Vec3 p = m.positions[t[i % 3]], q = m.positions[t[(i + 1) % 3]];
        Vec3 target;
        switch (i % 4) {
            case 0: target = p; break;                                // a vertex
            case 1: target = 0.5 * (p + q); break;                    // an edge's midpoint (exact)
            case 2: target = p + 0.25 * (q - p); break;               // a point along an edge
            default: target = Vec3(unit(rng), unit(rng), unit(rng));  // anywhere
        }
        AimedRay r{{2.5 * Vec3(unit(rng), unit(rng), unit(rng)), {}}, 0.0, kInf};
        r.ray.dir = target - r.ray.origin;
        if (i % 9 == 0) {  // axis-aligned through the target, with signed zeros
            Vec3 d(i % 18 ? 0.0 : -0.0);
            d[i / 9 % 3] = unit(rng) < 0 ? -1.0 : 1.0;
            r.ray = {target - 3.0 * d, d};
        }
        if (i % 5 == 1) r.tmin = -kInf;  // the range reaches behind the origin
        if (i % 7 == 3) r.tmax = 0.5 + unit(rng);
        if (glm::length(r.ray.dir) > 0.0) rays.push_back(r);
    }
    return rays;
}

std::vector<std::pair<const char*, TriangleMesh>> meshes() {
    std::mt19937_64 rng(5);
    std::vector<std::pair<const char*, TriangleMesh>> out;
    out.push_back({"icosphere", icosphere(4)});
    out.push_back({"jittered grid", jitteredGrid(24, rng)});
    out.push_back({"fan", fan(2000)});
    return out;
}

}  // namespace

TEST_CASE("bvh4/the AVX2 walks equal the scalar walks, counters included") {
    std::mt19937_64 rng(11);
    for (const auto& [name, m] : meshes()) {
        BvhBuildOptions scalarOpts, simdOpts;
        scalarOpts.simd = false;
        const TriangleBvh scalar(m, scalarOpts), simd(m, simdOpts);
        INFO(name);
        for (const AimedRay& r : aimedRays(m, rng, 2000)) {
            BvhStats ss, vs;
            TriangleHit sh, vh;
            const bool sf = scalar.closestHit(r.ray, r.tmin, r.tmax, sh, ss);
            REQUIRE(simd.closestHit(r.ray, r.tmin, r.tmax, vh, vs) == sf);
            if (sf) {
                REQUIRE(vh.t == sh.t);
                REQUIRE(vh.triangle == sh.triangle);
                REQUIRE(vh.u == sh.u);
                REQUIRE(vh.v == sh.v);
            }
            REQUIRE(simd.anyHit(r.ray, r.tmin, r.tmax, vs) ==
                    scalar.anyHit(r.ray, r.tmin, r.tmax, ss));
            std::vector<TriangleCrossing> sx, vx;
            scalar.allCrossings(r.ray, r.tmin, r.tmax, sx, ss);
            simd.allCrossings(r.ray, r.tmin, r.tmax, vx, vs);
            REQUIRE(vx == sx);
            REQUIRE(vs.nodesVisited == ss.nodesVisited);
            REQUIRE(vs.trianglesTested == ss.trianglesTested);
        }
    }
}

TEST_CASE("bvh4/both walks equal brute force on rays aimed at vertices and edges") {
    std::mt19937_64 rng(12);
    for (const auto& [name, m] : meshes())
        for (bool useSimd : {false, true}) {
            BvhBuildOptions opts;
            opts.simd = useSimd;
            const TriangleBvh bvh(m, opts);
            INFO(name << (useSimd ? " simd" : " scalar"));
            for (const AimedRay& r : aimedRays(m, rng, 600))
                checkAgainstBruteForce(m, bvh, r.ray, r.tmin, r.tmax);
        }
}
