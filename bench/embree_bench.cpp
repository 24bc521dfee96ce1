// kerf's triangle BVH against Embree 3 on the same meshes, rays and machine, in one process
// (issue 12 §3; docs/BENCHMARKS.md, "Meshes against Embree"). A bench-only peer: Embree is
// never linked into kerf. For each PLY file (bench/gen_bench_meshes.py writes the three):
//   - build time on 1 and 2 threads: kerf's TriangleBvh under a TBB global_control, Embree's
//     scene with RTC_BUILD_QUALITY_HIGH on a device configured "threads=N" (median of
//     --build-runs);
//   - primary rays (a pinhole camera framing the mesh, N × N jittered rays, closestHit against
//     rtcIntersect1) and shadow rays (from kerf's primary hits toward a point light, anyHit
//     against rtcOccluded1) on 1 and 2 threads: single rays, as a renderer calls them; the
//     2-thread figures split the rays over 2 std::threads in chunks of 64, each with its own
//     stats and context (median wall time of --runs, each as many passes over the rays as
//     fill about 0.25 s; kerf and Embree alternate, so a busy machine slows both alike; the
//     1-thread runs are also timed by the thread's CPU time);
//   - agreement: pixels hit by one library only, the largest relative depth difference,
//     whether the rays where they differ graze an edge, shadow rays on which they disagree,
//     and both libraries against a long-double brute-force reference on the disagreeing rays
//     and a sample of the others.
// Rays and vertices are float numbers (the PLY stores floats), so both trace the same rays
// against the same triangles; kerf computes in double, Embree in float.
//
// Build: cmake --build build/bench-reference --target kerf_embree_bench (bench/CMakeLists.txt)
// Run:   kerf_embree_bench [--size N] [--fan-size N] [--runs R] [--build-runs R] [--robust]
// MESH.ply...
#include "mesh/mesh_loader.h"
#include "mesh/triangle_bvh.h"

#include <embree3/rtcore.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <thread>
#include <vector>

using namespace kerf;

namespace {

struct Options {
    int size = 1024;      ///< N: N × N primary rays per mesh
    int fanSize = 128;    ///< N for meshes named fan (both are slow there: keep runs short)
    int runs = 5;         ///< ray timings: median of this many
    int buildRuns = 3;    ///< build timings: median of this many
    bool robust = false;  ///< RTC_SCENE_FLAG_ROBUST (watertight Embree), to explain mismatches
};

double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

Vec3 toFloat(const Vec3& p) { return Vec3(float(p.x), float(p.y), float(p.z)); }

[[noreturn]] void embreeFail(RTCDevice device, const char* what) {
    std::fprintf(stderr, "kerf_embree_bench: Embree: %s failed (error %d)\n", what,
                 int(rtcGetDeviceError(device)));
    std::exit(1);
}

// An Embree device configured for `threads` build threads.
class EmbreeDevice {
public:
    explicit EmbreeDevice(int threads) {
        const std::string config = "threads=" + std::to_string(threads);
        mDevice = rtcNewDevice(config.c_str());
        if (!mDevice) embreeFail(nullptr, "rtcNewDevice");
    }
    ~EmbreeDevice() { rtcReleaseDevice(mDevice); }
    EmbreeDevice(const EmbreeDevice&) = delete;
    EmbreeDevice& operator=(const EmbreeDevice&) = delete;
    RTCDevice get() const { return mDevice; }

private:
    RTCDevice mDevice = nullptr;
};

// An Embree scene over the mesh's triangles (float vertices shared, not copied).
class EmbreeScene {
public:
    EmbreeScene(const EmbreeDevice& device, const std::vector<float>& vertices,
                const std::vector<uint32_t>& indices, bool robust) {
        mScene = rtcNewScene(device.get());
        rtcSetSceneBuildQuality(mScene, RTC_BUILD_QUALITY_HIGH);
        if (robust) rtcSetSceneFlags(mScene, RTC_SCENE_FLAG_ROBUST);
        RTCGeometry g = rtcNewGeometry(device.get(), RTC_GEOMETRY_TYPE_TRIANGLE);
        rtcSetGeometryBuildQuality(g, RTC_BUILD_QUALITY_HIGH);
        // vertices holds one float more than 3 per vertex: Embree reads 16 bytes at a time.
        rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, vertices.data(),
                                   0, 3 * sizeof(float), vertices.size() / 3);
        rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, indices.data(), 0,
                                   3 * sizeof(uint32_t), indices.size() / 3);
        rtcCommitGeometry(g);
        rtcAttachGeometry(mScene, g);
        rtcReleaseGeometry(g);
        rtcCommitScene(mScene);
        if (rtcGetDeviceError(device.get()) != RTC_ERROR_NONE)
            embreeFail(device.get(), "the build");
    }
    ~EmbreeScene() { rtcReleaseScene(mScene); }
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;
    RTCScene scene() const { return mScene; }

