/// @file bench/depth_reference.cpp
/// @brief The depth oracle of the benchmark: traces the pixel-centre camera rays of a `.ref`
/// scene (written by bench/gen_scenes.py beside the .kerf) in long double with closed forms and
/// its own CSG, and compares kerf's `--aov depth=` EXR with it pixel by pixel.
///
///     depth_reference SCENE.ref --width W --height H [--compare KERF.exr] [--write REF.exr]
///                     [--threads N] [--list DISAGREE.txt] [--tolerance E]
///     depth_reference --self-test
///
/// Prints one JSON object about the pixels both hit: the relative error |kerf - ref| / ref
/// (max, mean, 99th percentile, the worst pixel), how many exceed 1e-6, how many exceed kerf's
/// relative tolerance E (a different surface: a missed object, an edge, a silhouette), and how
/// many of kerf's floats equal the correctly rounded float of the reference; then the hit/miss
/// disagreements. Disagreements where the reference's nearest span is thinner than E times its
/// distance are counted apart ("thin"): kerf drops such spans by design. --list writes every
/// disagreeing pixel as "i j reference kerf thickness-of-the-reference-span".
#include "reference/ref_scene.h"
#include "reference/ref_spans.h"
#include "reference/self_test.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace kerf::bench;

constexpr Real kPi = 3.141592653589793238462643383279502884L;

struct Options {
    std::string scene, compare, write, list;
    int width = 800, height = 600, threads = 0;
    double tolerance = 1e-6;
};

Options parseArguments(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw std::runtime_error(arg + " needs a value");
            return argv[++i];
        };
        if (arg == "--width")
            o.width = std::stoi(value());
        else if (arg == "--height")
            o.height = std::stoi(value());
        else if (arg == "--threads")
            o.threads = std::stoi(value());
        else if (arg == "--compare")
            o.compare = value();
        else if (arg == "--write")
            o.write = value();
        else if (arg == "--list")
            o.list = value();
        else if (arg == "--tolerance")
            o.tolerance = std::stod(value());
        else if (!arg.empty() && arg[0] != '-' && o.scene.empty())
            o.scene = arg;
        else
            throw std::runtime_error("unknown argument " + arg);
    }
    if (o.scene.empty())
        throw std::runtime_error(
            "usage: depth_reference SCENE.ref --width W "
            "--height H [--compare KERF.exr] [--write REF.exr]");
    if (o.width < 1 || o.height < 1) throw std::runtime_error("bad image size");
    return o;
}

/// Per pixel: the distance to the nearest hit and the thickness of the span it enters.
struct RefImage {
    std::vector<Real> depth, thickness;
};

/// The pinhole camera, in long double: d = normalize(f + sx tan(fov/2) (W/H) r +
/// sy tan(fov/2) u) through the pixel centre.
RefImage traceDepths(const RefScene& scene, int width, int height, int threads) {
    const RefCamera& cam = scene.camera;
    const V3 f = normalize(cam.lookAt - cam.eye);
    const V3 r = normalize(cross(f, cam.up));
    const V3 u = cross(r, f);
    const Real tanHalf = std::tan(cam.fovDegrees * (kPi / 180) / 2);
    const Real aspect = Real(width) / Real(height);
    RefImage image;
    image.depth.resize(size_t(width) * height);
    image.thickness.resize(size_t(width) * height);
    auto rows = [&](int first, int step) {
        for (int j = first; j < height; j += step) {
            const Real sy = 1 - (j + 0.5L) / height * 2;
            for (int i = 0; i < width; ++i) {
                const Real sx = (i + 0.5L) / width * 2 - 1;
                const V3 d = normalize(f + (sx * tanHalf * aspect) * r + (sy * tanHalf) * u);
                const auto hit = nearestHit(scene.objects, cam.eye, d);
                image.depth[size_t(j) * width + i] = hit.first;
                image.thickness[size_t(j) * width + i] = hit.second - hit.first;
            }
        }
    };
    const int n = threads > 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::thread> pool;
    for (int t = 0; t < n; ++t) pool.emplace_back(rows, t, n);
    for (std::thread& t : pool) t.join();
    return image;
}

std::vector<float> readDepthExr(const std::string& path, int width, int height) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw std::runtime_error(path + ": " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width != width || spec.height != height)
        throw std::runtime_error(path + ": size " + std::to_string(spec.width) + "x" +
                                 std::to_string(spec.height) + " differs from the reference");
    std::vector<float> all(size_t(width) * height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data()))
        throw std::runtime_error(path + ": " + in->geterror());
    std::vector<float> depth(size_t(width) * height);
    for (size_t k = 0; k < depth.size(); ++k) depth[k] = all[k * spec.nchannels];
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

