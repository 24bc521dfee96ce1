/// @file bench/displace_reference.cpp
/// @brief The depth oracle of the displacement benchmark (bench/displace_bench.py): traces the
/// pixel-centre camera rays of a floor plus a sphere displaced by noise or turbulence in long
/// double and writes the nearest hit's distance as a depth EXR (inf = miss), for
/// `hit_mask depth` to compare kerf's `--aov depth=` with.
///
///     displace_reference --width W --height H --camera EX EY EZ LX LY LZ FOV
///         --sphere CX CY CZ R --pattern noise|turbulence --scale S --depth D
///         [--octaves N] [--seed K] [--threads N] --write REF.exr
///     displace_reference --self-test
///
/// The solid is what lang/lower_displace.cpp builds: {|p − c| − R − D·h(p − c) ≤ 0}, with
/// h(q) = noise(q/S, K) for noise and 2·Σₒ|noise(2ᵒq/S, K + o)|/2ᵒ / Σₒ2⁻ᵒ − 1 for turbulence.
/// The noise itself is kerf's long-double gradientNoise (csg/tape/noise.cpp, compiled in): the
/// oracle checks kerf's root finding on its own function, not the noise's definition.
///
/// Root finding is sound by a Lipschitz bound: |∂noise/∂xᵢ| ≤ kNoiseSlopeBound, so
/// |∇f| ≤ L = 1 + |D|·|∇h|max and no root lies within f(t)/L of t. Steps of f/L, at least
/// kMinStep·t; a sign change then bisects to long-double precision. A span thinner than the
/// minimum step may be stepped over: kerf drops spans thinner than its tolerance by design.
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "csg/tape/noise.h"

namespace {

using Real = long double;
using V3 = glm::tvec3<long double>;

constexpr Real kPi = 3.141592653589793238462643383279502884L;
/// The smallest step, relative to the distance: far below any tolerance kerf uses.
constexpr Real kMinStep = 1e-8L;
/// Steps a ray may take before it is given up (and counted): none did in the benchmark.
constexpr long kMaxSteps = 20000000;
std::atomic<long> gGivenUp{0};

struct Options {
    int width = 400, height = 300, threads = 0, octaves = 1;
    V3 eye{0, 0, -5}, lookAt{0, 0, 0}, center{0, 0, 0};
    Real fov = 40, radius = 1, scale = 1, depth = 0.1;
    uint64_t seed = 0;
    bool turbulence = false;
    std::string write;
};

Options parseArguments(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw std::runtime_error(arg + " needs a value");
            return argv[++i];
        };
        auto number = [&]() { return std::stold(value()); };
        if (arg == "--width")
            o.width = std::stoi(value());
        else if (arg == "--height")
            o.height = std::stoi(value());
        else if (arg == "--threads")
            o.threads = std::stoi(value());
        else if (arg == "--octaves")
            o.octaves = std::stoi(value());
        else if (arg == "--seed")
            o.seed = std::stoull(value());
        else if (arg == "--scale")
            o.scale = number();
        else if (arg == "--depth")
            o.depth = number();
        else if (arg == "--write")
            o.write = value();
        else if (arg == "--pattern") {
            const std::string p = value();
            if (p != "noise" && p != "turbulence") throw std::runtime_error("unknown pattern " + p);
            o.turbulence = p == "turbulence";
        } else if (arg == "--camera") {
            for (int k = 0; k < 3; ++k) o.eye[k] = number();
            for (int k = 0; k < 3; ++k) o.lookAt[k] = number();
            o.fov = number();
        } else if (arg == "--sphere") {
            for (int k = 0; k < 3; ++k) o.center[k] = number();
            o.radius = number();
        } else
            throw std::runtime_error("unknown argument " + arg);
    }
    if (o.write.empty()) throw std::runtime_error("--write REF.exr is required");
    if (o.width < 1 || o.height < 1 || o.octaves < 1 || !(o.scale > 0))
        throw std::runtime_error("bad size, octaves or scale");
    return o;
}

/// The displaced sphere's implicit function and its Lipschitz constant.
struct Displaced {
    Options o;
    Real norm = 1;

