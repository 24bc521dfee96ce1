// Coherent camera rays (render/primary_beams.h): the frustum slice holds every ray point it
// claims to, each pixel's start lies before the first surface of every ray through the pixel,
// and renders with beams give the same first hits as without, within the tolerance.
#include "render/primary_beams.h"

#include "assets/asset_cache.h"
#include "csg/bvh/scene_geometry.h"
#include "lang/compile.h"
#include "render/camera.h"
#include "render/render.h"
#include "util/compiled_scene.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <random>
#include <sstream>

using namespace kerf;

namespace {

Scene compiled(const std::string& text) {
    return test::compiledScene(text, "primary_beams_test.kerf");
}

/// Issue 8's gyroid ball on a floor, and Barth's sextic clipped by a sphere.
const char* kGyroidBall = R"(
let k = 2*pi;
solid g = implicit {
    f sin(k*x)*cos(k*y) + sin(k*y)*cos(k*z) + sin(k*z)*cos(k*x)
    bound box { min <-3.1, -3.1, -3.1> max <3.1, 3.1, 3.1> }
};
object intersection { g sphere { radius 3 } } translate <0, 3, 0>;
object halfspace { normal <0, 1, 0> offset 0 };
camera { eye <0, 5, -12> look_at <0, 3, 0> up <0, 1, 0> fov 35 }
)";

const char* kBarth = R"(
let p = (1 + sqrt(5)) / 2;
solid barth = implicit {
    f 4*(p^2*x^2 - y^2)*(p^2*y^2 - z^2)*(p^2*z^2 - x^2) - (1 + 2*p)*(x^2 + y^2 + z^2 - 1)^2
    bound box { min <-1.8, -1.8, -1.8> max <1.8, 1.8, 1.8> }
};
object intersection { barth sphere { radius 1.8 } } rotate <20, 30, 0>;
camera { eye <0, 0, -6> look_at <0, 0, 0> up <0, 1, 0> fov 40 }
)";

}  // namespace

TEST_CASE("Camera::frustumSlice holds every ray point of the rectangle and range", "[beams]") {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int outside = 0;
    std::string first;
    for (int trial = 0; trial < 400; ++trial) {
        const double scale = trial % 4 == 0 ? 1e-6 : trial % 4 == 1 ? 1e6 : 1.0;
        CameraDesc desc;
        desc.eye = scale * Vec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5) * 20.0 +
                   (trial % 7 == 0 ? Vec3(1e8, 0.0, 0.0) : Vec3(0.0));  // far from the origin
        desc.lookAt = desc.eye + scale * Vec3(unit(rng) - 0.5, unit(rng) - 0.5, 1.0);
        desc.up = Vec3(0.0, 1.0, 0.0);
        desc.fovDegrees = 1.0 + 170.0 * unit(rng);
        const int width = 1 + int(unit(rng) * 800), height = 1 + int(unit(rng) * 600);
        const Camera camera(desc, width, height);
        const double x0 = unit(rng) * width, x1 = x0 + unit(rng) * (width - x0);
        const double y0 = unit(rng) * height, y1 = y0 + unit(rng) * (height - y0);
        const double ta = trial % 5 == 0 ? 0.0 : scale * 30.0 * unit(rng);
        const double tb = ta * (1.0 + unit(rng)) + scale * unit(rng);
        const Bounds3 box = camera.frustumSlice(x0, y0, x1, y1, ta, tb);
        for (int k = 0; k < 50; ++k) {
            // Corners and edges of the rectangle and range, and points inside.
            const double fx = k < 4 ? double(k & 1) : unit(rng),
                         fy = k < 4 ? double(k >> 1) : unit(rng);
            const double ft = k % 3 == 0 ? 0.0 : k % 3 == 1 ? 1.0 : unit(rng);
            const Ray ray = camera.rayThrough(x0 + fx * (x1 - x0), y0 + fy * (y1 - y0));
            const Vec3 p = ray.at(ta + ft * (tb - ta));
            bool in = true;
            for (int a = 0; a < 3; ++a) in = in && box.lo[a] <= p[a] && p[a] <= box.hi[a];
            if (in || outside++) continue;
            std::ostringstream s;
            s.precision(17);
            s << "trial " << trial << ": point (" << p.x << ", " << p.y << ", " << p.z << ") at t "
              << ta + ft * (tb - ta) << " outside [" << box.lo.x << ", " << box.hi.x << "] x ["
              << box.lo.y << ", " << box.hi.y << "] x [" << box.lo.z << ", " << box.hi.z << "]";
            first = s.str();
        }
    }
    INFO(first);
    REQUIRE(outside == 0);
}