private:
    RTCScene mScene = nullptr;
};

// A pinhole camera outside the mesh's bounding sphere, looking at its centre from `from`'s
// direction, with a square field of view just holding every vertex (so most rays meet the
// mesh). Rays are rounded to float.
std::vector<Ray> primaryRays(const TriangleMesh& mesh, const Bounds3& box, const Vec3& from,
                             int n) {
    const Vec3 centre = box.center();
    const double radius = 0.5 * glm::length(box.extent());
    const Vec3 eye = toFloat(centre + 2.5 * radius * glm::normalize(from));
    const Vec3 forward = glm::normalize(centre - eye);
    const Vec3 right0 = glm::normalize(glm::cross(forward, Vec3(0, 0, 1)));
    const Vec3 up0 = glm::cross(right0, forward);
    double halfTan = 0.0;
    for (const Vec3& p : mesh.positions) {
        const Vec3 q = p - eye;
        const double depth = glm::dot(q, forward);
        halfTan = std::max(
            {halfTan, std::fabs(glm::dot(q, right0)) / depth, std::fabs(glm::dot(q, up0)) / depth});
    }
    const Vec3 right = halfTan * right0, up = halfTan * up0;
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> jitter(0.0, 1.0);
    std::vector<Ray> rays;
    rays.reserve(size_t(n) * n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double u = 2.0 * (x + jitter(rng)) / n - 1.0;
            const double v = 1.0 - 2.0 * (y + jitter(rng)) / n;
            rays.push_back({eye, toFloat(forward + u * right + v * up)});
        }
    return rays;
}

// The machine's load (1-minute average), printed with the figures: other jobs slow both
// libraries, the 2-thread figures most.
std::string loadAverage() {
    std::FILE* f = std::fopen("/proc/loadavg", "r");
    double load = -1.0;
    if (f) {
        if (std::fscanf(f, "%lf", &load) != 1) load = -1.0;
        std::fclose(f);
    }
    char text[32];
    std::snprintf(text, sizeof text, load < 0 ? "unknown" : "%.2f", load);
    return text;
}

RTCRay embreeRay(const Ray& r, double tnear, double tfar) {
    RTCRay e{};
    e.org_x = float(r.origin.x), e.org_y = float(r.origin.y), e.org_z = float(r.origin.z);
    e.dir_x = float(r.dir.x), e.dir_y = float(r.dir.y), e.dir_z = float(r.dir.z);
    e.tnear = float(tnear), e.tfar = float(tfar);
    e.mask = ~0u;
    return e;
}

// The primary hits of both libraries: t (inf when the ray misses) and triangle.
struct Hits {
    std::vector<double> t;
    std::vector<uint32_t> triangle;
    explicit Hits(size_t n) : t(n, kInf), triangle(n, 0) {}
};

