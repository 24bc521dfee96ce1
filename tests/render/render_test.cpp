/// @file tests/render/render_test.cpp
/// @brief render(): the depth and normal outputs against closed forms, the same image at
/// every scale and every thread count, statistics and progress.
#include "csg/bvh/scene_geometry.h"
#include "render/camera.h"
#include "render_test_util.h"

#include <catch2/catch.hpp>

#include <glm/gtc/constants.hpp>

#include <cstring>
#include <vector>

using namespace kerf;
using namespace kerf::test;

namespace {

/// A mirror ball resting on a floor, a diffuse ball beside it, a point light: everything a
/// self-intersection bug would show (contact point, reflections, shadows), scaled by s.
Scene sceneAtScale(double s) {
    Scene scene;
    Material floor = blackMaterial();
    floor.color = Vec3(0.8, 0.7, 0.5);
    floor.ambient = 0.1;
    floor.diffuse = 0.8;
    Material mirror = blackMaterial();
    mirror.color = Vec3(0.9);
    mirror.diffuse = 0.1;
    mirror.reflect = 0.8;
    mirror.specular = 0.5;
    mirror.shininess = 40;
    Material clay = blackMaterial();
    clay.color = Vec3(0.3, 0.5, 0.9);
    clay.ambient = 0.1;
    clay.diffuse = 0.9;
    addObject(scene, makeHalfSpace(Vec3(0, 1, 0), 0.0), addMaterial(scene, floor));
    addObject(scene, makeSphere(s * Vec3(0.0, 1.0, 0.0), s * 1.0), addMaterial(scene, mirror));
    addObject(scene, makeSphere(s * Vec3(1.8, 0.6, 0.8), s * 0.6), addMaterial(scene, clay));
    Light light;
    light.position = s * Vec3(2.0, 5.0, -3.0);
    light.power = 300.0 * s * s;  // the same irradiance at every scale
    scene.lights.push_back(light);
    scene.background = Vec3(0.2, 0.3, 0.5);
    scene.camera.eye = s * Vec3(0.0, 2.0, -6.0);
    scene.camera.lookAt = s * Vec3(0.3, 0.8, 0.0);
    scene.camera.fovDegrees = 40;
    scene.settings.maxDepth = 5;
    return scene;
}

}  // namespace

TEST_CASE("render: depth and normal outputs") {
    Scene scene;
    const Vec3 center(0.3, -0.2, 0.5);
    const double radius = 1.1;
    addObject(scene, makeSphere(center, radius), 0);
    const int W = 32, H = 24;
    RenderOptions options = smallImage(W, H);
    options.wantDepth = true;
    options.wantNormal = true;

    for (int spp : {1, 4}) {  // the AOVs use the pixel-centre ray whatever the sampling
        options.spp = spp;
        const RenderResult r = render(scene, options);
        REQUIRE(r.depth.channels == 1);
        REQUIRE(r.normal.channels == 3);
        const Camera camera(scene.camera, W, H);
        int hits = 0;
        for (int j = 0; j < H; ++j)
            for (int i = 0; i < W; ++i) {
                const Ray ray = camera.rayThrough(i + 0.5, j + 0.5);
                const auto t = raySphere(ray.origin, ray.dir, center, radius);
                INFO("spp " << spp << " pixel " << i << "," << j);
                const float depth = r.depth.at(i, j, 0);
                if (!t) {
                    CHECK(std::isinf(depth));
                    CHECK(depth > 0);
                    CHECK(pixel(r.normal, i, j) == Vec3(0.0));
                    continue;
                }
                ++hits;
                // The film is float: compare the stored value with the float of the oracle.
                CHECK(std::abs(double(depth) - double(float(*t))) <= 1e-12 * double(*t));
                const Vec3 n = (ray.at(double(*t)) - center) / radius;
                CHECK(glm::length(pixel(r.normal, i, j) - n) <= 1e-6);
            }
        CHECK(hits > 100);
    }
}

TEST_CASE("render: depth in double precision agrees with the closed form to 1e-12") {
    // The film stores floats; the hit distance itself is checked through the integrator's
    // first-hit path with a double oracle.
    Scene scene;
    const Vec3 center(0.3, -0.2, 0.5);
    const double radius = 1.1;
    addObject(scene, makeSphere(center, radius), 0);
    const SceneGeometry geometry(scene.objects);
    const int W = 32, H = 24;
    const Camera camera(scene.camera, W, H);
    TraceContext ctx;
    ctx.relTolerance = defaultTolerance(H, scene.camera.fovDegrees);
    int hits = 0;
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            const Ray ray = camera.rayThrough(i + 0.5, j + 0.5);
            const auto expected = raySphere(ray.origin, ray.dir, center, radius);
            const auto hit = geometry.nearestHit(ray, 0.0, kInf, ctx);
            INFO("pixel " << i << "," << j);
            REQUIRE(bool(hit) == bool(expected));
            if (!hit) continue;
            ++hits;
            const double depth = glm::length(ray.dir) * hit->t;
            CHECK(std::abs(depth - double(*expected)) <= 1e-12 * double(*expected));
        }
    CHECK(hits > 100);
}

