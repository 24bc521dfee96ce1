/// @file tests/render/section_test.cpp
/// @brief Section views (render/section_cut.h): the cut model against ray–plane and ray–circle
/// geometry in long double, shadows through the removed part, and untouched objects' bits.
#include "render/section_cut.h"
#include "render_test_util.h"
#include "util/compiled_scene.h"

#include <catch2/catch.hpp>

#include <glm/gtc/constants.hpp>

#include <cstring>

using namespace kerf;
using namespace kerf::test;

namespace {

constexpr int kSide = 101;  // odd: the middle pixel's centre ray is the view axis
const Vec3 kCapColor(1.0, 0.0, 0.0);

/// A unit green sphere at the origin seen from (0, 0, 10) looking down -z; no lights.
Scene sphereFromAbove() {
    Scene scene;
    Material green = blackMaterial();
    green.color = Vec3(0.0, 1.0, 0.0);
    green.ambient = 1.0;
    addObject(scene, makeSphere(Vec3(0.0), 1.0), addMaterial(scene, green));
    scene.camera.eye = Vec3(0.0, 0.0, 10.0);
    scene.camera.lookAt = Vec3(0.0);
    scene.camera.up = Vec3(0.0, 1.0, 0.0);
    scene.camera.fovDegrees = 20.0;
    return scene;
}

SectionPlane plane(const Vec3& point, const Vec3& normal) {
    SectionPlane s;
    s.point = point;
    s.normal = glm::normalize(normal);
    s.color = kCapColor;
    return s;
}

/// Where the centre ray of pixel (i, j) meets the plane z = height, in long double.
struct PlaneHit {
    long double t, x, y;
};
PlaneHit centreRayOnPlane(const CameraDesc& c, int i, int j, double height) {
    const Vec3 d = referenceDirection(c, kSide, kSide, i + 0.5, j + 0.5);
    const long double t = (static_cast<long double>(height) - c.eye.z) / d.z;
    return {t, c.eye.x + t * d.x, c.eye.y + t * d.y};
}

bool isCap(const Image& image, int i, int j) {
    return image.at(i, j, 0) > 0.0f && image.at(i, j, 1) == 0.0f && image.at(i, j, 2) == 0.0f;
}

bool sameBits(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.channels == b.channels &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

}  // namespace

TEST_CASE("section: a sphere cut by z = 0 seen from above shows its cap") {
    Scene scene = sphereFromAbove();
    scene.sections.push_back(plane(Vec3(0.0), Vec3(0, 0, 1)));
    RenderOptions options = smallImage(kSide, kSide);
    options.wantDepth = true;
    options.wantNormal = true;
    const RenderResult r = render(scene, options);

    // The middle pixel's ray is the view axis: it meets the cap at the origin, 10 away,
    // where the normal is the plane's, towards the removed side.
    const int mid = kSide / 2;
    CHECK(std::fabs(r.depth.at(mid, mid, 0) - 10.0f) <= 10.0f * 1e-6f);
    CHECK(r.normal.at(mid, mid, 0) == 0.0f);
    CHECK(r.normal.at(mid, mid, 1) == 0.0f);
    CHECK(r.normal.at(mid, mid, 2) == 1.0f);
    CHECK(isCap(r.color, mid, mid));

    // Pixel by pixel: a centre ray shows the cap exactly where it meets z = 0 inside the unit
    // disc (long double), and never the sphere (the lower half lies inside the equator's cone
    // from the eye). Rays within 1e-9 of the rim are not judged.
    int capPixels = 0, oraclePixels = 0, judged = 0, spherePixels = 0;
    for (int j = 0; j < kSide; ++j)
        for (int i = 0; i < kSide; ++i) {
            const PlaneHit h = centreRayOnPlane(scene.camera, i, j, 0.0);
            const long double rho = std::sqrt(h.x * h.x + h.y * h.y);
            const bool cap = isCap(r.color, i, j);
            capPixels += cap;
            spherePixels += r.color.at(i, j, 1) > 0.0f;
            oraclePixels += rho < 1.0L;
            if (std::fabs(rho - 1.0L) < 1e-9L) continue;
            ++judged;
            INFO("pixel " << i << ", " << j << " rho " << double(rho));
            REQUIRE(cap == (rho < 1.0L));
            if (cap) REQUIRE(std::fabs(r.depth.at(i, j, 0) - double(h.t)) <= 1e-6 * double(h.t));
        }
    CHECK(judged == kSide * kSide);
    CHECK(capPixels == oraclePixels);
    CHECK(spherePixels == 0);

    // Against the area: the disc of radius 1 at distance 10 is a circle of radius
    // R = 0.1 / tan(10°) · 101/2 pixels on the film, and the pixel centres inside it number
    // πR² within the area of the band |ρ − R| ≤ √2/2 about its rim (2√2·πR).
    const double R = 0.1 / std::tan(glm::radians(10.0)) * kSide / 2.0;
    const double pi = glm::pi<double>();
    INFO("cap pixels " << capPixels << ", pi R^2 = " << pi * R * R);
    CHECK(std::fabs(capPixels - pi * R * R) <= 2.0 * std::sqrt(2.0) * pi * R);
}

TEST_CASE("section: an oblique plane's cap lies on the plane") {
    // The plane through (0.2, 0, 0) with normal (1, 1, 2)/√6: the camera looks along −n at
    // the cap, so every ray that meets the plane inside the ball shows the cap there.
    Scene scene = sphereFromAbove();
    const Vec3 n = glm::normalize(Vec3(1.0, 1.0, 2.0));
    const Vec3 p0(0.2, 0.0, 0.0);
    scene.sections.push_back(plane(p0, n));
    scene.camera.eye = p0 + 10.0 * n;
    scene.camera.lookAt = p0;
    RenderOptions options = smallImage(kSide, kSide);
    options.wantDepth = true;
    const RenderResult r = render(scene, options);
    int caps = 0;
    for (int j = 0; j < kSide; ++j)
        for (int i = 0; i < kSide; ++i) {
            const Vec3 d = referenceDirection(scene.camera, kSide, kSide, i + 0.5, j + 0.5);
            using LD = long double;
            const LD dn = LD(d.x) * n.x + LD(d.y) * n.y + LD(d.z) * n.z;
            const LD t = -10.0L / dn;  // the eye is 10 from the plane along n
            const LD x = LD(scene.camera.eye.x) + t * d.x, y = LD(scene.camera.eye.y) + t * d.y,
                     z = LD(scene.camera.eye.z) + t * d.z;
            const LD rho = std::sqrt(x * x + y * y + z * z);
            if (std::fabs(rho - 1.0L) < 1e-9L) continue;
            INFO("pixel " << i << ", " << j);
            REQUIRE(isCap(r.color, i, j) == (rho < 1.0L));
            if (rho < 1.0L) {
                ++caps;
                REQUIRE(std::fabs(r.depth.at(i, j, 0) - double(t)) <= 1e-6 * double(t));
            }
        }
    CHECK(caps > 1000);
}

TEST_CASE("section: the cup cut at mid height shows its wall's annulus") {
    // The cup's body (models/cup.kerf): radius 1.2, wall 0.12, axis y, cut by y = 1.2 and seen
    // from above. A centre ray shows the cap where it meets the plane in the annulus
    // 1.08 ≤ ρ ≤ 1.2, the cup's floor (y = 0.12) inside it, and nothing outside.
    const Scene scene = compiledScene(R"(
        let R = 1.2;
        let wall = R / 10;
        material clay { color <0, 1, 0> ambient 1 diffuse 0 }
        object difference {
            cylinder { from <0, 0, 0> to <0, 2.4, 0> radius R }
            cylinder { from <0, wall, 0> to <0, 2.5, 0> radius R - wall }
        } material clay;
        section { point <0, 1.2, 0> normal <0, 1, 0> color <1, 0, 0> }
        camera { eye <0, 10, 0> look_at <0, 0, 0> up <0, 0, 1> fov 20 })");
    RenderOptions options = smallImage(kSide, kSide);
    options.wantDepth = true;
    const RenderResult r = render(scene, options);
    int caps = 0, floors = 0;
    for (int j = 0; j < kSide; ++j)
        for (int i = 0; i < kSide; ++i) {
            const Vec3 d = referenceDirection(scene.camera, kSide, kSide, i + 0.5, j + 0.5);
            const long double t = (1.2L - 10.0L) / d.y;
            const long double x = t * d.x, z = t * d.z;
            const long double rho = std::sqrt(x * x + z * z);
            const long double inner = 1.2L - 1.2L / 10;
            if (std::fabs(rho - 1.2L) < 1e-9L || std::fabs(rho - inner) < 1e-9L) continue;
            const bool cap = rho > inner && rho < 1.2L;
            INFO("pixel " << i << ", " << j << " rho " << double(rho));
            REQUIRE(isCap(r.color, i, j) == cap);
            if (cap) {
                ++caps;
                REQUIRE(std::fabs(r.depth.at(i, j, 0) - double(t)) <= 1e-6 * double(t));
            } else if (rho < inner) {
                // Inside: the cup's floor where the ray reaches it within the inner wall,
                // else the inner wall; both clay.
                REQUIRE(r.color.at(i, j, 1) == 1.0f);
                const long double tFloor = (0.12L - 10.0L) / d.y;
                const long double rhoFloor = rho * tFloor / t;
                if (rhoFloor < inner * (1 - 1e-9L)) {
                    ++floors;
                    REQUIRE(std::fabs(r.depth.at(i, j, 0) - double(tFloor)) <=
                            1e-6 * double(tFloor));
                }
            } else {
                REQUIRE(std::isinf(r.depth.at(i, j, 0)));
            }
        }
    // Against the annulus π(R² − r²) on the film (radii scaled by 1/(8.8·tan 10°) · 101/2 px):
    // pixel centres in it number its area within the area of the bands about both rims.
    const double k = 1.0 / (8.8 * std::tan(glm::radians(10.0))) * kSide / 2.0;
    const double outer = 1.2 * k, inner = 1.08 * k, pi = glm::pi<double>();
    const double area = pi * (outer * outer - inner * inner);
    INFO("cap pixels " << caps << ", annulus " << area);
    CHECK(std::fabs(caps - area) <= 2.0 * std::sqrt(2.0) * pi * (outer + inner));
    CHECK(floors > 0);
}

TEST_CASE("section: shadow rays see the cut, the cap is lit") {
    // A point light above the cut, off the view axis: the removed upper half would shadow the
    // cap's centre; cut, the centre gets ambient + diffuse · cos · power / (4π d²).
    Scene scene = sphereFromAbove();
    scene.sections.push_back(plane(Vec3(0.0), Vec3(0, 0, 1)));
    Light light;
    light.position = Vec3(0.0, 3.0, 4.0);  // 5 from the origin, cos = 4/5 on the cap
    light.power = 100.0 * glm::pi<double>();
    scene.lights.push_back(light);
    const RenderResult r = render(scene, smallImage(kSide, kSide));
    const int mid = kSide / 2;
    const Material cap;  // the cap material: the defaults with the plane's colour
    const double expected =
        cap.ambient + cap.diffuse * 0.8 * light.power / (4.0 * glm::pi<double>() * 25.0);
    CHECK(r.color.at(mid, mid, 0) == Approx(expected).epsilon(1e-6));
    CHECK(r.color.at(mid, mid, 0) > 2.0 * cap.ambient);  // far from the shadowed value
    CHECK(r.color.at(mid, mid, 1) == 0.0f);
}

TEST_CASE("section: a plane that misses an object leaves its bits") {
    const RenderResult plain = render(sphereFromAbove(), smallImage(kSide, kSide));

    // Kept side: the object is not wrapped, the image is the same bit for bit.
    Scene kept = sphereFromAbove();
    kept.sections.push_back(plane(Vec3(0.0, 0.0, 1.5), Vec3(0, 0, 1)));
    kept.sections.push_back(plane(Vec3(-2.0, 0.0, 0.0), Vec3(-1, 0, 0)));
    const Scene cut = cutBySections(kept);
    REQUIRE(cut.objects.size() == 1);
    CHECK(cut.objects[0] == kept.objects[0]);
    CHECK(sameBits(render(kept, smallImage(kSide, kSide)).color, plain.color));

    // A face in the plane, the box on the kept side: compared exactly, so not wrapped (its
    // face and the cap would be coincident surfaces), whichever way the plane is written.
    Scene touching;
    touching.objects = {makeBox(Vec3(-1.0, -1.0, 0.0), Vec3(1.0, 1.0, 4.0)),
                        makeBox(Vec3(-1.0, 0.1, -3.0), Vec3(1.0, 0.3, 0.3))};
    touching.sections.push_back(plane(Vec3(5.0, 7.0, 0.0), Vec3(0, 0, -3)));
    const Scene touched = cutBySections(touching);
    REQUIRE(touched.objects.size() == 2);
    CHECK(touched.objects[0] == touching.objects[0]);
    CHECK(touched.objects[1] != touching.objects[1]);  // straddles z = 0: cut
    CHECK(touched.objects[1]->bounds().lo.z == 0.0);   // and its bounds shrink to the kept side

    // Removed side: the object is gone, every pixel is the background.
    Scene removed = sphereFromAbove();
    removed.background = Vec3(0.25, 0.5, 0.75);
    removed.sections.push_back(plane(Vec3(0.0, 0.0, -1.5), Vec3(0, 0, 1)));
    CHECK(cutBySections(removed).objects.empty());
    const RenderResult empty = render(removed, smallImage(kSide, kSide));
    for (int j = 0; j < kSide; ++j)
        for (int i = 0; i < kSide; ++i) REQUIRE(pixel(empty.color, i, j) == Vec3(0.25, 0.5, 0.75));
}

TEST_CASE("section: a removed object drops its flags with it, a kept one keeps them") {
    Scene scene = sphereFromAbove();
    addObject(scene, makeSphere(Vec3(5.0, 0.0, 0.0), 1.0), 0);
    addObject(scene, makeSphere(Vec3(-5.0, 0.0, 0.0), 1.0), 0);
    scene.objectFlags = {ObjectFlags{true}, ObjectFlags{false}, ObjectFlags{true}};
    scene.sections.push_back(plane(Vec3(3.0, 0.0, 0.0), Vec3(1, 0, 0)));  // removes x > 3
    const Scene cut = cutBySections(scene);
    REQUIRE(cut.objects.size() == 2);
    REQUIRE(cut.objectFlags.size() == 2);
    CHECK(cut.objects[0] == scene.objects[0]);  // x ≤ 1: wholly kept
    CHECK(cut.objects[1] == scene.objects[2]);
    CHECK(cut.objectFlags[0].castsShadow);
    CHECK(cut.objectFlags[1].castsShadow);
    CHECK(cut.materials.size() == scene.materials.size() + 1);
    CHECK(cut.materials.back().color == kCapColor);
}

TEST_CASE("section: the octree and beams give the cut the same depths as plain tracing") {
    // An implicit ball (root-found, so the octree and beams take it) cut by two planes.
    const std::string model = R"(
        object implicit { f x*x + y*y + z*z - 1 bound box { min <-1.1, -1.1, -1.1> max <1.1, 1.1, 1.1> } };
        section { point <0, 0, 0.3> normal <0, 0, 1> }
        section { point <0.2, 0, 0> normal <1, 1, 0> }
        camera { eye <3, 4, 8> look_at <0, 0, 0> up <0, 1, 0> fov 25 })";
    const Scene scene = compiledScene(model);
    RenderOptions fast = smallImage(64, 64);
    fast.wantDepth = true;
    fast.accel = Accel::Octree;
    fast.beams = BeamMode::On;
    RenderOptions plain = fast;
    plain.accel = Accel::None;
    plain.beams = BeamMode::Off;
    const RenderResult a = render(scene, fast);
    const RenderResult b = render(scene, plain);
    CHECK(a.stats.octree.objects == 1);
    CHECK(a.stats.beamsUsed);
    int hits = 0;
    for (int j = 0; j < 64; ++j)
        for (int i = 0; i < 64; ++i) {
            const float da = a.depth.at(i, j, 0), db = b.depth.at(i, j, 0);
            INFO("pixel " << i << ", " << j << ": " << da << " vs " << db);
            REQUIRE(std::isinf(da) == std::isinf(db));
            if (std::isinf(da)) continue;
            ++hits;
            // Both within the relative tolerance of the true hit, so within twice it.
            REQUIRE(std::fabs(da - db) <= 2.0 * a.stats.tolerance * db + 1e-6 * db);
        }
    CHECK(hits > 500);
}