/// Pixels where kerf and the reference disagree beyond 1e-6 or on hit/miss, one per line.
void listDisagreements(const std::string& path, const RefImage& image,
                       const std::vector<float>& kerf, int width) {
    const std::vector<Real>& ref = image.depth;
    std::unique_ptr<FILE, int (*)(FILE*)> out(std::fopen(path.c_str(), "w"), &std::fclose);
    if (!out) throw std::runtime_error(path + ": cannot write");
    for (size_t k = 0; k < ref.size(); ++k) {
        const bool refHit = std::isfinite(ref[k]), kerfHit = std::isfinite(kerf[k]);
        const bool differ =
            refHit != kerfHit || (refHit && std::fabs(Real(kerf[k]) - ref[k]) > 1e-6L * ref[k]);
        if (differ)
            std::fprintf(out.get(), "%ld %ld %.12Lg %.12g %.3Lg\n", long(k % width),
                         long(k / width), ref[k], double(kerf[k]), image.thickness[k]);
    }
}

void printComparison(const RefImage& image, const std::vector<float>& kerf, int width, int height,
                     double tolerance, double seconds) {
    const std::vector<Real>& ref = image.depth;
    long refOnly = 0, kerfOnly = 0, both = 0, missBoth = 0, offSurface = 0, floatExact = 0;
    long beyondTolerance = 0, thin = 0;
    std::vector<double> errors;
    double sum = 0, worst = 0;
    long worstPixel = -1;
    for (size_t k = 0; k < ref.size(); ++k) {
        const bool refHit = std::isfinite(ref[k]), kerfHit = std::isfinite(kerf[k]);
        if (!refHit && !kerfHit) {
            ++missBoth;
            continue;
        }
        const bool refThin = refHit && image.thickness[k] <= Real(tolerance) * ref[k];
        if (refHit != kerfHit) {
            if (refThin)
                ++thin;
            else
                (refHit ? refOnly : kerfOnly)++;
            continue;
        }
        ++both;
        const double e = double(std::fabs(Real(kerf[k]) - ref[k]) / ref[k]);
        errors.push_back(e);
        sum += e;
        if (e > worst) worst = e, worstPixel = long(k);
        if (e > 1e-6) ++offSurface;
        if (e > tolerance) (refThin ? thin : beyondTolerance)++;
        if (kerf[k] == float(ref[k])) ++floatExact;
    }
    double p99 = 0;
    if (!errors.empty()) {
        const size_t at = std::min(errors.size() - 1, size_t(0.99 * double(errors.size())));
        std::nth_element(errors.begin(), errors.begin() + long(at), errors.end());
        p99 = errors[at];
    }
    std::printf(
        "{\"pixels\": %ld, \"both_hit\": %ld, \"both_miss\": %ld, "
        "\"ref_hit_kerf_miss\": %ld, \"kerf_hit_ref_miss\": %ld, "
        "\"rel_max\": %.3e, \"rel_mean\": %.3e, \"rel_p99\": %.3e, "
        "\"worst_pixel\": [%ld, %ld], \"over_1e-6\": %ld, \"tolerance\": %.3g, "
        "\"over_tolerance\": %ld, \"thin\": %ld, \"float_exact\": %ld, "
        "\"reference_seconds\": %.2f}\n",
        long(width) * height, both, missBoth, refOnly, kerfOnly, worst,
        both ? sum / double(both) : 0.0, p99, worstPixel < 0 ? -1 : worstPixel % width,
        worstPixel < 0 ? -1 : worstPixel / width, offSurface, tolerance, beyondTolerance, thin,
        floatExact, seconds);
}

}  // namespace

int main(int argc, char** argv) {
    try {
        if (argc == 2 && std::string(argv[1]) == "--self-test") {
            const int failures = runSelfTest();
            std::printf("depth_reference self-test: %s\n", failures ? "FAILED" : "passed");
            return failures ? 1 : 0;
        }
        const Options o = parseArguments(argc, argv);
        const RefScene scene = readRefScene(o.scene);
        const auto start = std::chrono::steady_clock::now();
        const RefImage image = traceDepths(scene, o.width, o.height, o.threads);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (!o.write.empty()) writeDepthExr(o.write, image.depth, o.width, o.height);
        if (!o.compare.empty()) {
            const std::vector<float> kerf = readDepthExr(o.compare, o.width, o.height);
            if (!o.list.empty()) listDisagreements(o.list, image, kerf, o.width);
            printComparison(image, kerf, o.width, o.height, o.tolerance, seconds);
        } else {
            long hits = 0;
            for (Real v : image.depth) hits += std::isfinite(v) ? 1 : 0;
            std::printf("{\"pixels\": %ld, \"hits\": %ld, \"reference_seconds\": %.2f}\n",
                        long(o.width) * o.height, hits, seconds);
        }
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "depth_reference: error: %s\n", e.what());
        return 1;
    }
}