TEST_CASE("a pixel's beam start lies before every surface its rays meet", "[beams]") {
    for (const char* text : {kGyroidBall, kBarth}) {
        const Scene scene = compiled(text);
        const int width = 96, height = 72;
        const Camera camera(scene.camera, width, height);
        const PrimaryBeams beams(camera, scene.objects);
        REQUIRE(beams.enabled());
        const SceneGeometry geometry(scene.objects);
        TraceContext ctx;
        ctx.relTolerance = 1e-9;
        std::mt19937_64 rng(3);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        BeamStats stats;
        int checked = 0, late = 0, moved = 0;
        std::string first;
        for (int y0 = 0; y0 < height; y0 += 16)
            for (int x0 = 0; x0 < width; x0 += 16) {
                const int x1 = std::min(x0 + 16, width), y1 = std::min(y0 + 16, height);
                double start[16 * 16];
                beams.tileStarts(x0, y0, x1, y1, start, stats);
                for (int j = y0; j < y1; ++j)
                    for (int i = x0; i < x1; ++i) {
                        const double s = start[(j - y0) * (x1 - x0) + (i - x0)];
                        if (s > 0.0) ++moved;
                        // The centre and a random position in the pixel.
                        for (int k = 0; k < 2; ++k) {
                            const Ray ray = camera.rayThrough(i + (k ? unit(rng) : 0.5),
                                                              j + (k ? unit(rng) : 0.5));
                            const std::optional<Hit> hit = geometry.nearestHit(ray, 0.0, kInf, ctx);
                            ++checked;
                            if (!hit || hit->t > s) continue;
                            if (late++ == 0)
                                first = "pixel " + std::to_string(i) + "," + std::to_string(j) +
                                        ": start " + std::to_string(s) + " past the hit at " +
                                        std::to_string(hit->t);
                        }
                    }
            }
        INFO(first);
        REQUIRE(late == 0);
        CHECK(checked == 2 * width * height);
        CHECK(stats.pixels == uint64_t(width * height));
        // The beams do prove space empty in front of most pixels.
        CHECK(moved > width * height / 2);
    }
}

namespace {

/// Renders with beams off and on: the same hit or miss per pixel, depths within the
/// tolerance (the ray's search starts elsewhere, so its root polish may end an ulp away).
void requireSameFirstHits(const Scene& scene, int width, int height, int spp) {
    RenderOptions options;
    options.width = width;
    options.height = height;
    options.spp = spp;
    options.threads = 2;
    options.wantDepth = true;
    options.beams = BeamMode::Off;
    const RenderResult off = render(scene, options);
    options.beams = BeamMode::On;
    const RenderResult on = render(scene, options);
    REQUIRE(on.stats.beamsUsed);
    CHECK_FALSE(off.stats.beamsUsed);
    const double tolerance = off.stats.tolerance;
    int hitMismatches = 0, depthMismatches = 0;
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            const double a = off.depth.at(i, j, 0), b = on.depth.at(i, j, 0);
            if (std::isinf(a) != std::isinf(b)) {
                ++hitMismatches;
                continue;
            }
            // Depths are stored as float: allow its rounding on top of the tolerance.
            if (!std::isinf(a) && std::fabs(a - b) > (tolerance + 1e-6) * a) ++depthMismatches;
        }
    CHECK(hitMismatches == 0);
    CHECK(depthMismatches == 0);
    CHECK(on.stats.cameraRays == off.stats.cameraRays);
}

}  // namespace

TEST_CASE("renders with camera beams give the first hits of renders without", "[beams]") {
    SECTION("the gyroid ball, one and four samples per pixel") {
        const Scene scene = compiled(kGyroidBall);
        requireSameFirstHits(scene, 96, 72, 1);
        requireSameFirstHits(scene, 48, 36, 4);
    }
    SECTION("Barth's sextic") { requireSameFirstHits(compiled(kBarth), 96, 72, 1); }
    SECTION("every model in models/") {
        const std::filesystem::path models = std::filesystem::path(KERF_SOURCE_DIR) / "models";
        int checked = 0;
        for (const auto& entry : std::filesystem::directory_iterator(models)) {
            if (entry.path().extension() != ".kerf") continue;
            DiagnosticSink sink;
            AssetCache assets;
            std::optional<Scene> scene = compileFile(entry.path().string(), sink, assets);
            INFO(entry.path().filename().string() << sink.format());
            REQUIRE(scene.has_value());
            // Beams start rays at the eye, so a lens turns them off (the showcase has one):
            // compare the model's geometry through the pinhole.
            scene->camera.aperture = 0.0;
            const Camera camera(scene->camera, 64, 48);
            if (!PrimaryBeams(camera, scene->objects).enabled()) continue;  // eye inside bounds
            requireSameFirstHits(*scene, 64, 48, 1);
            ++checked;
        }
        CHECK(checked >= 3);
    }
}

TEST_CASE("the default rule turns beams on for implicit scenes only", "[beams]") {
    OctreeOptions octree;
    octree.footprintPerDistance = 2.0 * std::tan(0.5 * 35.0 * 3.14159265358979323846 / 180.0) / 600;
    const Scene ball = compiled(kGyroidBall);
    octree.eye = ball.camera.eye;
    CHECK(beamsPay(ball.objects, octree));
    // A closed-form object beside it: its rays are cheap, slices would cost more than they save.
    const Scene mixed =
        compiled(std::string(kGyroidBall) + "object box { min <4, 0, 0> max <5, 1, 1> };");
    CHECK_FALSE(beamsPay(mixed.objects, octree));
    // The eye inside the ball's bounds: nothing in front of it to prove empty.
    octree.eye = Vec3(0.0, 3.0, 0.0);
    CHECK_FALSE(beamsPay(ball.objects, octree));
}
