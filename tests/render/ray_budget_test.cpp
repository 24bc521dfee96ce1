/// @file tests/render/ray_budget_test.cpp
/// @brief The work per camera ray is bounded whatever the weights (render/whitted_integrator.h):
/// the budget's split, a glass whose weights exceed the language's policy (built through the API,
/// which does not check them) in a mirror box finishing with a bounded ray count, and a mirror box
/// that the language accepts (reflect 1, max_depth 1000) tracing every bounce uncut.
#include "lang/compile.h"
#include "render/whitted_integrator.h"
#include "render_test_util.h"

#include <catch2/catch.hpp>

using namespace kerf;
using namespace kerf::test;

TEST_CASE("splitRayBudget: in proportion to the weights, never more than the budget") {
    const RayBudgetSplit even = splitRayBudget(100, 0.5, 0.5);
    CHECK(even.reflect == 50);
    CHECK(even.refract == 50);
    const RayBudgetSplit skew = splitRayBudget(1000, 0.04, 0.96);
    CHECK(skew.reflect == 40);
    CHECK(skew.refract == 960);
    CHECK(splitRayBudget(7, 1.0, 0.0).reflect == 7);
    CHECK(splitRayBudget(7, 1e-4, 0.3).reflect == 0);  // below kMinRayWeight
    CHECK(splitRayBudget(7, 1e-4, 0.3).refract == 7);
    CHECK(splitRayBudget(0, 1.0, 1.0).reflect + splitRayBudget(0, 1.0, 1.0).refract == 0);
    for (const double w : {kInf, std::nan(""), 1e300}) {
        const RayBudgetSplit s = splitRayBudget(9, w, w);
        CHECK(s.reflect + s.refract <= 9);
    }
}

TEST_CASE(
    "render: a glass with transmit 1 reflect 1 in a mirror box at depth 1000 finishes within the "
    "budget") {
    // Every hit on the ball sends two rays on and the mirror walls bring both back, so the
    // tree would hold ~2^1000 rays (the earlier code never finished); the budget bounds it.
    Scene scene;
    Material glass = blackMaterial();
    glass.transmit = 1;
    glass.reflect = 1;  // past the policy: each hit passes on more light than arrives
    glass.ior = 1.5;
    Material mirror = blackMaterial();
    mirror.reflect = 1;
    addObject(scene, makeSphere(Vec3(0.0), 1.0), addMaterial(scene, glass));
    addObject(scene,
              makeBoolean(BoolOp::Difference,
                          {makeBox(Vec3(-4.0), Vec3(4.0)), makeBox(Vec3(-3.0), Vec3(3.0))}),
              addMaterial(scene, mirror));
    Light light;
    light.position = Vec3(1.5, 2.5, -2);
    light.power = 100;
    scene.lights.push_back(light);
    scene.camera.eye = Vec3(0.2, 0.3, -2.5);
    scene.settings.maxDepth = 1000;
    const RenderResult r = render(scene, smallImage(2, 2));
    const uint64_t secondary = r.stats.reflectionRays + r.stats.refractionRays;
    INFO("secondary rays " << secondary << " for " << r.stats.cameraRays << " camera rays");
    CHECK(secondary <= r.stats.cameraRays * kRayBudget);
    CHECK(secondary > r.stats.cameraRays * 1000);  // it did branch: more than one chain per ray
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i)
            for (int k = 0; k < 3; ++k) CHECK(std::isfinite(r.color.at(i, j, k)));
}

TEST_CASE("render: a mirror box with reflect 1 traces every bounce to max_depth 1000") {
    DiagnosticSink sink;
    const auto scene = compileString(R"(
        material m { color <1, 1, 1> reflect 1 ambient 0.1 }
        camera { eye <0, 0, 0> look_at <0.3, 0.2, 1> }
        light point { at <0, 0.5, 0> power 10 }
        render { max_depth 1000 }
        object difference { box { min <-2, -2, -2> max <2, 2, 2> } box { min <-1, -1, -1> max <1, 1, 1> } } material m;
    )",
                                     "mirror.kerf", sink);
    INFO(sink.format());
    REQUIRE(scene);
    const RenderResult r = render(*scene, smallImage(2, 2));
    CHECK(r.stats.reflectionRays == r.stats.cameraRays * 1000);
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i)
            for (int k = 0; k < 3; ++k) CHECK(std::isfinite(r.color.at(i, j, k)));
}
