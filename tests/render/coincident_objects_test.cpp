/// @file tests/render/coincident_objects_test.cpp
/// @brief Two separate objects touching along a face: a glass box resting on an opaque one
/// (and, mirrored, an opaque box on glass) has no speckles where the faces coincide, at any
/// scale and in either object order.
#include "render/camera.h"
#include "render_test_util.h"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace kerf;
using namespace kerf::test;

namespace {

constexpr int kW = 48, kH = 36;

/// The glass slab (about 2 × 0.25 × 2) lies on a larger opaque block; `mirrored` flips y, so
/// the opaque block rests on the glass and camera and light look from below. The glass is
/// placed by a transform and the block by its coordinates, so the shared face at y = 0.3·s
/// comes out of different roundings (0.1 + 0.2 is not 0.3): the two objects' hits differ by
/// an ulp or so, either way.
Scene contactScene(double s, bool mirrored, bool glassFirst) {
    const double sy = mirrored ? -1.0 : 1.0;
    auto box = [&](const Vec3& lo, const Vec3& hi) {  // y mirrored when asked
        const double y0 = mirrored ? -hi.y : lo.y, y1 = mirrored ? -lo.y : hi.y;
        return makeBox(s * Vec3(lo.x, y0, lo.z), s * Vec3(hi.x, y1, hi.z));
    };
    const Vec3 centre(0.1, 0.3 * sy, -0.05);
    Scene scene;
    Material glass = blackMaterial();
    glass.transmit = 0.9;
    glass.ior = 1.5;
    glass.reflect = 0.04;
    Material clay = blackMaterial();
    clay.color = Vec3(0.8, 0.5, 0.3);
    clay.ambient = 0.1;
    clay.diffuse = 0.8;
    const int32_t glassId = addMaterial(scene, glass), clayId = addMaterial(scene, clay);
    auto addGlass = [&] {
        addObject(scene,
                  makeTransform(box({-1, 0.1, -1}, {1, 0.35, 1}),
                                Affine::translate(s * (centre - Vec3(0, 0.1 * sy, 0)))),
                  glassId);
    };
    if (glassFirst) addGlass();
    const Vec3 top(0.1, 0.3, -0.05);  // the block's top centre before mirroring
    addObject(scene, box(top + Vec3(-2, -1, -2), top + Vec3(2, 0, 2)), clayId);
    if (!glassFirst) addGlass();
    Light sun;
    sun.kind = Light::Kind::Directional;
    sun.direction = Vec3(0.3, -1.0 * sy, 0.2);
    sun.color = Vec3(1.0);
    scene.lights.push_back(sun);
    scene.background = Vec3(0.2, 0.3, 0.5);
    scene.camera.eye = s * Vec3(0.4, 2.6 * sy, -1.3);
    scene.camera.lookAt = s * centre;
    scene.camera.fovDegrees = 35;
    scene.settings.maxDepth = 5;
    return scene;
}

/// Pixels whose centre ray crosses the glass's outer face well inside it (at least 0.4 from
/// its edges): seen through the glass, every one of them shows the contact face.
std::vector<std::pair<int, int>> contactPixels(bool mirrored) {
    const Scene scene = contactScene(1.0, mirrored, true);
    const Camera camera(scene.camera, kW, kH);
    const double faceY = mirrored ? -0.55 : 0.55;
    std::vector<std::pair<int, int>> pixels;
    for (int j = 0; j < kH; ++j)
        for (int i = 0; i < kW; ++i) {
            const Ray ray = camera.rayThrough(i + 0.5, j + 0.5);
            const Vec3 p = ray.at((faceY - ray.origin.y) / ray.dir.y);
            if (std::abs(p.x - 0.1) < 0.6 && std::abs(p.z + 0.05) < 0.6) pixels.push_back({i, j});
        }
    return pixels;
}

}  // namespace

TEST_CASE("render: a glass box on an opaque box shows the contact face without speckles") {
    for (bool mirrored : {false, true}) {
        const std::vector<std::pair<int, int>> region = contactPixels(mirrored);
        REQUIRE(region.size() > 150);
        std::vector<bool> inRegion(kW * kH, false);
        for (auto [i, j] : region) inRegion[j * kW + i] = true;
        Image unit;
        for (bool glassFirst : {true, false}) {
            for (double s : {1.0, 1e-3, 1e3}) {
                INFO((mirrored ? "opaque on glass" : "glass on opaque")
                     << (glassFirst ? ", glass first" : ", opaque first") << ", scale " << s);
                const RenderResult r =
                    render(contactScene(s, mirrored, glassFirst), smallImage(kW, kH));
                // Seen through the glass the lit face is smooth: neighbours differ little,
                // where a speckle (the block's far face, or a shadow) differs by ~0.3.
                double worstStep = 0;
                for (auto [i, j] : region) {
                    if (i + 1 < kW && inRegion[j * kW + i + 1])
                        worstStep = std::max(
                            worstStep,
                            double(glm::length(pixel(r.color, i, j) - pixel(r.color, i + 1, j))));
                    if (j + 1 < kH && inRegion[(j + 1) * kW + i])
                        worstStep = std::max(
                            worstStep,
                            double(glm::length(pixel(r.color, i, j) - pixel(r.color, i, j + 1))));
                }
                CHECK(worstStep <= 0.02);
                // The clay is lit through the glass: brighter than its ambient term alone.
                int dark = 0;
                for (auto [i, j] : region) dark += pixel(r.color, i, j).x <= 0.2;
                CHECK(dark == 0);
                // And the same picture at every scale and in either object order.
                if (unit.pixels.empty()) unit = r.color;
                double worst = 0;
                for (size_t k = 0; k < unit.pixels.size(); ++k)
                    worst = std::max(worst, double(std::abs(unit.pixels[k] - r.color.pixels[k])));
                CHECK(worst <= 1e-4);
            }
        }
    }
}