TEST_CASE("section: reflected rays see the cut, not the removed part") {
    // A horizontal mirror below the plane z = 0 (wholly kept) reflects the centre ray up
    // through (0.9, 0, 0.3), inside the ball's removed upper part, having crossed z = 0 at
    // x ≈ 1.17, outside the ball: uncut, it sees the ball; cut, what a scene without the
    // ball shows there.
    const auto scene = [](bool withBall, bool cut) {
        Scene s;
        s.background = Vec3(0.25, 0.5, 0.75);
        Material mirror = blackMaterial();
        mirror.reflect = 0.5;
        addObject(s, makeBox(Vec3(2.0, -3.0, -3.0), Vec3(6.0, 3.0, -2.0)), addMaterial(s, mirror));
        if (withBall) {
            Material green = blackMaterial();
            green.color = Vec3(0.0, 1.0, 0.0);
            green.ambient = 1.0;
            addObject(s, makeSphere(Vec3(0.0), 1.0), addMaterial(s, green));
        }
        if (cut) s.sections.push_back(plane(Vec3(0.0), Vec3(0, 0, 1)));
        // The mirror point (3, 0, −2) seen along (−2.1, 0, −2.3), reflected to (−2.1, 0, 2.3).
        s.camera.eye = Vec3(3.0 + 4 * 2.1, 0.0, -2.0 + 4 * 2.3);
        s.camera.lookAt = Vec3(3.0, 0.0, -2.0);
        s.camera.up = Vec3(0.0, 1.0, 0.0);
        return s;
    };
    const int mid = kSide / 2;
    const Vec3 uncut = pixel(render(scene(true, false), smallImage(kSide, kSide)).color, mid, mid);
    const Vec3 cut = pixel(render(scene(true, true), smallImage(kSide, kSide)).color, mid, mid);
    const Vec3 none = pixel(render(scene(false, false), smallImage(kSide, kSide)).color, mid, mid);
    CHECK(uncut.y == Approx(0.5));  // half the mirror's light is the green ball
    CHECK(cut == none);
    CHECK(cut == Vec3(0.5 * 0.25, 0.5 * 0.5, 0.5 * 0.75));  // half the background
}
