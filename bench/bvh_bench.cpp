// The triangle BVH's figures: build time (1 and 2 threads) and primary- and shadow-ray
// throughput (1 thread, CPU and wall time; 2 threads, wall time) on three generated meshes,
// with a brute-force check of a sample of the rays (the same watertight test over every
// triangle: hit and t must agree bit for bit; shadow rays: occluded or not).
// Built only when asked: cmake --build build --target kerf_bvh_bench; run:
// build/mesh/kerf_bvh_bench
// [--size N] (image N×N rays per mesh, default 1024) [--only sphere|city|fan]
// [--traversal-cost C] [--leaf N] (build options, to tune) [--check RAYS] (brute-force rays
// per mesh; default as many as 2e8 triangle tests allow) [--scalar] (no AVX2 lanes)
// [--split-depth N] (halvings of thin triangles' references; 0: none).
#include "mesh/triangle_bvh.h"
#include "mesh/watertight_triangle.h"

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <random>
#include <string>

using namespace kerf;

namespace {

double seconds(std::chrono::steady_clock::time_point a) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count();
}

// This thread's CPU time: on a machine shared with other jobs it counts only the time the
// walk actually ran (wall time counts the waits too).
double threadSeconds() {
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}
double processSeconds() {
    timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

// A sphere of radius about 1 with bumps, as a latitude–longitude grid of `rows × cols` quads
// (2·rows·cols triangles, poles closed by fans).
TriangleMesh bumpySphere(int rows, int cols) {
    TriangleMesh m;
    auto radius = [](double th, double ph) {
        return 1.0 + 0.04 * std::sin(17.0 * th) * std::sin(23.0 * ph) +
               0.01 * std::sin(91.0 * th + 3.0) * std::cos(77.0 * ph);
    };
    m.positions.push_back({0, 0, radius(0, 0)});
    for (int i = 1; i < rows; ++i)
        for (int j = 0; j < cols; ++j) {
            const double th = M_PI * i / rows, ph = 2.0 * M_PI * j / cols, r = radius(th, ph);
            m.positions.push_back(
                r * Vec3(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)));
        }
    m.positions.push_back({0, 0, -radius(M_PI, 0)});
    const uint32_t south = uint32_t(m.positions.size() - 1);
    auto v = [cols](int i, int j) { return uint32_t(1 + (i - 1) * cols + (j % cols)); };
    for (int j = 0; j < cols; ++j) {
        m.triangles.push_back({0, v(1, j), v(1, j + 1)});
        m.triangles.push_back({south, v(rows - 1, j + 1), v(rows - 1, j)});
    }
    for (int i = 1; i < rows - 1; ++i)
        for (int j = 0; j < cols; ++j) {
            m.triangles.push_back({v(i, j), v(i + 1, j), v(i + 1, j + 1)});
            m.triangles.push_back({v(i, j), v(i + 1, j + 1), v(i, j + 1)});
        }
    return m;
}

// 10,000 random boxes on a 100 × 100 ground, 12 triangles each.
TriangleMesh city(int boxes) {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> pos(-50.0, 50.0), size(0.3, 2.0), height(0.0, 1.0);
    TriangleMesh m;
    for (int b = 0; b < boxes; ++b) {
        const Vec3 lo(pos(rng), pos(rng), 0.0);
        const double h = 1.0 + 14.0 * std::pow(height(rng), 3.0);
        const Vec3 hi = lo + Vec3(size(rng), size(rng), h);
        const uint32_t k = uint32_t(m.positions.size());
        for (int c = 0; c < 8; ++c)
            m.positions.push_back({c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z});
        const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                 {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
        for (const auto& q : quads) {
            m.triangles.push_back({k + q[0], k + q[1], k + q[2]});
            m.triangles.push_back({k + q[0], k + q[2], k + q[3]});
        }
    }
    return m;
}

// n long thin triangles from a shared centre to a circle of radius 1 (plane z = 0).
TriangleMesh fan(int n) {
    TriangleMesh m;
    m.positions.push_back({0, 0, 0});
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * M_PI * i / n;
        m.positions.push_back({std::cos(a), std::sin(a), 0.0});
    }
    for (int i = 0; i < n; ++i)
        m.triangles.push_back({0, uint32_t(1 + i), uint32_t(1 + (i + 1) % n)});
    return m;
}

struct Camera {
    Vec3 eye, forward, right, up;
    Camera(const Vec3& e, const Vec3& target, double fovDegrees) : eye(e) {
        forward = glm::normalize(target - e);
        right = glm::normalize(glm::cross(forward, Vec3(0, 0, 1)));
        up = glm::cross(right, forward);
        const double s = std::tan(0.5 * fovDegrees * M_PI / 180.0);
        right *= s;
        up *= s;
    }
    // A jittered ray through pixel (x, y) of an n × n image.
    Ray ray(int x, int y, int n, std::mt19937_64& rng) const {
        std::uniform_real_distribution<double> j(0.0, 1.0);
        const double u = 2.0 * (x + j(rng)) / n - 1.0, v = 1.0 - 2.0 * (y + j(rng)) / n;
        return {eye, forward + u * right + v * up};
    }
};

