/// @file tests/render/shading_test.cpp
/// @brief The Whitted integrator against closed forms: Lambert shading, shadows (opaque and
/// tinted), Fresnel and Beer through a slab, total internal reflection, facing mirrors, mist.
#include "render/camera.h"
#include "render_test_util.h"

#include <catch2/catch.hpp>

#include <glm/gtc/constants.hpp>

using namespace kerf;
using namespace kerf::test;

namespace {

/// A ground plane y ≤ 0 with a ball between it and a point light straight above.
struct ShadowScene {
    Scene scene;
    Vec3 ballCenter{0.2, 1.0, 0.3};
    double ballRadius = 0.5;
    Vec3 lightPos{0.0, 3.0, 0.0};
    double power = 40.0;
    Material ground;

    explicit ShadowScene(const Material& ball, bool extraGlassMaterial = false) {
        ground = blackMaterial();
        ground.diffuse = 0.7;
        ground.color = Vec3(0.9, 0.8, 0.7);
        scene.camera.eye = Vec3(0.0, 5.0, -4.0);
        scene.camera.lookAt = Vec3(0.0, 0.0, 0.5);
        scene.camera.fovDegrees = 45;
        addObject(scene, makeHalfSpace(Vec3(0, 1, 0), 0.0), addMaterial(scene, ground));
        addObject(scene, makeSphere(ballCenter, ballRadius), addMaterial(scene, ball));
        if (extraGlassMaterial) {  // unused: forces shadow rays through the span path
            Material glass = blackMaterial();
            glass.transmit = 1;
            addMaterial(scene, glass);
        }
        Light light;
        light.position = lightPos;
        light.power = power;
        scene.lights.push_back(light);
    }

    /// Runs the image and compares every ground pixel clearly in or out of the shadow with
    /// the lit value times `shadowFactor` (in) or 1 (out). Returns {in, out} pixel counts.
    std::pair<int, int> check(const Vec3& shadowFactor, const Vec3& absorb) const {
        const int W = 32, H = 24;
        // Secondary rays start past their surface by a multiple of the tolerance (1/8 pixel
        // by default, coarse at 24 rows): a tight explicit one keeps the shadow rays on the
        // oracle's lines. The default is exercised by the scale test in render_test.cpp.
        RenderOptions options = smallImage(W, H);
        options.tolerance = 1e-10;
        const RenderResult r = render(scene, options);
        const Camera camera(scene.camera, W, H);
        int in = 0, out = 0;
        for (int j = 0; j < H; ++j)
            for (int i = 0; i < W; ++i) {
                const Ray ray = camera.rayThrough(i + 0.5, j + 0.5);
                if (ray.dir.y >= 0) continue;
                const double t = -ray.origin.y / ray.dir.y;
                const auto tBall = raySphere(ray.origin, ray.dir, ballCenter, ballRadius);
                if (tBall && double(*tBall) < t) continue;  // the ball hides the ground here
                const Vec3 p = ray.at(t);
                const Vec3 toLight = lightPos - p;
                const double d2 = glm::dot(toLight, toLight);
                const double cosL = toLight.y / std::sqrt(d2);
                const Vec3 lit =
                    ground.diffuse * ground.color * cosL * power / (4 * glm::pi<double>() * d2);
                const double miss = distanceToSegment(ballCenter, p, lightPos);
                Vec3 expected;
                if (miss < ballRadius * 0.98) {
                    const double chord = 2 * std::sqrt(ballRadius * ballRadius - miss * miss);
                    expected = lit * shadowFactor * glm::exp(-absorb * chord);
                    ++in;
                } else if (miss > ballRadius * 1.02) {
                    expected = lit;
                    ++out;
                } else {
                    continue;  // too close to the penumbra line to call
                }
                const Vec3 got = pixel(r.color, i, j);
                INFO("pixel " << i << "," << j);
                for (int k = 0; k < 3; ++k) CHECK(got[k] == Approx(expected[k]).margin(1e-6));
            }
        return {in, out};
    }
};

}  // namespace

