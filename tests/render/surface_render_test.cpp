/// @file tests/render/surface_render_test.cpp
/// @brief Surfaces in images (csg/primitives/surfaces.h): a disc casts the shadow its closed form
/// says, on both shadow paths, and its back shows the interior material.
#include "render/camera.h"
#include "render_test_util.h"

#include "csg/primitives/surfaces.h"

#include <catch2/catch.hpp>

#include <glm/gtc/constants.hpp>

using namespace kerf;
using namespace kerf::test;

TEST_CASE("surfaces: a disc between a point light and the ground shadows what is under it") {
    const Vec3 c(0.2, 1.0, 0.3), lightPos(0.0, 3.0, 0.0);
    const double radius = 0.5, power = 40.0;
    for (bool spanPath : {false, true}) {
        INFO("span path " << spanPath);
        Scene scene;
        Material ground = blackMaterial();
        ground.diffuse = 0.7;
        ground.color = Vec3(0.9, 0.8, 0.7);
        Material sheet = blackMaterial();
        sheet.diffuse = 0.5;
        scene.camera.eye = Vec3(0.0, 5.0, -4.0);
        scene.camera.lookAt = Vec3(0.0, 0.0, 0.5);
        scene.camera.fovDegrees = 45;
        addObject(scene, makeHalfSpace(Vec3(0, 1, 0), 0.0), addMaterial(scene, ground));
        addObject(scene, makeDisc(c, Vec3(0, 1, 0), radius), addMaterial(scene, sheet));
        if (spanPath) {  // an unused glass: shadow rays then walk spans instead of occluded()
            Material glass = blackMaterial();
            glass.transmit = 1;
            addMaterial(scene, glass);
        }
        Light light;
        light.position = lightPos;
        light.power = power;
        scene.lights.push_back(light);

        const int W = 32, H = 24;
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
                // The camera's view of the ground through the disc's plane y = 1.
                const Vec3 q = ray.at((1.0 - ray.origin.y) / ray.dir.y);
                if (std::hypot(q.x - c.x, q.z - c.z) < radius * 1.02) continue;
                const Vec3 p = ray.at(t);
                // The segment from p to the light meets y = 1 a third of the way up.
                const Vec3 m = p + (lightPos - p) / 3.0;
                const double rho = std::hypot(m.x - c.x, m.z - c.z);
                const Vec3 toLight = lightPos - p;
                const double d2 = glm::dot(toLight, toLight);
                const Vec3 lit = ground.diffuse * ground.color * (toLight.y / std::sqrt(d2)) *
                                 power / (4 * glm::pi<double>() * d2);
                Vec3 expected;
                if (rho < radius * 0.98) {
                    expected = Vec3(0.0);
                    ++in;
                } else if (rho > radius * 1.02) {
                    expected = lit;
                    ++out;
                } else {
                    continue;
                }
                INFO("pixel " << i << "," << j);
                const Vec3 got = pixel(r.color, i, j);
                for (int k = 0; k < 3; ++k) CHECK(got[k] == Approx(expected[k]).margin(1e-6));
            }
        CHECK(in > 10);
        CHECK(out > 200);
    }
}

TEST_CASE("surfaces: the back of a disc shows its interior material, the front its material") {
    Scene scene;
    Material front = blackMaterial(), back = blackMaterial();
    front.emit = Vec3(0.9, 0.1, 0.1);
    back.emit = Vec3(0.1, 0.2, 0.8);
    const int32_t f = addMaterial(scene, front), b = addMaterial(scene, back);
    // Facing +z; the camera looks along the axis from either side.
    scene.objects.push_back(
        makeMaterial(makeInterior(makeDisc(Vec3(0.0), Vec3(0, 0, 1), 1.0), b), f));
    scene.background = Vec3(0.0);
    for (double side : {1.0, -1.0}) {
        INFO("camera at z = " << 4 * side);
        scene.camera.eye = Vec3(0, 0, 4 * side);
        scene.camera.lookAt = Vec3(0.0);
        scene.camera.fovDegrees = 30;
        const RenderResult r = render(scene, smallImage(9, 9));
        const Vec3 expected = side > 0 ? front.emit : back.emit;
        const Vec3 got = pixel(r.color, 4, 4);
        for (int k = 0; k < 3; ++k) CHECK(got[k] == Approx(expected[k]).margin(1e-6));
        CHECK(pixel(r.color, 0, 0) == Vec3(0.0));  // past the rim: the background
    }
}
