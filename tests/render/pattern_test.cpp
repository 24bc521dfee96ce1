// Solid textures (render/pattern_eval.h) against closed forms: the checker's parity, the box
// filter of the square wave against dense sampling, the noise's range and smoothness, nested
// patterns and the pattern's own transform; and a checker floor to the horizon that does not
// alias at one sample per pixel.
#include "render/pattern_eval.h"
#include "render/render.h"
#include "render_test_util.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace kerf;
using namespace kerf::test;

namespace {

std::shared_ptr<Pattern> twoTone(Pattern::Kind kind) {
    auto p = std::make_shared<Pattern>();
    p->kind = kind;
    p->a.color = Vec3(1.0, 0.0, 0.0);
    p->b.color = Vec3(0.0, 0.0, 1.0);
    return p;
}

}  // namespace

TEST_CASE("checker, stripes and rings at points: the parity of the cells") {
    const auto checker = twoTone(Pattern::Kind::Checker);
    const auto stripes = twoTone(Pattern::Kind::Stripes);
    const auto rings = twoTone(Pattern::Kind::Rings);
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> coord(-50.0, 50.0);
    for (int k = 0; k < 2000; ++k) {
        const Vec3 p(coord(rng), coord(rng), coord(rng));
        const int64_t sum =
            int64_t(std::floor(p.x)) + int64_t(std::floor(p.y)) + int64_t(std::floor(p.z));
        CHECK(patternColor(*checker, p, 0.0).x == ((sum & 1) == 0 ? 1.0 : 0.0));
        CHECK(patternColor(*stripes, p, 0.0).x ==
              ((int64_t(std::floor(p.x)) & 1) == 0 ? 1.0 : 0.0));
        const double r = std::sqrt(p.x * p.x + p.z * p.z);
        CHECK(patternColor(*rings, p, 0.0).x == ((int64_t(std::floor(r)) & 1) == 0 ? 1.0 : 0.0));
    }
    // A hit on the floor y = 0 computed a rounding error below it is on the upper side, so the
    // floor's cells do not flicker; with no error bound it is where it was computed.
    const Vec3 below(0.5, -1e-17, 0.5);
    CHECK(patternColor(*checker, below, 1e-16).x == 1.0);
    CHECK(patternColor(*checker, below, 0.0).x == 0.0);
}

TEST_CASE("the filtered square wave is the mean of the wave over the box") {
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int k = 0; k < 300; ++k) {
        const double x = 20.0 * unit(rng) - 10.0, w = 3.0 * unit(rng) * unit(rng);
        const int n = 200000;
        double sum = 0.0;
        for (int i = 0; i < n; ++i) {
            const double u = x - 0.5 * w + w * (i + 0.5) / n;
            sum += (int64_t(std::floor(u)) & 1) == 0 ? 1.0 : -1.0;
        }
        INFO("x " << x << " w " << w);
        CHECK(filteredSquareWave(x, w) == Approx(sum / n).margin(2e-5));
    }
    // Whole periods average to 0; a point is the wave's value.
    CHECK(filteredSquareWave(0.3, 2.0) == Approx(0.0).margin(1e-15));
    CHECK(filteredSquareWave(0.3, 0.0) == 1.0);
    CHECK(filteredSquareWave(1.3, 0.0) == -1.0);
}

TEST_CASE("a checker filtered over a footprint on the floor: exact cells near, grey far") {
    const auto checker = twoTone(Pattern::Kind::Checker);
    // A footprint inside one cell leaves the cell's colour; one spanning many cells averages
    // to the mean (the floor's normal axis, y, is not filtered).
    const Footprint small{Vec3(0.1, 0.0, 0.0), Vec3(0.0, 0.0, 0.1)};
    CHECK(patternColor(*checker, Vec3(0.5, 0.0, 0.5), 1e-16, small) == Vec3(1.0, 0.0, 0.0));
    CHECK(patternColor(*checker, Vec3(1.5, 0.0, 0.5), 1e-16, small) == Vec3(0.0, 0.0, 1.0));
    const Footprint wide{Vec3(40.0, 0.0, 0.0), Vec3(0.0, 0.0, 40.0)};
    const Vec3 grey = patternColor(*checker, Vec3(0.3, 0.0, 0.7), 1e-16, wide);
    CHECK(grey.x == Approx(0.5).margin(1e-12));
    CHECK(grey.z == Approx(0.5).margin(1e-12));
}

