// Reconstruction filters and adaptive sampling (issue 10 §1): the filters' weights, a
// straight edge filtered as the closed-form convolution says, images independent of the
// thread count, and adaptive sampling that stops where there is no noise.
#include "render/film.h"
#include "render/render.h"
#include "render/sampler.h"
#include "render_test_util.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace kerf;
using namespace kerf::test;

namespace {

/// ∫ from a to b of w, by Simpson's rule on 4000 intervals (w is piecewise cubic or smooth).
double integrate(const ReconstructionFilter& f, double a, double b) {
    const int n = 4000;
    const double h = (b - a) / n;
    double s = f.weight1D(a) + f.weight1D(b);
    for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * f.weight1D(a + i * h);
    return s * h / 3.0;
}

/// A camera at x = 0.3 looking along +z at the half-space x ≤ 0 (black) before a white sky:
/// the edge is the film's centre column, x = W/2, for every row.
Scene edgeScene() {
    Scene scene;
    const int32_t m = addMaterial(scene, blackMaterial());
    addObject(scene, makeHalfSpace(Vec3(1.0, 0.0, 0.0), 0.0), m);
    scene.background = Vec3(1.0);
    scene.camera.eye = Vec3(0.3, 0.0, 0.0);
    scene.camera.lookAt = Vec3(0.3, 0.0, 1.0);
    return scene;
}

}  // namespace

TEST_CASE("reconstruction filters: their weights") {
    const auto box = ReconstructionFilter::of(FilterKind::Box);
    const auto gauss = ReconstructionFilter::of(FilterKind::Gaussian);
    const auto mitchell = ReconstructionFilter::of(FilterKind::Mitchell);
    CHECK(box.weight1D(0.49) == 1.0);
    CHECK(box.weight1D(0.5) == 0.0);
    CHECK(gauss.weight1D(1.5) == 0.0);
    CHECK(gauss.weight1D(0.0) == Approx(1.0 - std::exp(-4.5)));
    // Mitchell–Netravali's kernel integrates to 1, is 8/9 at 0 (B = C = 1/3), and has
    // negative lobes between 1 and 2.
    CHECK(integrate(mitchell, -2.0, 2.0) == Approx(1.0).epsilon(1e-9));
    CHECK(mitchell.weight1D(0.0) == Approx(8.0 / 9.0));
    CHECK(mitchell.weight1D(1.5) < 0.0);
    CHECK(mitchell.weight1D(2.0) == 0.0);
}

TEST_CASE("a straight edge through each filter: the convolution of a step") {
    // With 1024 samples a pixel, pixel k (centre c = k + ½) next to the edge at film x = X is
    // ∫_{−r}^{X−c} w / ∫ w on the white side (the row direction integrates out).
    const Scene scene = edgeScene();
    const int width = 16, height = 4;
    for (FilterKind kind : {FilterKind::Box, FilterKind::Gaussian, FilterKind::Mitchell}) {
        RenderOptions options = smallImage(width, height, 2);
        options.spp = 1024;
        options.filter = kind;
        const RenderResult r = render(scene, options);
        const auto f = ReconstructionFilter::of(kind);
        const double total = integrate(f, -f.radius, f.radius);
        // Which side is white: the first column's.
        const bool whiteLeft = r.color.at(0, 1, 0) > 0.5;
        for (int k = 4; k < 12; ++k) {
            const double c = k + 0.5, edge = width / 2.0;
            const double leftPart =
                integrate(f, -f.radius, std::clamp(edge - c, -f.radius, f.radius)) / total;
            const double expected = whiteLeft ? leftPart : 1.0 - leftPart;
            INFO(filterName(kind) << " column " << k);
            CHECK(r.color.at(k, 1, 0) == Approx(expected).margin(0.01));
        }
    }
}

TEST_CASE("filtered images do not depend on the thread count") {
    Scene scene = edgeScene();
    scene.objects.push_back(makeSphere(Vec3(0.0, 0.0, 4.0), 1.0));
    for (FilterKind kind : {FilterKind::Gaussian, FilterKind::Mitchell}) {
        RenderOptions options = smallImage(40, 30, 1);
        options.spp = 3;
        options.filter = kind;
        const RenderResult one = render(scene, options);
        options.threads = 2;
        const RenderResult two = render(scene, options);
        CHECK(one.color.pixels == two.color.pixels);
    }
}

TEST_CASE("adaptive sampling: flat pixels stop at the minimum, edges sample more") {
    // 15 columns: the edge at film x = 7.5 halves column 7, whose samples are 0 or 1 (standard
    // error ½/√n > 0.01 up to 256 samples); the other 14 columns are flat and stop at 16.
    const Scene scene = edgeScene();
    RenderOptions options = smallImage(15, 4, 2);
    options.spp = 256;
    options.noise = 0.01;
    const RenderResult r = render(scene, options);
    CHECK(r.stats.samplesTaken == uint64_t(14 * 4 * kMinAdaptiveSamples + 4 * 256));
    CHECK(r.color.at(7, 1, 0) == Approx(0.5).margin(0.05));
    options.noise = 0.0;
    CHECK(render(scene, options).stats.samplesTaken == uint64_t(15 * 256 * 4));
    // A flat image takes exactly the minimum everywhere.
    Scene flat;
    flat.background = Vec3(0.3);
    options.noise = 0.01;
    CHECK(render(flat, options).stats.samplesTaken == uint64_t(15 * 4 * kMinAdaptiveSamples));
}

TEST_CASE("adaptive sampling takes its samples spread over the pixel") {
    // A horizontal edge across the middle of row 2 of 5: those pixels are half covered. With a
    // target no pixel misses, each stops after 16 of 256 samples; taken in index order they
    // would be the grid's top row (all sky), so the value would be 1 instead of about ½.
    Scene scene;
    const int32_t m = addMaterial(scene, blackMaterial());
    addObject(scene, makeHalfSpace(Vec3(0.0, 1.0, 0.0), 0.0), m);
    scene.background = Vec3(1.0);
    scene.camera.eye = Vec3(0.0, 0.3, 0.0);
    scene.camera.lookAt = Vec3(0.0, 0.3, 1.0);
    for (SamplerKind kind : {SamplerKind::Jittered, SamplerKind::Lattice, SamplerKind::Regular}) {
        RenderOptions options = smallImage(6, 5, 2);
        options.spp = 256;
        options.sampler = kind;
        options.noise = 10.0;
        const RenderResult r = render(scene, options);
        CHECK(r.stats.samplesTaken == uint64_t(6 * 5 * kMinAdaptiveSamples));
        for (int i = 0; i < 6; ++i) {
            INFO(samplerName(kind) << " column " << i);
            CHECK(r.color.at(i, 2, 0) == Approx(0.5).margin(0.15));
        }
    }
    // The order is a permutation of the samples, for any count.
    for (int n : {1, 5, 16, 100, 256}) {
        const PixelSampler sampler(n);
        std::vector<uint32_t> order = sampler.spreadOrder();
        std::sort(order.begin(), order.end());
        REQUIRE(order.size() == size_t(n));
        for (int i = 0; i < n; ++i) CHECK(order[size_t(i)] == uint32_t(i));
    }
}