BvhBuildOptions gOptions;
long gCheck = -1;  // brute-force rays per mesh; -1: as many as 2e8 triangle tests allow

void run(const char* name, const TriangleMesh& mesh, const Camera& cam, const Vec3& light, int n) {
    double build1 = 0, build2 = 0, build1Cpu = 0;
    {
        tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
        const auto t0 = std::chrono::steady_clock::now();
        const double c0 = processSeconds();
        TriangleBvh b(mesh, gOptions);
        build1 = seconds(t0);
        build1Cpu = processSeconds() - c0;
    }
    const auto t0 = std::chrono::steady_clock::now();
    const TriangleBvh bvh(mesh, gOptions);
    build2 = seconds(t0);

    std::mt19937_64 rng(2);
    std::vector<Ray> rays;
    rays.reserve(size_t(n) * n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) rays.push_back(cam.ray(x, y, n, rng));

    BvhStats primaryStats, shadowStats;
    std::vector<TriangleHit> hits(rays.size());
    std::vector<char> hitMask(rays.size());
    auto t1 = std::chrono::steady_clock::now();
    double c1 = threadSeconds();
    for (size_t i = 0; i < rays.size(); ++i)
        hitMask[i] = bvh.closestHit(rays[i], 0.0, kInf, hits[i], primaryStats);
    const double primary = seconds(t1), primaryCpu = threadSeconds() - c1;
    size_t hitCount = 0, shadowed = 0;
    std::vector<Ray> shadowRays;
    for (size_t i = 0; i < rays.size(); ++i)
        if (hitMask[i]) {
            ++hitCount;
            // From the light to the hit point, stopping short of it by a relative 1e-9 of the
            // segment (no scene-scale epsilon).
            shadowRays.push_back({light, rays[i].at(hits[i].t) - light});
        }
    t1 = std::chrono::steady_clock::now();
    c1 = threadSeconds();
    for (const Ray& r : shadowRays) shadowed += bvh.anyHit(r, 0.0, 1.0 - 1e-9, shadowStats);
    const double shadow = seconds(t1), shadowCpu = threadSeconds() - c1;

    // The same rays on two threads (wall time; the answers must not change).
    double primary2 = 0, shadow2 = 0;
    size_t differ2 = 0;
    {
        tbb::global_control two(tbb::global_control::max_allowed_parallelism, 2);
        std::vector<char> mask2(rays.size());
        std::vector<double> t2(rays.size());
        auto t2start = std::chrono::steady_clock::now();
        tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 4096),
                          [&](const tbb::blocked_range<size_t>& r) {
                              BvhStats st;
                              for (size_t i = r.begin(); i < r.end(); ++i) {
                                  TriangleHit h;
                                  mask2[i] = bvh.closestHit(rays[i], 0.0, kInf, h, st);
                                  t2[i] = h.t;
                              }
                          });
        primary2 = seconds(t2start);
        std::vector<char> occ2(shadowRays.size());
        t2start = std::chrono::steady_clock::now();
        tbb::parallel_for(tbb::blocked_range<size_t>(0, shadowRays.size(), 4096),
                          [&](const tbb::blocked_range<size_t>& r) {
                              BvhStats st;
                              for (size_t i = r.begin(); i < r.end(); ++i)
                                  occ2[i] = bvh.anyHit(shadowRays[i], 0.0, 1.0 - 1e-9, st);
                          });
        shadow2 = seconds(t2start);
        size_t occluded2 = 0;
        for (size_t i = 0; i < rays.size(); ++i)
            differ2 += mask2[i] != hitMask[i] || (mask2[i] && t2[i] != hits[i].t);
        for (char o : occ2) occluded2 += o;
        differ2 += occluded2 != shadowed;
    }

    // Brute force on a sample of the primary rays and of the shadow rays: the reference.
    const size_t sample =
        gCheck >= 0
            ? std::min<size_t>(rays.size(), size_t(gCheck))
            : std::max<size_t>(1, std::min<size_t>(rays.size(), 2e8 / mesh.triangles.size()));
    size_t mismatches = 0;
    for (size_t s = 0; s < sample; ++s) {
        const size_t i = (s * 7919) % rays.size();
        const ShearedRay sr(rays[i]);
        double best = kInf;
        for (const auto& t : mesh.triangles) {
            TriangleIntersection x;
            if (intersectWatertight(sr, mesh.positions[t[0]], mesh.positions[t[1]],
                                    mesh.positions[t[2]], 0.0, best, x))
                best = x.t;
        }
        const bool bruteHit = best < kInf;
        if (bruteHit != bool(hitMask[i]) || (bruteHit && best != hits[i].t)) ++mismatches;
    }
    size_t shadowMismatches = 0;
    const size_t shadowSample = std::min(sample, shadowRays.size());
    for (size_t s = 0; s < shadowSample; ++s) {
        const size_t i = (s * 7919) % shadowRays.size();
        const ShearedRay sr(shadowRays[i]);
        bool any = false;
        for (const auto& t : mesh.triangles) {
            TriangleIntersection x;
            if (intersectWatertight(sr, mesh.positions[t[0]], mesh.positions[t[1]],
                                    mesh.positions[t[2]], 0.0, 1.0 - 1e-9, x)) {
                any = true;
                break;
            }
        }
        BvhStats st;
        if (any != bvh.anyHit(shadowRays[i], 0.0, 1.0 - 1e-9, st)) ++shadowMismatches;
    }
    std::printf("%s: %zu triangles, %zu nodes, depth %d\n", name, bvh.triangleCount(),
                bvh.nodeCount(), bvh.depth());
    std::printf("  build: %.3f s (1 thread; CPU time %.3f s), %.3f s (2 threads)\n", build1,
                build1Cpu, build2);
    std::printf(
        "  primary: %zu rays, %zu hits, %.3f s, %.2f M rays/s (CPU time %.3f s, "
        "%.2f M rays/s); per ray %.1f nodes, %.1f triangles\n",
        rays.size(), hitCount, primary, rays.size() / primary * 1e-6, primaryCpu,
        rays.size() / primaryCpu * 1e-6, double(primaryStats.nodesVisited) / rays.size(),
        double(primaryStats.trianglesTested) / rays.size());
    std::printf(
        "  shadow: %zu rays, %zu occluded, %.3f s, %.2f M rays/s (CPU time %.3f s, "
        "%.2f M rays/s); per ray %.1f nodes, %.1f triangles\n",
        shadowRays.size(), shadowed, shadow, shadowRays.size() / shadow * 1e-6, shadowCpu,
        shadowRays.size() / shadowCpu * 1e-6,
        double(shadowStats.nodesVisited) / std::max<size_t>(1, shadowRays.size()),
        double(shadowStats.trianglesTested) / std::max<size_t>(1, shadowRays.size()));
    std::printf(
        "  2 threads: primary %.3f s, %.2f M rays/s; shadow %.3f s, %.2f M rays/s "
        "(wall time); %zu answers differ from 1 thread\n",
        primary2, rays.size() / primary2 * 1e-6, shadow2,
        shadowRays.size() / std::max(shadow2, 1e-12) * 1e-6, differ2);
    std::printf(
        "  brute force on %zu primary rays: %zu differ (hit or t, bitwise); on %zu shadow "
        "rays: %zu differ\n",
        sample, mismatches, shadowSample, shadowMismatches);
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
    int n = 1024;
    std::string only;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--size") && i + 1 < argc)
            n = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--only") && i + 1 < argc)
            only = argv[++i];
        else if (!std::strcmp(argv[i], "--traversal-cost") && i + 1 < argc)
            gOptions.traversalCost = std::atof(argv[++i]);
        else if (!std::strcmp(argv[i], "--check") && i + 1 < argc)
            gCheck = std::atol(argv[++i]);
        else if (!std::strcmp(argv[i], "--split-depth") && i + 1 < argc)
            gOptions.splitDepth = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--scalar"))
            gOptions.simd = false;
        else if (!std::strcmp(argv[i], "--leaf") && i + 1 < argc)
            gOptions.maxLeafSize = std::atoi(argv[++i]);
        else {
            std::fprintf(
                stderr,
                "usage: kerf_bvh_bench [--size N] [--only sphere|city|fan] [--traversal-cost C] "
                "[--leaf N] [--check RAYS] [--scalar] [--split-depth N]\n");
            return 2;
        }
    }
    if (n < 1 || n > 8192) {
        std::fprintf(stderr, "kerf_bvh_bench: --size must be 1..8192\n");
        return 2;
    }
    if (only.empty() || only == "sphere")
        run("bumpy sphere", bumpySphere(500, 1000), Camera({0, -3.2, 1.0}, {0, 0, 0}, 40.0),
            {3, -3, 5}, n);
    if (only.empty() || only == "city")
        run("city", city(10000), Camera({-60, -70, 40}, {0, 0, 0}, 50.0), {30, -20, 100}, n);
    if (only.empty() || only == "fan")
        run("fan", fan(100000), Camera({0.3, -1.6, 1.2}, {0, 0, 0}, 60.0), {0.5, 0.5, 2.0}, n);
    return 0;
}
