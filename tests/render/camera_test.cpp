/// @file tests/render/camera_test.cpp
#include "render/camera.h"
#include "render_test_util.h"

#include <catch2/catch.hpp>

#include <glm/gtc/constants.hpp>

using namespace kerf;

TEST_CASE("Camera::rayThrough") {
    SECTION("pixel centres follow the documented formula, W != H") {
        CameraDesc desc;
        desc.eye = Vec3(1.0, 2.0, 3.0);
        desc.lookAt = Vec3(-1.0, 0.5, 7.0);
        desc.up = Vec3(0.1, 1.0, 0.0);
        desc.fovDegrees = 50;
        const int W = 7, H = 4;
        const Camera camera(desc, W, H);
        for (auto [i, j] : {std::pair{0, 0}, {6, 0}, {0, 3}, {6, 3}, {3, 2}, {5, 1}}) {
            const Ray ray = camera.rayThrough(i + 0.5, j + 0.5);
            const Vec3 expected = test::referenceDirection(desc, W, H, i + 0.5, j + 0.5);
            INFO("pixel " << i << "," << j);
            CHECK(ray.origin == desc.eye);
            CHECK(glm::length(ray.dir - expected) <= 1e-15);
            CHECK(std::abs(glm::length(ray.dir) - 1.0) <= 1e-15);
        }
    }

    SECTION("geometry: centre on the axis, film edges at half the fov, x to the left") {
        CameraDesc desc;  // eye (0,0,-5) looking at the origin along +z, y up
        desc.fovDegrees = 60;
        const int W = 9, H = 5;  // odd: a pixel sits exactly on the axis
        const Camera camera(desc, W, H);
        const Vec3 axis = camera.rayThrough(4.5, 2.5).dir;
        CHECK(axis == Vec3(0.0, 0.0, 1.0));
        // The top edge of the film is fov/2 above the axis.
        const Vec3 top = camera.rayThrough(4.5, 0.0).dir;
        CHECK(std::acos(glm::dot(top, axis)) == Approx(glm::radians(30.0)).epsilon(1e-13));
        CHECK(top.y > 0);
        // The right edge: tan of the horizontal half angle is tan(fov/2)·W/H.
        const Vec3 right = camera.rayThrough(9.0, 2.5).dir;
        CHECK(std::abs(right.x / right.z) == Approx(std::tan(glm::radians(30.0)) * 9 / 5));
        // Right-handed, y up, looking along +z: the image's right is −x.
        CHECK(right.x < 0);
        CHECK(camera.rayThrough(0.5, 2.5).dir.x > 0);
    }
}