TEST_CASE("gradient noise: zero on the lattice, within [-1, 1], smooth, seeded") {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> coord(-100.0, 100.0);
    double lo = 1.0, hi = -1.0;
    for (int k = 0; k < 20000; ++k) {
        const Vec3 p(coord(rng), coord(rng), coord(rng));
        const double n = gradientNoise(p, 7);
        lo = std::min(lo, n), hi = std::max(hi, n);
        // Lipschitz: each corner term has gradient at most √2 + its fade's, so a bound of 10
        // per unit is generous; a jump would break it.
        const Vec3 q = p + Vec3(1e-4, -1e-4, 1e-4);
        REQUIRE(std::fabs(gradientNoise(q, 7) - n) <= 10.0 * glm::length(q - p));
    }
    CHECK(lo >= -1.0);
    CHECK(hi <= 1.0);
    CHECK(hi - lo > 1.0);  // it does vary
    for (int k = 0; k < 100; ++k) {
        const Vec3 lattice(std::floor(coord(rng)), std::floor(coord(rng)), std::floor(coord(rng)));
        CHECK(gradientNoise(lattice, 7) == 0.0);
    }
    CHECK(gradientNoise(Vec3(0.3, 0.4, 0.5), 7) != gradientNoise(Vec3(0.3, 0.4, 0.5), 8));
    CHECK(gradientNoise(Vec3(0.3, 0.4, 0.5), 7) == gradientNoise(Vec3(0.3, 0.4, 0.5), 7));
}

TEST_CASE("nested patterns and the pattern's own transform") {
    auto inner = twoTone(Pattern::Kind::Stripes);
    inner->a.color = Vec3(0.0, 1.0, 0.0);
    auto outer = twoTone(Pattern::Kind::Checker);
    outer->b.pattern = inner;
    // Scaled by 0.5: cells half a unit wide. (0.25, 0.25, 0.25) is in cell (0,0,0) → a;
    // (0.75, 0.25, 0.25) in cell (1,0,0) → b, the stripes at x = 0.75 (cell 0 → green).
    outer->toPattern = Affine::scale(Vec3(0.5)).inverse();
    CHECK(patternColor(*outer, Vec3(0.25), 0.0) == Vec3(1.0, 0.0, 0.0));
    CHECK(patternColor(*outer, Vec3(0.75, 0.25, 0.25), 0.0) == Vec3(0.0, 1.0, 0.0));
    CHECK(patternColor(*outer, Vec3(1.25, 0.25, 0.75), 0.0) == Vec3(0.0, 0.0, 1.0));
    auto turbulence = twoTone(Pattern::Kind::Turbulence);
    for (double x = -3.0; x < 3.0; x += 0.37) {
        const Vec3 c = patternColor(*turbulence, Vec3(x, 0.2 * x, 1.0), 0.0);
        CHECK(c.x >= 0.0);
        CHECK(c.x <= 1.0);
        CHECK(c.x + c.z == Approx(1.0));
    }
}