// This thread's CPU time: on a machine shared with other jobs it counts only the time the
// thread ran, not the time it waited for a core.
double threadSeconds() {
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

struct Timing {
    double wall;  ///< s
    double cpu;   ///< s of the tracing thread's CPU time (1 thread only)
};

// Runs body(thread, first, last) `passes` times over [0, count) on `threads` threads, chunks
// of 64 dealt in turn, and returns the time taken. Each thread keeps its own state.
using Body = std::function<void(int, size_t, size_t)>;
Timing timed(size_t count, int threads, int passes, const Body& body) {
    constexpr size_t kChunk = 64;
    auto worker = [&](int k) {
        for (int pass = 0; pass < passes; ++pass)
            for (size_t first = k * kChunk; first < count; first += threads * kChunk)
                body(k, first, std::min(count, first + kChunk));
    };
    const auto t0 = std::chrono::steady_clock::now();
    double cpu = 0.0;
    if (threads == 1) {
        const double c0 = threadSeconds();
        worker(0);
        cpu = threadSeconds() - c0;
    } else {
        std::vector<std::thread> pool;
        for (int k = 0; k < threads; ++k) pool.emplace_back(worker, k);
        for (auto& t : pool) t.join();
    }
    return {secondsSince(t0), cpu};
}

// One warm-up pass on one thread, which also chooses how many passes make a run last about
// 0.25 s (a run of a few milliseconds would mostly time the threads' start).
int passesFor(size_t count, const Body& body) {
    const double once = timed(count, 1, 1, body).wall;
    return int(std::clamp(std::ceil(0.25 / std::max(once, 1e-9)), 1.0, 1000.0));
}

// Median throughput in M rays/s of kerf ([0]) and Embree ([1]) on 1 and 2 threads ([1], [2];
// [0] is 1 thread by its CPU time), the two alternating run by run.
void throughput(size_t count, int runs, const Body& kerfBody, const Body& embreeBody,
                double out[2][3]) {
    const Body* bodies[2] = {&kerfBody, &embreeBody};
    int passes[2];
    for (int lib = 0; lib < 2; ++lib) passes[lib] = passesFor(count, *bodies[lib]);
    std::vector<double> times[2][3];
    for (int run = 0; run < runs; ++run)
        for (int threads = 1; threads <= 2; ++threads)
            for (int lib = 0; lib < 2; ++lib) {
                const Timing t = timed(count, threads, passes[lib], *bodies[lib]);
                times[lib][threads].push_back(t.wall);
                if (threads == 1) times[lib][0].push_back(t.cpu);
            }
    for (int lib = 0; lib < 2; ++lib)
        for (int threads = 0; threads <= 2; ++threads)
            out[lib][threads] = double(passes[lib]) * count / median(times[lib][threads]) * 1e-6;
}

// How near a hit lies to its triangle's nearest edge (as a line), relative to the size of
// the numbers involved: floats carry about 6e-8 of that, so a ray within a few hundred float
// roundings of an edge may pass on either side of it in one library and not the other.
double edgeGap(const TriangleMesh& mesh, uint32_t triangle, const Ray& ray, double t) {
    const auto& tri = mesh.triangles[triangle];
    const Vec3 p = ray.at(t);
    double gap = kInf, scale = std::max(glm::length(ray.origin), glm::length(p - ray.origin));
    for (int e = 0; e < 3; ++e) {
        const Vec3 a = mesh.positions[tri[e]], b = mesh.positions[tri[(e + 1) % 3]];
        gap = std::min(gap, glm::length(glm::cross(p - a, b - a)) / glm::length(b - a));
        scale = std::max(scale, glm::length(a));
    }
    return gap / scale;
}

// The reference: the nearest crossing of the ray with any triangle (edges included), by brute
// force in long double. Inputs are floats, so the differences to the origin are exact and the
// signed volumes carry 64 bits: far finer than either library's answer.
double bruteForce(const TriangleMesh& mesh, const Ray& ray) {
    using L = long double;
    struct V {
        L x, y, z;
    };
    auto sub = [](const Vec3& p, const Vec3& o) {
        return V{L(p.x) - L(o.x), L(p.y) - L(o.y), L(p.z) - L(o.z)};
    };
    auto det = [](const V& a, const V& b, const V& c) {  // a · (b × c)
        return a.x * (b.y * c.z - b.z * c.y) + a.y * (b.z * c.x - b.x * c.z) +
               a.z * (b.x * c.y - b.y * c.x);
    };
    const V d{L(ray.dir.x), L(ray.dir.y), L(ray.dir.z)};
    L best = std::numeric_limits<L>::infinity();
    for (const auto& tri : mesh.triangles) {
        const V a = sub(mesh.positions[tri[0]], ray.origin),
                b = sub(mesh.positions[tri[1]], ray.origin),
                c = sub(mesh.positions[tri[2]], ray.origin);
        const L w0 = det(d, b, c), w1 = det(d, c, a), w2 = det(d, a, b);
        if ((w0 < 0 || w1 < 0 || w2 < 0) && (w0 > 0 || w1 > 0 || w2 > 0)) continue;
        const L w = w0 + w1 + w2;
        if (w == 0) continue;  // the ray lies in the triangle's plane
        const L t = det(a, b, c) / w;
        if (t > 0 && t < best) best = t;
    }
    return double(best);
}

struct Figures {
    double build[2][3];    ///< [kerf, Embree][threads] in s (index 1, 2)
    double primary[2][3];  ///< M rays/s; index 0: 1 thread by CPU time
    double shadow[2][3];   ///< M rays/s; index 0: 1 thread by CPU time
};

void runMesh(const std::string& path, const Options& opt) {
    const std::string name = path.substr(path.find_last_of('/') + 1, std::string::npos);
    const std::string stem = name.substr(0, name.find('.'));
    const TriangleMesh mesh = loadMesh(path);
    std::vector<float> vertices;
    for (const Vec3& p : mesh.positions)
        vertices.insert(vertices.end(), {float(p.x), float(p.y), float(p.z)});
    vertices.push_back(0.0f);
    std::vector<uint32_t> indices;
    for (const auto& t : mesh.triangles) indices.insert(indices.end(), t.begin(), t.end());

    Figures f{};
    // Builds: kerf and Embree alternate, 1 then 2 threads in each round.
    std::vector<double> builds[2][3];
    for (int run = 0; run < opt.buildRuns; ++run)
        for (int threads = 1; threads <= 2; ++threads) {
            tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
            const EmbreeDevice device(
                threads);  // made before the clock starts, as a renderer would
            auto t0 = std::chrono::steady_clock::now();
            {
                const TriangleBvh bvh(mesh);
                builds[0][threads].push_back(secondsSince(t0));
            }
            t0 = std::chrono::steady_clock::now();
            {
                const EmbreeScene scene(device, vertices, indices, opt.robust);
                builds[1][threads].push_back(secondsSince(t0));
            }
        }
    for (int lib = 0; lib < 2; ++lib)
        for (int threads = 1; threads <= 2; ++threads)
            f.build[lib][threads] = median(builds[lib][threads]);

    const TriangleBvh bvh(mesh);
    const EmbreeDevice device(2);
    const EmbreeScene embree(device, vertices, indices, opt.robust);
    const Bounds3 box = bvh.bounds();
    // The view and the light: from the front, a little to the side and above.
    const Vec3 view = stem == "city"  ? Vec3(-0.6, -0.7, 0.4)
                      : stem == "fan" ? Vec3(0.2, -0.5, 1.0)
                                      : Vec3(0.3, -1.6, 1.0);
    const int n = stem == "fan" ? opt.fanSize : opt.size;
    const std::vector<Ray> rays = primaryRays(mesh, box, view, n);
    const double radius = 0.5 * glm::length(box.extent());
    const Vec3 light = toFloat(box.center() + 3.0 * radius * glm::normalize(Vec3(0.5, -0.3, 1.0)));

    Hits kh(rays.size()), eh(rays.size());
    struct alignas(64) ThreadStats : BvhStats {
        uint64_t rays = 0;
    };  // a cache line each
    std::vector<ThreadStats> stats(2);
    auto kerfPrimary = [&](int k, size_t a, size_t b) {
        stats[k].rays += b - a;
        for (size_t i = a; i < b; ++i) {
            TriangleHit h;
            if (bvh.closestHit(rays[i], 0.0, kInf, h, stats[k]))
                kh.t[i] = h.t, kh.triangle[i] = h.triangle;
        }
    };
    auto embreePrimary = [&](int, size_t a, size_t b) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        for (size_t i = a; i < b; ++i) {
            RTCRayHit rh{};
            rh.ray = embreeRay(rays[i], 0.0, kInf);
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(embree.scene(), &context, &rh);
            if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID)
                eh.t[i] = rh.ray.tfar, eh.triangle[i] = rh.hit.primID;
        }
    };
    throughput(rays.size(), opt.runs, kerfPrimary, embreePrimary, f.primary);
    const double kerfNodes = double(stats[0].nodesVisited + stats[1].nodesVisited) /
                             double(std::max<uint64_t>(1, stats[0].rays + stats[1].rays));

    // Shadow rays from kerf's hits (rounded to float) toward the light, t in (1e-4, 1): the
    // start skips the surface it leaves by a fraction of the segment, not a scene distance.
    std::vector<Ray> shadowRays;
    for (size_t i = 0; i < rays.size(); ++i)
        if (kh.t[i] < kInf) {
            const Vec3 p = toFloat(rays[i].at(kh.t[i]));
            shadowRays.push_back({p, toFloat(light - p)});
        }
    constexpr double kShadowStart = 1e-4;
    std::vector<char> kerfOccluded(shadowRays.size()), embreeOccluded(shadowRays.size());
    auto kerfShadow = [&](int k, size_t a, size_t b) {
        stats[k].rays += b - a;
        for (size_t i = a; i < b; ++i)
            kerfOccluded[i] = bvh.anyHit(shadowRays[i], kShadowStart, 1.0, stats[k]);
    };
    auto embreeShadow = [&](int, size_t a, size_t b) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        for (size_t i = a; i < b; ++i) {
            RTCRay r = embreeRay(shadowRays[i], kShadowStart, 1.0);
            rtcOccluded1(embree.scene(), &context, &r);
            embreeOccluded[i] = r.tfar < 0.0f;  // Embree marks an occluded ray with tfar = -inf
        }
    };
    for (ThreadStats& s : stats) s = ThreadStats();
    throughput(shadowRays.size(), opt.runs, kerfShadow, embreeShadow, f.shadow);
    const double kerfShadowNodes = double(stats[0].nodesVisited + stats[1].nodesVisited) /
                                   double(std::max<uint64_t>(1, stats[0].rays + stats[1].rays));

    // Agreement on the primary rays. A ray grazes an edge when either library's hit lies
    // within 1e-5 of its triangle's edge relative to the coordinates (about 170 float roundings).
    constexpr double kGrazing = 1e-5;
    size_t kerfHits = 0, onlyKerf = 0, onlyEmbree = 0, otherTriangle = 0, deeper = 0;
    size_t notGrazing = 0;  // disagreements (hit or depth) that are not at an edge
    double maxRel = 0.0, maxRelInside = 0.0;  // the latter over rays grazing no edge
    for (size_t i = 0; i < rays.size(); ++i) {
        const bool k = kh.t[i] < kInf, e = eh.t[i] < kInf;
        const double edge = std::min(k ? edgeGap(mesh, kh.triangle[i], rays[i], kh.t[i]) : kInf,
                                     e ? edgeGap(mesh, eh.triangle[i], rays[i], eh.t[i]) : kInf);
        kerfHits += k;
        if (k != e) {
            (k ? onlyKerf : onlyEmbree)++;
            notGrazing += edge > kGrazing;
        } else if (k) {
            otherTriangle += kh.triangle[i] != eh.triangle[i];
            const double rel = std::fabs(kh.t[i] - eh.t[i]) / kh.t[i];
            maxRel = std::max(maxRel, rel);
            if (edge > kGrazing) maxRelInside = std::max(maxRelInside, rel);
            deeper += rel > 1e-5;
            notGrazing += rel > 1e-5 && edge > kGrazing;
        }
    }
    // Against the reference: every disagreeing ray (hit or depth over 1e-5) and a spread sample
    // of the others, as many as 4e7 triangle tests allow (at least 20).
    const size_t budget = std::max<size_t>(20, size_t(4e7) / mesh.triangles.size());
    std::vector<size_t> checked;
    for (size_t i = 0; i < rays.size() && checked.size() < budget / 2; ++i) {
        const bool k = kh.t[i] < kInf, e = eh.t[i] < kInf;
        if (k != e || (k && std::fabs(kh.t[i] - eh.t[i]) > 1e-5 * kh.t[i])) checked.push_back(i);
    }
    const size_t disagreeing = checked.size();
    for (size_t s = 0; checked.size() < budget && s < budget; ++s)
        checked.push_back(s * rays.size() / budget);
    std::sort(checked.begin(), checked.end());  // a disagreeing ray may also be in the sample
    checked.erase(std::unique(checked.begin(), checked.end()), checked.end());
    size_t wrongHit[2] = {0, 0};
    double worstDepth[2] = {0.0, 0.0};
    for (size_t i : checked) {
        const double ref = bruteForce(mesh, rays[i]);
        const double t[2] = {kh.t[i], eh.t[i]};
        for (int lib = 0; lib < 2; ++lib) {
            if ((t[lib] < kInf) != (ref < kInf))
                ++wrongHit[lib];
            else if (ref < kInf)
                worstDepth[lib] = std::max(worstDepth[lib], std::fabs(t[lib] - ref) / ref);
        }
    }

    size_t shadowDiffer = 0, occluded = 0;
    for (size_t i = 0; i < shadowRays.size(); ++i) {
        shadowDiffer += kerfOccluded[i] != embreeOccluded[i];
        occluded += kerfOccluded[i];
    }

    std::printf(
        "## %s: %zu triangles; %d x %d primary rays (%zu hit in kerf), %zu shadow rays "
        "(%zu occluded in kerf); kerf visits %.1f nodes per primary ray, %.1f per shadow ray; "
        "load average %s\n",
        stem.c_str(), mesh.triangles.size(), n, n, kerfHits, shadowRays.size(), occluded, kerfNodes,
        kerfShadowNodes, loadAverage().c_str());
    std::printf("| %-6s | threads | kerf | Embree | kerf/Embree |\n|---|---|---|---|---|\n",
                stem.c_str());
    for (int threads = 1; threads <= 2; ++threads)
        std::printf("| build (s) | %d | %.3f | %.3f | %.2f |\n", threads, f.build[0][threads],
                    f.build[1][threads], f.build[0][threads] / f.build[1][threads]);
    const char* threadsLabel[3] = {"1 (CPU time)", "1", "2"};
    for (int threads : {1, 2, 0})
        std::printf("| primary (M rays/s) | %s | %.3g | %.3g | %.2f |\n", threadsLabel[threads],
                    f.primary[0][threads], f.primary[1][threads],
                    f.primary[0][threads] / f.primary[1][threads]);
    for (int threads : {1, 2, 0})
        std::printf("| shadow (M rays/s) | %s | %.3g | %.3g | %.2f |\n", threadsLabel[threads],
                    f.shadow[0][threads], f.shadow[1][threads],
                    f.shadow[0][threads] / f.shadow[1][threads]);
    std::printf(
        "agreement: %zu pixels hit by kerf only, %zu by Embree only; %zu pixels on "
        "another triangle; depth: max relative difference %.3g (%.3g on rays grazing no edge), "
        "%zu pixels over 1e-5; disagreements not grazing an edge: %zu; shadow rays "
        "disagreeing: %zu\n",
        onlyKerf, onlyEmbree, otherTriangle, maxRel, maxRelInside, deeper, notGrazing,
        shadowDiffer);
    std::printf(
        "reference (long double, every triangle) on %zu rays (%zu disagreeing, the rest "
        "spread): kerf misjudges hit or miss on %zu, Embree on %zu; max relative depth "
        "error kerf %.3g, Embree %.3g\n\n",
        checked.size(), disagreeing, wrongHit[0], wrongHit[1], worstDepth[0], worstDepth[1]);
    std::fflush(stdout);
}

