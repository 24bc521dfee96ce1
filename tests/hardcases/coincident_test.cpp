// Coincident faces, at scales 1e-6, 1 and 1e6: abutting boxes in a union leave no seam (one
// span, and a glass union renders like the single box), a difference whose cutter shares faces
// with the body leaves a clean hole (whole depth images against the analytic first hit), and
// the intersection or union of identical solids is the solid, span for span. The straight-down
// hole case for spans alone is in tests/csg/boolean_test.cpp.
#include "render/camera.h"
#include "render/render.h"
#include "render/render_test_util.h"
#include "util/oracles.h"

#include <catch2/catch.hpp>

#include <functional>
#include <vector>

using namespace kerf;
using namespace kerf::test;

namespace {

constexpr double kScales[] = {1e-6, 1.0, 1e6};

/// Spans with every field compared: t exactly, normals as unit vectors to 1e-15.
void checkSameSpans(const SpanList& got, const SpanList& expected) {
    REQUIRE(got.size() == expected.size());
    for (int k = 0; k < got.size(); ++k) {
        CHECK(got[k].in.t == expected[k].in.t);
        CHECK(got[k].out.t == expected[k].out.t);
        CHECK(glm::length(unit(got[k].in.normal) - unit(expected[k].in.normal)) <= 1e-15);
        CHECK(glm::length(unit(got[k].out.normal) - unit(expected[k].out.normal)) <= 1e-15);
    }
}

/// A random ray from a shell around the scaled unit cube toward a point inside it.
Ray randomRay(Random& rng, double s) {
    const Vec3 o = s * (Vec3(0.5) + rng.uniform(3, 6) * rng.unitVector());
    const Vec3 target = s * (Vec3(0.5) + 0.6 * rng.inBall());
    return {o, (target - o) * rng.logUniform(0.1, 10)};
}

}  // namespace

TEST_CASE("Union of abutting boxes: one span across the shared face") {
    Random rng(201);
    for (double s : kScales) {
        // The cube [0, 1]³ cut at x = 0.5 and at y = 0.375 into three boxes sharing faces.
        const NodePtr whole = makeBox(Vec3(0.0), s * Vec3(1.0));
        const NodePtr parts =
            makeBoolean(BoolOp::Union, {makeBox(Vec3(0.0), s * Vec3(0.5, 1.0, 1.0)),
                                        makeBox(s * Vec3(0.5, 0.0, 0.0), s * Vec3(1.0, 0.375, 1.0)),
                                        makeBox(s * Vec3(0.5, 0.375, 0.0), s * Vec3(1.0))});
        TraceContext ctx;
        int crossing = 0;
        for (int i = 0; i < 2000; ++i) {
            const Ray ray = randomRay(rng, s);
            SpanList a, b;
            whole->spans(ray, 0.0, kInf, ctx, a);
            parts->spans(ray, 0.0, kInf, ctx, b);
            CAPTURE(s, i);
            checkSameSpans(b, a);
            if (!a.empty()) {
                const double x0 = ray.at(a[0].in.t).x, x1 = ray.at(a[0].out.t).x;
                crossing += (x0 - 0.5 * s) * (x1 - 0.5 * s) < 0;
            }
        }
        CHECK(crossing > 300);
    }
}

TEST_CASE("render: a glass union of abutting boxes renders like the single box") {
    for (double s : kScales) {
        auto sceneWith = [s](NodePtr solid) {
            Scene scene;
            Material glass = blackMaterial();
            glass.transmit = 0.9;
            glass.reflect = 0.05;
            glass.ior = 1.5;
            glass.absorb = Vec3(0.3, 0.1, 0.0) / s;  // the same optical depth at every scale
            Material floor = blackMaterial();
            floor.diffuse = 0.8;
            floor.color = Vec3(0.9, 0.6, 0.3);
            // One object each, so the comparison does not involve the nearest-of-objects search.
            addObject(scene,
                      makeBoolean(BoolOp::Union,
                                  {makeMaterial(std::move(solid), addMaterial(scene, glass)),
                                   makeMaterial(makeHalfSpace(Vec3(0, 1, 0), -0.01 * s),
                                                addMaterial(scene, floor))}),
                      0);
            Light light;
            light.position = s * Vec3(1.0, 4.0, -2.0);
            light.power = 200.0 * s * s;
            scene.lights.push_back(light);
            scene.background = Vec3(0.2, 0.3, 0.6);
            scene.camera.eye = s * Vec3(1.9, 1.6, -2.6);
            scene.camera.lookAt = s * Vec3(0.5, 0.4, 0.5);
            scene.settings.maxDepth = 6;
            return scene;
        };
        const Scene single = sceneWith(makeBox(Vec3(0.0), s * Vec3(1.0)));
        const Scene split = sceneWith(
            makeBoolean(BoolOp::Union, {makeBox(Vec3(0.0), s * Vec3(0.5, 1.0, 1.0)),
                                        makeBox(s * Vec3(0.5, 0.0, 0.0), s * Vec3(1.0, 0.5, 1.0)),
                                        makeBox(s * Vec3(0.5, 0.5, 0.0), s * Vec3(1.0))}));
        RenderOptions options = smallImage(48, 36);
        options.tolerance = 1e-9;
        const RenderResult a = render(single, options), b = render(split, options);
        double worst = 0;
        for (size_t k = 0; k < a.color.pixels.size(); ++k)
            worst = std::max(worst, double(std::fabs(a.color.pixels[k] - b.color.pixels[k])));
        INFO("scale " << s << " worst pixel difference " << worst);
        CHECK(worst <= 1e-6);
        CHECK(a.stats.refractionRays == b.stats.refractionRays);
        CHECK(a.stats.refractionRays > 500);
    }
}

