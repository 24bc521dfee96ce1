// Dielectrics: total internal reflection inside a glass sphere and a glass box, and nested
// dielectrics (a glass sphere inside a glass box). Lit only by a uniform background (no lights,
// no emission), so every pixel is a sum of path weights times the background: no channel may
// exceed the brightest background value, none may be negative or non-finite, and the number
// of reflection plus refraction rays is bounded by the binary tree of depth maxDepth. (Single
// rays through a slab and a cube against closed forms are in tests/render/shading_test.cpp.)
#include "render/render.h"
#include "render/render_test_util.h"

#include <catch2/catch.hpp>

#include <cstdio>

using namespace kerf;
using namespace kerf::test;

namespace {

Material glass(double ior, const Vec3& absorb) {
    Material m = blackMaterial();
    m.transmit = 0.95;
    m.reflect = 0.05;
    m.ior = ior;
    m.absorb = absorb;
    return m;
}

/// 0: a glass sphere; 1: a glass box, rotated so that rays meet its faces obliquely (total
/// internal reflection inside); 2: a denser glass sphere inside a glass box (nested).
Scene dielectricScene(int kind, int maxDepth) {
    Scene scene;
    scene.background = Vec3(0.9, 0.6, 0.3);
    scene.camera.eye = Vec3(0.4, 1.2, -4.0);
    scene.camera.lookAt = Vec3(0.0);
    scene.settings.maxDepth = maxDepth;
    const int outer = addMaterial(scene, glass(1.5, Vec3(0.1, 0.0, 0.2)));
    const NodePtr box =
        makeTransform(makeBox(Vec3(-1.0), Vec3(1.0)), Affine::rotateDegrees(Vec3(25, 35, 10)));
    if (kind == 0) addObject(scene, makeSphere(Vec3(0.0), 1.2), outer);
    if (kind >= 1) addObject(scene, box, outer);
    if (kind == 2)
        addObject(scene, makeSphere(Vec3(0.1, -0.1, 0.0), 0.6),
                  addMaterial(scene, glass(2.4, Vec3(0.0))));
    return scene;
}

}  // namespace

TEST_CASE("render: dielectrics end within maxDepth and never add energy") {
    const double brightest = 0.9;
    for (int kind = 0; kind < 3; ++kind)
        for (int maxDepth : {0, 1, 3, 6, 12}) {
            const Scene scene = dielectricScene(kind, maxDepth);
            const RenderOptions options = smallImage(40, 30);
            const RenderResult r = render(scene, options);
            const double pixels = 40.0 * 30.0;
            const double tree = std::pow(2.0, maxDepth + 1) - 2;  // children of a binary tree
            const double secondary = double(r.stats.reflectionRays + r.stats.refractionRays);
            INFO("scene " << kind << " maxDepth " << maxDepth);
            CHECK(r.stats.cameraRays == uint64_t(pixels));
            CHECK(secondary <= pixels * tree);
            if (maxDepth == 0) CHECK(secondary == 0);
            int bad = 0, lit = 0;
            float worst = 0;
            for (float v : r.color.pixels) {
                if (!std::isfinite(v) || v < 0 || v > brightest * (1 + 1e-6)) ++bad;
                worst = std::max(worst, v);
                lit += v > 0;
            }
            CHECK(bad == 0);
            CHECK(worst <= brightest * (1 + 1e-6));
            CHECK(lit > 0);
            if (maxDepth == 12)
                std::printf(
                    "dielectric scene %d, maxDepth 12: %.0f secondary rays (%.2f per pixel), "
                    "brightest channel %.4f\n",
                    kind, secondary, secondary / pixels, worst);
        }
}

TEST_CASE("render: light trapped by total internal reflection in a glass box decays") {
    // Inside the box, rays steeper than the critical angle (41.8° at ior 1.5) bounce between
    // faces: with Beer absorption their weight falls each bounce and the recursion stops by
    // weight before maxDepth = 40; the count of secondary rays stays far below the tree bound.
    Scene scene = dielectricScene(1, 40);
    scene.materials[1].absorb = Vec3(0.5);
    const RenderResult r = render(scene, smallImage(24, 18));
    const double perPixel = double(r.stats.reflectionRays + r.stats.refractionRays) / (24 * 18);
    std::printf("TIR box, maxDepth 40: %.1f secondary rays per pixel\n", perPixel);
    CHECK(perPixel < 200);
    for (float v : r.color.pixels) {
        CHECK(std::isfinite(v));
        CHECK(v <= 0.9f * (1 + 1e-6f));
        CHECK(v >= 0);
    }
}