TEST_CASE("a checker floor to the horizon does not alias at one sample per pixel") {
    // High-frequency energy (mean squared difference of horizontal neighbours) in the far
    // band of a 1-sample render must be close to that of a 256-sample reference, and the band
    // must be the reference's grey within 0.05 on average; point sampling gives noise there.
    Scene scene;
    Material floor = blackMaterial();
    floor.ambient = 1.0;
    auto checker = std::make_shared<Pattern>();
    checker->a.color = Vec3(1.0);
    checker->b.color = Vec3(0.0);
    floor.pattern = checker;
    const int32_t m = addMaterial(scene, floor);
    addObject(scene, makeHalfSpace(Vec3(0.0, 1.0, 0.0), 0.0), m);
    scene.camera.eye = Vec3(0.0, 2.0, 0.0);
    scene.camera.lookAt = Vec3(0.3, 1.6, 10.0);
    scene.camera.fovDegrees = 50.0;
    RenderOptions options = smallImage(96, 72, 2);
    const RenderResult one = render(scene, options);
    options.spp = 256;
    const RenderResult reference = render(scene, options);
    const Camera camera(scene.camera, 96, 72);
    double energyOne = 0, energyRef = 0, diff = 0;
    int n = 0;
    for (int j = 0; j < 72; ++j) {
        const Ray r = camera.rayThrough(48.0, j + 0.5);
        if (!(r.dir.y < 0.0)) continue;
        const double distance = -r.origin.y / r.dir.y;
        if (distance < 40.0) continue;  // the far band: cells smaller than a pixel
        for (int i = 0; i + 1 < 96; ++i) {
            energyOne += std::pow(one.color.at(i + 1, j, 0) - one.color.at(i, j, 0), 2);
            energyRef += std::pow(reference.color.at(i + 1, j, 0) - reference.color.at(i, j, 0), 2);
            diff += std::fabs(one.color.at(i, j, 0) - reference.color.at(i, j, 0));
            ++n;
        }
    }
    REQUIRE(n > 200);
    INFO("energy 1 spp " << energyOne / n << ", reference " << energyRef / n << ", mean |diff| "
                         << diff / n);
    CHECK(energyOne / n <= 2.0 * energyRef / n + 1e-3);
    CHECK(diff / n < 0.05);
}

TEST_CASE("bump maps tilt the normal against the height's gradient along the surface") {
    // h = frac(x / s) (a gradient pattern scaled by s) has gradient (1/s, 0, 0) away from its
    // jumps; on a floor (n = +y) the bumped normal is normalize(−depth/s, 1, 0).
    auto ramp = std::make_shared<Pattern>();
    ramp->kind = Pattern::Kind::Gradient;
    const double s = 4.0, depth = 0.7;
    ramp->toPattern = Affine::scale(Vec3(s)).inverse();
    const Vec3 n(0.0, 1.0, 0.0);
    for (double x : {0.5, 1.3, 2.9, -1.7}) {
        const Vec3 b = bumpedNormal(*ramp, depth, Vec3(x, 0.0, 0.2), n, 0.0);
        const Vec3 expect = glm::normalize(Vec3(-depth / s, 1.0, 0.0));
        INFO("x " << x);
        CHECK(b.x == Approx(expect.x).epsilon(1e-6));
        CHECK(b.y == Approx(expect.y).epsilon(1e-6));
        CHECK(b.z == Approx(0.0).margin(1e-9));
    }
    // The gradient's part along the normal does not tilt it: a ramp along y on the floor.
    ramp->toPattern = Affine::rotateDegrees(Vec3(0.0, 0.0, 90.0)).inverse();
    const Vec3 same = bumpedNormal(*ramp, depth, Vec3(0.3, 0.2, 0.1), n, 0.0);
    CHECK(same.y == Approx(1.0).epsilon(1e-9));
    // Depth 0: the normal itself.
    CHECK(bumpedNormal(*ramp, 0.0, Vec3(0.3), n, 0.0) == n);
}

TEST_CASE("a bumped floor under a directional light shades with the tilted normal") {
    Scene scene;
    Material floor = blackMaterial();
    floor.diffuse = 1.0;
    auto ramp = std::make_shared<Pattern>();
    ramp->kind = Pattern::Kind::Gradient;
    ramp->toPattern = Affine::scale(Vec3(8.0)).inverse();  // h = frac(x/8): slope 1/8
    floor.bump = ramp;
    floor.bumpDepth = 2.0;  // tilt: normalize(−0.25, 1, 0)
    const int32_t m = addMaterial(scene, floor);
    addObject(scene, makeHalfSpace(Vec3(0.0, 1.0, 0.0), 0.0), m);
    Light sun;
    sun.kind = Light::Kind::Directional;
    sun.direction = Vec3(0.0, -1.0, 0.0);
    scene.lights.push_back(sun);
    scene.camera.eye = Vec3(3.0, 5.0, 0.01);
    scene.camera.lookAt = Vec3(3.0, 0.0, 0.0);
    const RenderResult r = render(scene, smallImage(9, 9, 1));
    // The centre pixel sees x ≈ 3 (inside one ramp): cos = 1/√(1 + 1/16).
    CHECK(r.color.at(4, 4, 0) == Approx(1.0 / std::sqrt(1.0 + 1.0 / 16.0)).epsilon(1e-6));
}
