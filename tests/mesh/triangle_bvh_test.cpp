// The triangle BVH: watertightness of the ray–triangle test on shared edges and vertices, the
// three walks against brute force over every triangle, and degenerate inputs.
#include "mesh/triangle_bvh.h"
#include "mesh/watertight_triangle.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <random>

using namespace kerf;

namespace {

TriangleMesh octahedron() {
    TriangleMesh m;
    m.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    // Counter-clockwise seen from outside.
    m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                   {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    return m;
}

// The octahedron subdivided `levels` times, vertices pushed onto the unit sphere (shared
// midpoints, so the mesh stays closed).
TriangleMesh icosphere(int levels) {
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
TriangleMesh jitteredGrid(int n, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> jitter(-0.3, 0.3);
    TriangleMesh m;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const bool border = i == 0 || j == 0 || i == n || j == n;
            m.positions.push_back({i + (border ? 0.0 : jitter(rng)),
                                   j + (border ? 0.0 : jitter(rng)), 0.0});
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
TriangleMesh fan(int k) {
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
Brute bruteForce(const TriangleMesh& m, const Ray& ray, double tmin, double tmax) {
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

double tOf(const TriangleMesh& m, uint32_t tri, const Ray& ray) {
    const auto& t = m.triangles[tri];
    TriangleIntersection x;
    if (!intersectWatertight(ShearedRay(ray), m.positions[t[0]], m.positions[t[1]],
                             m.positions[t[2]], -kInf, kInf, x))
        return std::nan("");
    return x.t;
}

void checkAgainstBruteForce(const TriangleMesh& m, const TriangleBvh& bvh, const Ray& ray,
                            double tmin, double tmax) {
    INFO("ray o=(" << ray.origin.x << ", " << ray.origin.y << ", " << ray.origin.z << ") d=("
                   << ray.dir.x << ", " << ray.dir.y << ", " << ray.dir.z << ") range ("
                   << tmin << ", " << tmax << ")");
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

Vec3 randomDirection(std::mt19937_64& rng) {
    std::normal_distribution<double> g;
    Vec3 d;
    do d = {g(rng), g(rng), g(rng)};
    while (glm::length(d) < 1e-3);
    return d;
}

// Counts of entering and leaving crossings of a ray over the whole line.
std::pair<int, int> enterLeave(const std::vector<TriangleCrossing>& xs) {
    int in = 0, out = 0;
    for (const auto& x : xs) (x.entering ? in : out)++;
    return {in, out};
}

}  // namespace

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