TEST_CASE("render: a cutter sharing faces with the body leaves no speckle") {
    // The unit cube minus a square shaft [0.25, 0.75] × [0, 1] × [0.25, 0.75] exactly as tall
    // as the cube (no 1.001 trick), seen from above at an angle. Analytic first hit in long
    // double: the body's entry unless it lies in the closed cutter span, else the cutter's exit
    // if that is still inside the body, else a miss.
    Random rng(202);
    for (double s : kScales) {
        const Vec3 lo(0.0), hi = s * Vec3(1.0), clo = s * Vec3(0.25, 0.0, 0.25),
                            chi = s * Vec3(0.75, 1.0, 0.75);
        Scene scene;
        addObject(scene, makeBoolean(BoolOp::Difference, {makeBox(lo, hi), makeBox(clo, chi)}), 0);
        scene.camera.eye = s * Vec3(0.55, 3.0, 0.3);
        scene.camera.lookAt = s * Vec3(0.5, 0.0, 0.5);
        scene.camera.up = Vec3(0, 0, 1);
        scene.camera.fovDegrees = 30;
        const int W = 48, H = 48;
        RenderOptions options = smallImage(W, H);
        options.wantDepth = true;
        // Explicit: the default (1/8 pixel, 1.4e-3 here) rightly drops the 1.3e-3-wide sliver
        // of wall some rays graze (pixel 16,30), which is the tolerance policy, not a seam.
        options.tolerance = 1e-9;
        const RenderResult r = render(scene, options);
        const Camera camera(scene.camera, W, H);
        int throughHole = 0, mismatches = 0;
        for (int j = 0; j < H; ++j)
            for (int i = 0; i < W; ++i) {
                const Ray ray = camera.rayThrough(i + 0.5, j + 0.5);
                const auto body = boxOracle(ray, lo, hi), cut = boxOracle(ray, clo, chi);
                LD t = INFINITY;
                if (body) {
                    if (!cut || body->first < cut->first || body->first > cut->second)
                        t = body->first;
                    else if (cut->second < body->second)
                        t = cut->second;
                    else
                        ++throughHole;
                }
                const float expected =
                    std::isinf(t) ? INFINITY : float(t * glm::length(ld(ray.dir)));
                const float depth = r.depth.at(i, j, 0);
                const bool same =
                    depth == expected ||
                    std::fabs(depth - expected) <= std::nextafter(expected, INFINITY) - expected;
                if (!same) {
                    ++mismatches;
                    FAIL_CHECK("scale " << s << " pixel " << i << "," << j << " depth " << depth
                                        << " expected " << expected);
                }
            }
        CHECK(mismatches == 0);
        CHECK(throughHole > 100);
    }
}

TEST_CASE("Intersection and union of identical solids equal the solid") {
    Random rng(203);
    for (double s : kScales) {
        const std::vector<std::function<NodePtr()>> makers{
            [s] { return makeSphere(s * Vec3(0.5, 0.4, 0.6), s * 0.45); },
            [s] { return makeBox(s * Vec3(0.1, 0.2, 0.0), s * Vec3(0.9, 0.7, 1.0)); },
            [s] { return makeCylinder(s * Vec3(0.2, 0.1, 0.3), s * Vec3(0.8, 0.9, 0.6), s * 0.3); },
            [s] {
                return makeCone(s * Vec3(0.2, 0.1, 0.3), s * Vec3(0.8, 0.9, 0.6), s * 0.4, s * 0.1);
            },
        };
        TraceContext ctx;
        for (const auto& make : makers) {
            const NodePtr a = make(), twin = make();  // equal geometry, distinct primitives
            const NodePtr shared = makeBoolean(BoolOp::Intersection, {a, a});
            const NodePtr twins = makeBoolean(BoolOp::Intersection, {a, twin});
            const NodePtr unionTwins = makeBoolean(BoolOp::Union, {twin, a});
            const NodePtr minusTwin = makeBoolean(BoolOp::Difference, {a, twin});
            for (int i = 0; i < 500; ++i) {
                const Ray ray = randomRay(rng, s);
                SpanList ref, x;
                a->spans(ray, 0.0, kInf, ctx, ref);
                for (const NodePtr& n : {shared, twins, unionTwins}) {
                    n->spans(ray, 0.0, kInf, ctx, x);
                    CAPTURE(s, i);
                    checkSameSpans(x, ref);
                }
                // And A − A is empty: no sliver survives.
                minusTwin->spans(ray, 0.0, kInf, ctx, x);
                CHECK(x.empty());
            }
        }
    }
}
