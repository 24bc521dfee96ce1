// Scale invariance through the whole pipeline: one scene (a CSG of sphere, box and cylinder, a
// torus, a floor, camera and light) scaled by 1e-6, 1 and 1e6, camera included, gives the same
// hit/miss image and the same depths to 1e-9 relative; the same scene moved 1e6 away from the
// origin, with the error that costs measured and bounded. (tests/render/render_test.cpp checks
// the colour image of a ball scene at these scales; tests/csg/primitive_precision_test.cpp the
// primitives' spans.)
#include "render/camera.h"
#include "render/render.h"
#include "render/render_test_util.h"
#include "util/oracles.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <vector>

using namespace kerf;
using namespace kerf::test;

namespace {

constexpr int kW = 48, kH = 36;
/// Explicit and tight: the torus is root-found, and its depth may differ by the tolerance.
constexpr double kTolerance = 1e-12;

/// The scene scaled by s about the origin, then moved by `shift` (camera and light too).
Scene makeScene(double s, const Vec3& shift) {
    Scene scene;
    const Affine place = Affine::translate(shift).after(Affine::scale(Vec3(s)));
    const NodePtr csg = makeBoolean(
        BoolOp::Difference,
        {makeBoolean(BoolOp::Union, {makeSphere(Vec3(0.0, 0.9, 0.0), 0.9),
                                     makeBox(Vec3(-1.2, 0.0, -0.6), Vec3(0.2, 0.8, 0.6))}),
         makeCylinder(Vec3(-0.4, 0.4, -1.0), Vec3(-0.4, 0.4, 1.0), 0.3)});
    addObject(scene, makeTransform(csg, place), 0);
    addObject(
        scene,
        makeTransform(makeTransform(makeTorus(0.6, 0.2), Affine::translate(Vec3(1.4, 0.2, 0.3))),
                      place),
        0);
    // The floor y ≤ 0 moved: n·p ≤ n·shift.
    addObject(scene, makeHalfSpace(Vec3(0, 1, 0), shift.y), 0);
    Light light;
    light.position = place.point(Vec3(2.0, 5.0, -3.0));
    light.power = 300.0 * s * s;
    scene.lights.push_back(light);
    scene.camera.eye = place.point(Vec3(0.5, 2.2, -5.0));
    scene.camera.lookAt = place.point(Vec3(0.2, 0.5, 0.0));
    scene.camera.fovDegrees = 40;
    return scene;
}

struct Comparison {
    int hitMissDiffers = 0, compared = 0;
    double worstDouble = 0, worstFilm = 0;
};

/// Depth of `b` divided by `scale` against `a`, pixel by pixel: from the film (float) and
/// from nearestHit on each camera ray (double).
Comparison compareScenes(const Scene& a, const Scene& b, double scale) {
    RenderOptions options = smallImage(kW, kH);
    options.wantDepth = true;
    options.tolerance = kTolerance;
    const RenderResult ra = render(a, options), rb = render(b, options);
    const SceneGeometry ga(a.objects), gb(b.objects);
    const Camera ca(a.camera, kW, kH), cb(b.camera, kW, kH);
    TraceContext ctx;
    ctx.relTolerance = kTolerance;
    Comparison c;
    for (int j = 0; j < kH; ++j)
        for (int i = 0; i < kW; ++i) {
            const float da = ra.depth.at(i, j, 0), db = rb.depth.at(i, j, 0);
            if (std::isinf(da) != std::isinf(db)) {
                ++c.hitMissDiffers;
                continue;
            }
            if (std::isinf(da)) continue;
            ++c.compared;
            c.worstFilm = std::max(c.worstFilm, std::fabs(double(db) / scale - da) / da);
            const Ray rayA = ca.rayThrough(i + 0.5, j + 0.5),
                      rayB = cb.rayThrough(i + 0.5, j + 0.5);
            const auto ha = ga.nearestHit(rayA, 0.0, kInf, ctx),
                       hb = gb.nearestHit(rayB, 0.0, kInf, ctx);
            REQUIRE(ha);
            REQUIRE(hb);
            c.worstDouble = std::max(c.worstDouble, std::fabs(hb->t / scale - ha->t) / ha->t);
        }
    return c;
}

}  // namespace

TEST_CASE("render: one scene at scales 1e-6, 1 and 1e6, camera included") {
    const Scene unit = makeScene(1.0, Vec3(0.0));
    for (double s : {1e-6, 1e6}) {
        const Comparison c = compareScenes(unit, makeScene(s, Vec3(0.0)), s);
        std::printf(
            "scale %.0e: %d hits compared, hit/miss differs at %d, relative depth "
            "difference %.3g (double), %.3g (film)\n",
            s, c.compared, c.hitMissDiffers, c.worstDouble, c.worstFilm);
        INFO("scale " << s);
        CHECK(c.hitMissDiffers == 0);
        CHECK(c.compared > kW * kH / 2);
        CHECK(c.worstDouble <= 1e-9);
        // The film stores floats: each side is rounded once to 2^-24 relative.
        CHECK(c.worstFilm <= 0x1p-23);
    }
}

TEST_CASE("render: the same scene moved 1e6 away from the origin") {
    // Measured (48×36, tolerance 1e-12): no hit/miss difference; relative depth difference in
    // double 1.0e-10 for the shift along x, 3.7e-10 for the oblique one (the film's floats do
    // not see it). Why: every coordinate near 1e6 carries ulp(1e6) = 1.2e-10 of absolute
    // rounding, and the eye, the look-at point, each transform's offset and the hit point
    // o + t·d each add some; the scene is ~1 across and the hits ~5 away, and the errors
    // are amplified by grazing angles on the curved surfaces (depth error ≈ position error /
    // cos θ). The bound, 1e-9, is 2.7× the worst measured: translation by D costs about
    // ulp(D)/size relative, unlike pure scaling (1e-14 above), which is exact in binary.
    const Scene unit = makeScene(1.0, Vec3(0.0));
    for (const Vec3& shift : {Vec3(1e6, 0.0, 0.0), Vec3(-7e5, 4e5, 6e5)}) {
        const Comparison c = compareScenes(unit, makeScene(1.0, shift), 1.0);
        std::printf(
            "shift (%g, %g, %g): %d hits compared, hit/miss differs at %d, relative depth "
            "difference %.3g (double), %.3g (film)\n",
            shift.x, shift.y, shift.z, c.compared, c.hitMissDiffers, c.worstDouble, c.worstFilm);
        CHECK(c.hitMissDiffers == 0);
        CHECK(c.compared > kW * kH / 2);
        CHECK(c.worstDouble <= 1e-9);
        CHECK(c.worstFilm <= 0x1p-23 + 1e-9);
    }
}