    explicit Displaced(const Options& options) : o(options) {
        norm = 0;
        for (int k = 0; k < o.octaves; ++k) norm += std::ldexp(1.0L, -k);
    }

    Real height(V3 q) const {
        q *= 1 / o.scale;
        if (!o.turbulence) return kerf::gradientNoise(q, o.seed);
        Real sum = 0;
        for (int k = 0; k < o.octaves; ++k)
            sum += std::fabs(kerf::gradientNoise(std::ldexp(1.0L, k) * q, o.seed + uint64_t(k))) *
                   std::ldexp(1.0L, -k);
        return 2 * sum / norm - 1;
    }

    Real f(V3 p) const {
        const V3 q = p - o.center;
        return std::sqrt(glm::dot(q, q)) - o.radius - o.depth * height(q);
    }

    /// 1 + |D|·(a bound on |∇h|): each octave's slope is the noise's times 2ᵒ/2ᵒ.
    Real lipschitz() const {
        const Real noiseSlope = Real(kerf::kNoiseSlopeBound) * std::sqrt(3.0L) / o.scale;
        const Real slope = o.turbulence ? 2 * o.octaves * noiseSlope / norm : noiseSlope;
        return 1 + std::fabs(o.depth) * slope;
    }
};

/// The first t in [t0, t1] where f ≤ 0 along eye + t·d, or inf.
Real firstRoot(const Displaced& s, V3 eye, V3 d, Real t0, Real t1) {
    const Real L = s.lipschitz();
    Real t = t0, v = s.f(eye + t * d);
    if (v <= 0) return t;
    for (long n = 0; t < t1; ++n) {
        if (n == kMaxSteps) {
            ++gGivenUp;
            break;
        }
        const Real step = std::max(v / L, kMinStep * t);
        Real next = std::min(t + step, t1), w = s.f(eye + next * d);
        if (w <= 0) {
            Real lo = t, hi = next;  // f(lo) > 0 ≥ f(hi)
            for (int k = 0; k < 200 && hi - lo > 4 * std::numeric_limits<Real>::epsilon() * hi;
                 ++k) {
                const Real mid = (lo + hi) / 2;
                (s.f(eye + mid * d) <= 0 ? hi : lo) = mid;
            }
            return hi;
        }
        if (next >= t1) break;
        t = next, v = w;
    }
    return INFINITY;
}

Real traceRay(const Displaced& s, V3 eye, V3 d) {
    Real best = INFINITY;
    if (d.y < 0 && eye.y > 0) best = -eye.y / d.y;  // the floor, y ≤ 0
    // The displaced surface lies within |D| of the sphere: search only where the ray is
    // inside the sphere of radius R + |D| (and a margin).
    const Real outer = s.o.radius + std::fabs(s.o.depth) * 1.01L;
    const V3 m = eye - s.o.center;
    const Real b = glm::dot(m, d), c = glm::dot(m, m) - outer * outer, disc = b * b - c;
    if (disc <= 0) return best;
    const Real root = std::sqrt(disc), t0 = std::max(Real(0), -b - root),
               t1 = std::min(best, -b + root);
    if (t0 < t1) best = std::min(best, firstRoot(s, eye, d, t0, t1));
    return best;
}

/// kerf's pinhole camera through pixel centres (as bench/depth_reference.cpp).
std::vector<Real> traceImage(const Options& o) {
    const Displaced solid(o);
    const V3 f = glm::normalize(o.lookAt - o.eye);
    const V3 r = glm::normalize(glm::cross(f, V3(0, 1, 0)));
    const V3 u = glm::cross(r, f);
    const Real tanHalf = std::tan(o.fov * (kPi / 180) / 2), aspect = Real(o.width) / o.height;
    std::vector<Real> depth(size_t(o.width) * o.height);
    auto rows = [&](int first, int step) {
        for (int j = first; j < o.height; j += step)
            for (int i = 0; i < o.width; ++i) {
                const Real sx = (i + 0.5L) / o.width * 2 - 1, sy = 1 - (j + 0.5L) / o.height * 2;
                const V3 d = glm::normalize(f + (sx * tanHalf * aspect) * r + (sy * tanHalf) * u);
                depth[size_t(j) * o.width + i] = traceRay(solid, o.eye, d);
            }
    };
    const int n =
        o.threads > 0 ? o.threads : int(std::max(1u, std::thread::hardware_concurrency()));
    std::vector<std::thread> pool;
    for (int t = 0; t < n; ++t) pool.emplace_back(rows, t, n);
    for (std::thread& t : pool) t.join();
    return depth;
}

