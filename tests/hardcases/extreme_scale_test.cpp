// Scale invariance over the double range, through the language and the renderer: a primitive
// (sphere, box, cylinder, cone, torus, halfspace) written with `scale s` renders as the same
// primitive written with parameters scaled by s, and as the unit scene, for s = 1e±50 … 1e±300
// (camera scaled too); every pixel is finite. The depths are compared in double (nearestHit on each
// pixel's centre ray): the float film cannot hold 5e300. docs/robustness.md ("Values") states the
// bound.
#include "csg/bvh/scene_geometry.h"
#include "lang/compile.h"
#include "render/camera.h"
#include "render/render.h"
#include "render/render_test_util.h"

#include <catch2/catch.hpp>

#include <string>

using namespace kerf;
using namespace kerf::test;

namespace {

constexpr int kW = 24, kH = 18;
constexpr double kTolerance = 1e-12;

/// Relative difference allowed between the depths of the two spellings (and the unit scene
/// scaled): scaling by a power of ten is not exact in binary, so each input number is off by
/// half an ulp, and the camera and hit computations add a few ulps more.
constexpr double kDepthBound = 1e-12;

std::string camera(const std::string& s) {
    return "camera { eye <1.5 * " + s + ", 2 * " + s + ", -5 * " + s +
           "> look_at <0, 0, 0> fov 40 }\n"
           "light directional { direction <-1, -2, 1> }\n";
}

/// Each closed-form primitive written two ways at scale s.
std::string byScale(const std::string& solid, const std::string& s) {
    if (solid == "sphere") return "object sphere { radius 1 } scale " + s + ";\n";
    if (solid == "box")
        return "object box { min <-1, -0.5, -1> max <1, 0.5, 0.8> } rotate <0, 20, 0> scale " + s +
               ";\n";
    if (solid == "cone")
        return "object cone { from <0, -1, 0> to <0.3, 1, 0> radius1 1 radius2 0.2 } scale " + s +
               ";\n";
    if (solid == "torus")
        return "object torus { major 1 minor 0.4 } rotate <60, 0, 0> scale " + s + ";\n";
    if (solid == "halfspace")
        return "object halfspace { normal <0.1, 1, 0.3> offset -0.3 } scale " + s + ";\n";
    return "object cylinder { from <0, -1, 0> to <0.3, 1, 0> radius 0.6 } scale " + s + ";\n";
}

std::string byParameters(const std::string& solid, const std::string& s) {
    if (solid == "sphere") return "object sphere { radius " + s + " };\n";
    if (solid == "box")
        return "object box { min <-1 * " + s + ", -0.5 * " + s + ", -1 * " + s + "> max <" + s +
               ", 0.5 * " + s + ", 0.8 * " + s + "> } rotate <0, 20, 0>;\n";
    if (solid == "cone")
        return "object cone { from <0, -" + s + ", 0> to <0.3 * " + s + ", " + s + ", 0> radius1 " +
               s + " radius2 0.2 * " + s + " };\n";
    if (solid == "torus")
        return "object torus { major " + s + " minor 0.4 * " + s + " } rotate <60, 0, 0>;\n";
    if (solid == "halfspace")
        return "object halfspace { normal <0.1, 1, 0.3> offset -0.3 * " + s + " };\n";
    return "object cylinder { from <0, -" + s + ", 0> to <0.3 * " + s + ", " + s +
           ", 0> radius 0.6 * " + s + " };\n";
}

Scene compileModel(const std::string& text) {
    DiagnosticSink sink;
    const std::optional<Scene> scene = compileString(text, "scale.kerf", sink);
    INFO(text << sink.format());
    REQUIRE(scene);
    return *scene;
}

/// The pixel-centre hit distances (camera rays are unit length): -1 on a miss.
std::vector<double> depths(const Scene& scene) {
    const SceneGeometry geometry(scene.objects);
    const Camera cam(scene.camera, kW, kH);
    TraceContext ctx;
    ctx.relTolerance = kTolerance;
    std::vector<double> out;
    for (int j = 0; j < kH; ++j)
        for (int i = 0; i < kW; ++i) {
            const auto hit = geometry.nearestHit(cam.rayThrough(i + 0.5, j + 0.5), 0.0, kInf, ctx);
            out.push_back(hit ? hit->t : -1.0);
        }
    return out;
}

int nonFinitePixels(const Scene& scene) {
    RenderOptions options = smallImage(kW, kH);
    options.tolerance = kTolerance;
    const RenderResult r = render(scene, options);
    int bad = 0;
    for (int j = 0; j < kH; ++j)
        for (int i = 0; i < kW; ++i)
            for (int k = 0; k < 3; ++k) bad += !std::isfinite(r.color.at(i, j, k));
    return bad;
}

}  // namespace