TEST_CASE("WhittedIntegrator: Lambert shading under a directional light") {
    Scene scene;
    Material m = blackMaterial();
    m.color = Vec3(0.9, 0.6, 0.3);
    m.diffuse = 0.7;
    const Vec3 center(0.3, -0.2, 0.5);
    const double radius = 1.1;
    addObject(scene, makeSphere(center, radius), addMaterial(scene, m));
    Light sun;
    sun.kind = Light::Kind::Directional;
    sun.direction = Vec3(-1.0, -2.0, 1.5);
    sun.color = Vec3(1.0, 0.8, 0.6);
    scene.lights.push_back(sun);
    scene.background = Vec3(0.25, 0.5, 0.75);

    const int W = 32, H = 24;
    const RenderResult r = render(scene, smallImage(W, H));
    const Camera camera(scene.camera, W, H);
    const Vec3 l = -glm::normalize(sun.direction);
    int hits = 0;
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            const Ray ray = camera.rayThrough(i + 0.5, j + 0.5);
            const auto t = raySphere(ray.origin, ray.dir, center, radius);
            Vec3 expected = scene.background;
            if (t) {
                const Vec3 n = (ray.at(double(*t)) - center) / radius;
                expected = m.diffuse * m.color * sun.color * std::max(0.0, glm::dot(n, l));
                ++hits;
            }
            INFO("pixel " << i << "," << j);
            for (int k = 0; k < 3; ++k)
                CHECK(r.color.at(i, j, k) == Approx(expected[k]).margin(1e-5));
        }
    CHECK(hits > 100);
}

TEST_CASE("WhittedIntegrator: shadows") {
    SECTION("an opaque ball blocks a point light") {
        Material ball = blackMaterial();
        ball.diffuse = 0.5;
        for (bool spanPath : {false, true}) {
            const ShadowScene s(ball, spanPath);
            const auto [in, out] = s.check(Vec3(0.0), Vec3(0.0));
            CHECK(in > 10);
            CHECK(out > 200);
        }
    }

    SECTION("a transmissive ball tints the shadow: (transmit·color)² · exp(−absorb·chord)") {
        Material glass = blackMaterial();
        glass.transmit = 0.6;
        glass.color = Vec3(1.0, 0.5, 0.25);
        glass.absorb = Vec3(0.3, 0.1, 0.7);
        const ShadowScene s(glass);
        const Vec3 crossing = glass.transmit * glass.color;
        const auto [in, out] = s.check(crossing * crossing, glass.absorb);
        CHECK(in > 10);
        CHECK(out > 200);
    }
}

TEST_CASE("WhittedIntegrator: refraction through a slab seen head-on") {
    // Camera on the z axis; the centre pixel of an odd-sized image looks exactly along +z
    // through a slab 0 ≤ z ≤ L. At normal incidence Schlick's F is ((n−1)/(n+1))² on both faces.
    const double L = 0.5, ior = 1.5;
    Scene scene;
    Material glass = blackMaterial();
    glass.transmit = 1;
    glass.ior = ior;
    glass.absorb = Vec3(0.4, 1.0, 2.0);
    addObject(scene, makeBox(Vec3(-2, -2, 0), Vec3(2, 2, L)), addMaterial(scene, glass));
    scene.background = Vec3(0.8, 0.6, 0.4);
    scene.camera.fovDegrees = 20;
    const double F = std::pow((ior - 1) / (ior + 1), 2);
    const Vec3 a = glm::exp(-glass.absorb * L);
    const Vec3& B = scene.background;

    SECTION("two bounces: front reflection plus one pass through") {
        scene.settings.maxDepth = 2;
        const RenderResult r = render(scene, smallImage(9, 9));
        const Vec3 expected = B * (F + (1 - F) * (1 - F) * a);
        for (int k = 0; k < 3; ++k) CHECK(r.color.at(4, 4, k) == Approx(expected[k]).margin(1e-6));
    }

    SECTION("deep recursion: the geometric series of internal reflections") {
        // Inside, each face passes (1 − F)·B out and reflects F back: X = a·((1 − F)·B + F·X).
        // The weight threshold cuts the series after (1 − F)·F², an error below 1e-4.
        scene.settings.maxDepth = 8;
        const RenderResult r = render(scene, smallImage(9, 9));
        const Vec3 expected = B * (F + (1 - F) * (1 - F) * a / (1.0 - F * a));
        for (int k = 0; k < 3; ++k) CHECK(r.color.at(4, 4, k) == Approx(expected[k]).margin(1e-4));
    }
}