void writeDepthExr(const std::string& path, const std::vector<Real>& depth, int width, int height) {
    std::vector<float> pixels(depth.begin(), depth.end());
    auto out = OIIO::ImageOutput::create(path);
    OIIO::ImageSpec spec(width, height, 1, OIIO::TypeDesc::FLOAT);
    spec.channelnames = {"Z"};
    if (!out || !out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()))
        throw std::runtime_error(path + ": cannot write");
    out->close();
}

/// Checks of the oracle's two assumptions: with D = 0 it finds the sphere's and the floor's
/// closed-form hits; and no sampled slope of f exceeds the Lipschitz bound it steps by.
int selfTest() {
    int failures = 0;
    auto expect = [&](bool ok, const char* what) {
        if (!ok)
            std::fprintf(stderr, "displace_reference self-test failed: %s\n", what), ++failures;
    };
    Options o;
    o.center = V3(0, 1, 0);
    o.depth = 0;
    const Displaced plain(o);
    const V3 eye(0.3L, 2.2L, -4.2L);
    for (int k = 0; k < 50; ++k) {
        const V3 d = glm::normalize(V3(-0.3L + 0.01L * k, -0.25L - 0.004L * k, 1));
        const V3 m = eye - o.center;
        const Real b = glm::dot(m, d), disc = b * b - (glm::dot(m, m) - 1);
        Real expected = disc > 0 ? -b - std::sqrt(disc) : Real(INFINITY);
        expected = std::min(expected, -eye.y / d.y);
        const Real got = traceRay(plain, eye, d);
        expect(std::fabs(got - expected) <= 1e-15L * expected, "closed-form sphere and floor");
    }
    // Slopes along random segments of 1e-6 in the shell the search covers.
    for (int turbulence = 0; turbulence < 2; ++turbulence) {
        Options t;
        t.turbulence = turbulence == 1;
        t.octaves = t.turbulence ? 4 : 1;
        t.scale = t.turbulence ? 0.5L : 0.3L;
        const Displaced s(t);
        Real worst = 0;
        uint64_t state = 12345;
        auto uniform = [&]() {  // a small LCG: deterministic, no library
            state = state * 6364136223846793005ULL + 1442695040888963407ULL;
            return Real(state >> 11) / Real(1ULL << 53) * 2 - 1;
        };
        for (int k = 0; k < 200000; ++k) {
            const V3 p(1.1L * uniform(), 1.1L * uniform(), 1.1L * uniform());
            const V3 step = 1e-6L * glm::normalize(V3(uniform(), uniform(), uniform()));
            worst = std::max(worst, std::fabs(s.f(p + step) - s.f(p)) / 1e-6L);
        }
        expect(worst <= s.lipschitz(), "a sampled slope above the Lipschitz bound");
        std::fprintf(stderr,
                     "displace_reference self-test: %s: largest sampled slope %.3Lg, "
                     "bound %.3Lg\n",
                     t.turbulence ? "turbulence" : "noise", worst, s.lipschitz());
    }
    if (failures == 0) std::fprintf(stderr, "displace_reference self-test: ok\n");
    return failures == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        if (argc == 2 && std::string(argv[1]) == "--self-test") return selfTest();
        const Options o = parseArguments(argc, argv);
        const std::vector<Real> depth = traceImage(o);
        writeDepthExr(o.write, depth, o.width, o.height);
        long hits = 0;
        for (Real v : depth) hits += std::isfinite(v) ? 1 : 0;
        std::printf("{\"pixels\": %ld, \"hits\": %ld, \"lipschitz\": %.4Lg, \"given_up\": %ld}\n",
                    long(o.width) * o.height, hits, Displaced(o).lipschitz(), gGivenUp.load());
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "displace_reference: error: %s\n", e.what());
        return 1;
    }
}