TEST_CASE("render: scale s and parameters scaled by s agree from 1e-300 to 1e300") {
    for (const std::string solid : {"sphere", "box", "cylinder", "cone", "torus", "halfspace"}) {
        const std::vector<double> unit =
            depths(compileModel(camera("1") + byParameters(solid, "1")));
        int unitHits = 0;
        for (double t : unit) unitHits += t > 0;
        REQUIRE(unitHits > 40);
        for (const std::string s :
             {"1e50", "1e-50", "1e100", "1e-100", "1e150", "1e-150", "1e300", "1e-300"}) {
            INFO(solid << " at scale " << s);
            const double scale = std::stod(s);
            const Scene a = compileModel(camera(s) + byScale(solid, s));
            const Scene b = compileModel(camera(s) + byParameters(solid, s));
            const std::vector<double> da = depths(a), db = depths(b);
            int maskDiffers = 0;
            double worst = 0;
            for (size_t k = 0; k < unit.size(); ++k) {
                const bool hu = unit[k] > 0, ha = da[k] > 0, hb = db[k] > 0;
                maskDiffers += (hu != ha) + (hu != hb);
                if (hu && ha && hb) {
                    worst = std::max(worst, std::fabs(da[k] / scale - unit[k]) / unit[k]);
                    worst = std::max(worst, std::fabs(db[k] / scale - unit[k]) / unit[k]);
                }
            }
            CHECK(maskDiffers == 0);
            CHECK(worst <= kDepthBound);
            CHECK(nonFinitePixels(a) == 0);
            CHECK(nonFinitePixels(b) == 0);
        }
    }
}

TEST_CASE("render: a sphere of radius 1e308 centred at 1e308 gives finite pixels and hits") {
    const Scene scene = compileModel(
        "camera { eye <1e308, 0, -1.7e308> look_at <1e308, 0, 0> fov 60 }\n"
        "light directional { direction <-1, -2, 1> }\n"
        "object sphere { center <1e308, 0, 0> radius 1e308 };\n");
    CHECK(nonFinitePixels(scene) == 0);
    int hits = 0;
    for (double t : depths(scene)) hits += t > 0;
    CHECK(hits > kW * kH / 4);
}

TEST_CASE("render: scaling up to the edge of the double range matches the parameters") {
    // World radius 1e308 reached by a transform, against the same sphere written directly.
    const std::string view =
        "camera { eye <0, 0, -1.7e308> look_at <0, 0, 0> fov 60 }\n"
        "light directional { direction <-1, -2, 1> }\n";
    const Scene a = compileModel(view + "object sphere { radius 1e298 } scale 1e10;\n");
    const Scene b = compileModel(view + "object sphere { radius 1e308 };\n");
    const std::vector<double> da = depths(a), db = depths(b);
    int maskDiffers = 0, hits = 0;
    double worst = 0;
    for (size_t k = 0; k < da.size(); ++k) {
        maskDiffers += (da[k] > 0) != (db[k] > 0);
        if (da[k] > 0 && db[k] > 0) {
            ++hits;
            worst = std::max(worst, std::fabs(da[k] - db[k]) / db[k]);
        }
    }
    CHECK(hits > kW * kH / 4);
    CHECK(maskDiffers == 0);
    CHECK(worst <= kDepthBound);
    CHECK(nonFinitePixels(a) == 0);
    CHECK(nonFinitePixels(b) == 0);
}