TEST_CASE("WhittedIntegrator: total internal reflection inside a glass cube") {
    Scene scene;
    Material glass = blackMaterial();
    glass.transmit = 1;
    glass.ior = 1.5;
    addObject(scene, makeBox(Vec3(-1), Vec3(1)), addMaterial(scene, glass));
    scene.background = Vec3(0.5, 0.7, 0.9);
    scene.camera.eye = Vec3(0.0);
    scene.settings.maxDepth = 8;

    SECTION("a ray steeper than the critical angle on every face is trapped: black, finite") {
        // |d_i| < sqrt(1 − 1/ior²) ≈ 0.745 for every axis, and reflections only flip signs.
        scene.camera.lookAt = Vec3(1.0, 0.9, 0.8);
        const RenderResult r = render(scene, smallImage(9, 9));
        for (int k = 0; k < 3; ++k) CHECK(r.color.at(4, 4, k) == 0.0f);
        CHECK(r.stats.reflectionRays >= 8);  // the centre pixel bounced to maxDepth
        for (float v : r.color.pixels) CHECK(std::isfinite(v));
    }

    SECTION("a ray along an axis escapes: B·(1 − F³), the weight threshold ends the series") {
        scene.camera.lookAt = Vec3(0.0, 0.0, 1.0);
        const RenderResult r = render(scene, smallImage(9, 9));
        const double F = 0.04;  // F² = 1.6e-3 is still traced, F³ = 6.4e-5 is not
        for (int k = 0; k < 3; ++k)
            CHECK(r.color.at(4, 4, k) ==
                  Approx(scene.background[k] * (1 - F * F * F)).margin(1e-6));
    }
}

TEST_CASE("WhittedIntegrator: facing mirrors stop at maxDepth") {
    Scene scene;
    Material mirror = blackMaterial();
    mirror.color = Vec3(0.5, 0.7, 0.9);
    mirror.ambient = 1;
    mirror.reflect = 0.8;
    const int32_t id = addMaterial(scene, mirror);
    addObject(scene, makeHalfSpace(Vec3(0, 0, -1), -1.0), id);  // z ≥ 1
    addObject(scene, makeHalfSpace(Vec3(0, 0, 1), -1.0), id);   // z ≤ −1
    scene.camera.eye = Vec3(0.0);
    scene.camera.lookAt = Vec3(0.0, 0.0, 1.0);
    for (int depth : {0, 3, 8}) {
        scene.settings.maxDepth = depth;
        const RenderResult r = render(scene, smallImage(9, 9));
        double sum = 0;  // ambient seen after 0..depth bounces
        for (int b = 0; b <= depth; ++b) sum += std::pow(mirror.reflect, b);
        INFO("maxDepth " << depth);
        for (int k = 0; k < 3; ++k)
            CHECK(r.color.at(4, 4, k) == Approx(mirror.color[k] * sum).epsilon(1e-6));
        for (float v : r.color.pixels) CHECK(std::isfinite(v));
    }
}

TEST_CASE("WhittedIntegrator: mist") {
    Scene scene;
    Material m = blackMaterial();
    m.ambient = 1;
    m.color = Vec3(0.2, 0.4, 0.6);
    const Vec3 center(0.0, 0.0, 1.0);
    addObject(scene, makeSphere(center, 1.5), addMaterial(scene, m));
    scene.mist.enabled = true;
    scene.mist.color = Vec3(0.9, 0.8, 0.7);
    scene.mist.distance = 3.0;
    scene.background = Vec3(0.0, 1.0, 0.0);  // never seen through mist

    const int W = 16, H = 12;
    const RenderResult r = render(scene, smallImage(W, H));
    const Camera camera(scene.camera, W, H);
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            const Ray ray = camera.rayThrough(i + 0.5, j + 0.5);
            const auto t = raySphere(ray.origin, ray.dir, center, 1.5);
            const Vec3 expected =
                t ? scene.mist.color +
                        (m.color - scene.mist.color) * std::exp(-double(*t) / scene.mist.distance)
                  : scene.mist.color;
            INFO("pixel " << i << "," << j);
            for (int k = 0; k < 3; ++k)
                CHECK(r.color.at(i, j, k) == Approx(expected[k]).margin(1e-6));
        }
}