TEST_CASE("render: the same image at scales 1e-6, 1 and 1e6") {
    const int W = 32, H = 24;
    const RenderResult unit = render(sceneAtScale(1.0), smallImage(W, H));
    for (double s : {1e-6, 1e6}) {
        const RenderResult scaled = render(sceneAtScale(s), smallImage(W, H));
        double worst = 0;
        for (size_t k = 0; k < unit.color.pixels.size(); ++k)
            worst =
                std::max(worst, double(std::abs(unit.color.pixels[k] - scaled.color.pixels[k])));
        INFO("scale " << s);
        CHECK(worst <= 1e-4);
        CHECK(scaled.stats.shadowRays == unit.stats.shadowRays);
        CHECK(scaled.stats.reflectionRays == unit.stats.reflectionRays);
    }
    // No acne: floor pixels far from both balls' shadows are lit by the closed form.
    const Scene scene = sceneAtScale(1.0);
    const Camera camera(scene.camera, W, H);
    const Material& floor = scene.materials[1];
    int checked = 0;
    for (int j = H / 2; j < H; ++j)
        for (int i = 0; i < W; i += 3) {
            const Ray ray = camera.rayThrough(i + 0.5, j + 0.5);
            const double t = -ray.origin.y / ray.dir.y;
            const Vec3 p = ray.at(t);
            const Vec3 toLight = scene.lights[0].position - p;
            bool clear = true;
            for (const auto& [c, rad] : {std::pair{Vec3(0, 1, 0), 1.0}, {Vec3(1.8, 0.6, 0.8), 0.6}})
                if (raySphere(ray.origin, ray.dir, c, rad) ||
                    distanceToSegment(c, p, scene.lights[0].position) < 1.1 * rad)
                    clear = false;
            if (!clear) continue;
            const double d2 = glm::dot(toLight, toLight);
            const Vec3 expected = floor.ambient * floor.color +
                                  floor.diffuse * floor.color * (toLight.y / std::sqrt(d2)) *
                                      scene.lights[0].power / (4 * glm::pi<double>() * d2);
            INFO("pixel " << i << "," << j);
            for (int k = 0; k < 3; ++k)
                CHECK(unit.color.at(i, j, k) == Approx(expected[k]).margin(1e-5));
            ++checked;
        }
    CHECK(checked > 20);
}

TEST_CASE("render: identical bits whatever the thread count") {
    Scene scene = sceneAtScale(1.0);
    Material glass = blackMaterial();
    glass.transmit = 0.9;
    glass.ior = 1.5;
    glass.absorb = Vec3(0.2, 0.05, 0.2);
    glass.reflect = 0.05;
    addObject(scene, makeSphere(Vec3(-1.6, 0.7, -0.5), 0.7), addMaterial(scene, glass));
    RenderOptions options = smallImage(40, 30, 1);  // tiles of unequal size at the edges
    options.spp = 4;
    options.wantDepth = true;
    const RenderResult one = render(scene, options);
    options.threads = 2;
    const RenderResult two = render(scene, options);
    REQUIRE(one.color.pixels.size() == two.color.pixels.size());
    CHECK(std::memcmp(one.color.pixels.data(), two.color.pixels.data(),
                      one.color.pixels.size() * sizeof(float)) == 0);
    CHECK(std::memcmp(one.depth.pixels.data(), two.depth.pixels.data(),
                      one.depth.pixels.size() * sizeof(float)) == 0);
    CHECK(one.stats.cameraRays == two.stats.cameraRays);
    CHECK(one.stats.shadowRays == two.stats.shadowRays);
    CHECK(one.stats.refractionRays == two.stats.refractionRays);
    CHECK(one.stats.trace.primitiveTests == two.stats.trace.primitiveTests);
}

TEST_CASE("render: statistics, options and progress") {
    Scene scene = sceneAtScale(1.0);
    scene.settings.width = 20;
    scene.settings.height = 10;
    scene.settings.spp = 2;  // exactly two samples

    SECTION("the scene's settings apply when the options leave them at 0") {
        const RenderResult r = render(scene, RenderOptions{});
        CHECK(r.color.width == 20);
        CHECK(r.color.height == 10);
        CHECK(r.color.channels == 3);
        CHECK(r.depth.pixels.empty());
        CHECK(r.stats.cameraRays == 20u * 10u * 2u);
        CHECK(r.stats.shadowRays > 0);
        CHECK(r.stats.reflectionRays > 0);
        CHECK(r.stats.refractionRays == 0);
        CHECK(r.stats.trace.primitiveTests > 0);
        CHECK(r.stats.tolerance == Approx(defaultTolerance(10, 40)));
        // Every traced ray that hits sends at most one shadow ray per light, and there are
        // no refractions here: a count of rays traced twice or lost would break this.
        const uint64_t traced = r.stats.cameraRays + r.stats.reflectionRays;
        CHECK(r.stats.shadowRays <= traced * scene.lights.size());
        CHECK(r.stats.reflectionRays <= r.stats.cameraRays * uint64_t(scene.settings.maxDepth));
    }

    SECTION("an explicit tolerance is the one in force") {
        RenderOptions o = smallImage(8, 8);
        o.tolerance = 1e-7;
        CHECK(render(scene, o).stats.tolerance == 1e-7);
    }

    SECTION("defaultTolerance is an eighth of a pixel's angle") {
        CHECK(defaultTolerance(100, 90) == Approx(0.125 * 2.0 / 100).epsilon(1e-14));
        CHECK(defaultTolerance(600, 60) == Approx(0.125 * 2 * std::tan(glm::radians(30.0)) / 600));
    }

    SECTION("progress rises to 1") {
        std::vector<double> seen;
        RenderOptions o = smallImage(64, 48, 2);
        o.progress = [&](double f) { seen.push_back(f); };
        render(scene, o);
        REQUIRE(!seen.empty());
        CHECK(seen.back() == 1.0);
        for (size_t k = 0; k < seen.size(); ++k) {
            CHECK(seen[k] >= 0.0);
            CHECK(seen[k] <= 1.0);
            if (k > 0) CHECK(seen[k] >= seen[k - 1]);
        }
    }

    SECTION("a zero-sized image is refused") {
        scene.settings.width = 0;
        CHECK_THROWS_AS(render(scene, RenderOptions{}), std::invalid_argument);
    }
}