int usage() {
    std::fprintf(stderr,
                 "usage: kerf_embree_bench [--size N] [--fan-size N] [--runs R] "
                 "[--build-runs R] [--robust] MESH.ply...\n");
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    Options opt;
    std::vector<std::string> files;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto number = [&](int& out, int lo, int hi) {
            if (i + 1 >= argc) return false;
            char* end = nullptr;
            const long v = std::strtol(argv[++i], &end, 10);
            if (*end || v < lo || v > hi) {
                std::fprintf(stderr,
                             "kerf_embree_bench: %s must be a whole number %d..%d, not '%s'\n",
                             a.c_str(), lo, hi, argv[i]);
                std::exit(2);
            }
            out = int(v);
            return true;
        };
        if (a == "--size") {
            if (!number(opt.size, 1, 8192)) return usage();
        } else if (a == "--fan-size") {
            if (!number(opt.fanSize, 1, 8192)) return usage();
        } else if (a == "--runs") {
            if (!number(opt.runs, 1, 99)) return usage();
        } else if (a == "--build-runs") {
            if (!number(opt.buildRuns, 1, 99)) return usage();
        } else if (a == "--robust")
            opt.robust = true;
        else if (!a.empty() && a[0] == '-')
            return usage();
        else
            files.push_back(a);
    }
    if (files.empty()) return usage();
    std::printf(
        "kerf_embree_bench: Embree %s, %s scenes; medians of %d build runs and %d ray "
        "runs; %u hardware threads\n\n",
        RTC_VERSION_STRING, opt.robust ? "robust" : "default", opt.buildRuns, opt.runs,
        std::thread::hardware_concurrency());
    try {
        for (const std::string& file : files) runMesh(file, opt);
    } catch (const MeshError& e) {
        std::fprintf(stderr, "kerf_embree_bench: %s\n", e.what());
        return 2;
    }
    return 0;
}
