// Self-intersection: a secondary ray spawned from a hit as render/ray_offset.h does (origin moved
// past the hit's error bound along the side it leaves by) never meets its own surface again near
// where it left, at scales 1e-6, 1 and 1e6, on spheres, tori, boxes and a gyroid implicit,
// including rays leaving at grazing angles. And a mirror sphere and torus over a floor render
// the same image at every scale. (tests/render/render_test.cpp renders a mirror ball scene at
// these scales; here the spawn rule itself is tested on thousands of hits and on root-found
// surfaces.)
#include "render/ray_offset.h"
#include "render/render.h"
#include "render/render_test_util.h"
#include "util/oracles.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <vector>

using namespace kerf;
using namespace kerf::test;

namespace {

/// A direction on the side `n` points to, at an angle from the tangent plane whose sine is
/// log-uniform in [1e-3, 1]: many grazing departures.
Vec3 leavingDirection(Random& rng, const Vec3& n) {
    const Vec3 tangent = rng.perpendicular(n);
    const double sine = rng.logUniform(1e-3, 1.0);
    return unit(sine * n + std::sqrt(1 - sine * sine) * tangent);
}

NodePtr gyroidBall(double s) {
    // The gyroid of period 2π·s inside a box of half-size 2.5·s.
    ExprGraph h;
    auto v = [&](ExprId x) { return h.binary(Op::Mul, x, h.constant(1.0 / s)); };
    auto term = [&](ExprId a, ExprId b) {
        return h.binary(Op::Mul, h.unary(Op::Sin, v(a)), h.unary(Op::Cos, v(b)));
    };
    const ExprId f = h.binary(Op::Add, h.binary(Op::Add, term(h.x(), h.y()), term(h.y(), h.z())),
                              term(h.z(), h.x()));
    return makeImplicit(Tape::compile(h, f), Bounds3{Vec3(-2.5 * s), Vec3(2.5 * s)});
}

}  // namespace

TEST_CASE("Secondary rays from a hit never re-hit their own surface nearby, at every scale") {
    Random rng(601);
    for (double s : {1e-6, 1.0, 1e6}) {
        const std::vector<std::pair<const char*, NodePtr>> solids{
            {"sphere", makeSphere(s * Vec3(0.3, -0.2, 0.1), s * 1.3)},
            {"torus",
             makeTransform(makeTorus(s * 1.2, s * 0.4), Affine::rotateDegrees(Vec3(30, 10, -20)))},
            {"box", makeBox(s * Vec3(-1.1, -0.7, -0.9), s * Vec3(0.8, 1.2, 0.6))},
            {"gyroid", gyroidBall(s)},
        };
        for (const auto& [name, solid] : solids) {
            const SceneGeometry scene({solid});
            // The default render tolerance for a 480-row image at 40°: what secondary rays see.
            TraceContext ctx;
            ctx.relTolerance = defaultTolerance(480, 40);
            const double size = s * 2.5;
            int spawned = 0, rehits = 0;
            for (int i = 0; i < 500; ++i) {
                const Vec3 o = rng.unitVector() * (4.0 * size);
                const Ray ray{o, (rng.inBall() * size - o) * rng.logUniform(0.1, 10)};
                const auto hit = scene.nearestHit(ray, 0.0, kInf, ctx);
                if (!hit) continue;
                const Vec3 p = ray.at(hit->t);
                const double err = hitErrorBound(ray, hit->t, p, hit->relError);
                // The reflection side (toward the viewer) and the refraction side (through).
                const Vec3 front = glm::dot(hit->normal, ray.dir) < 0 ? hit->normal : -hit->normal;
                for (const Vec3& side : {front, -front}) {
                    const Ray next{offsetRayOrigin(p, side, err), leavingDirection(rng, side)};
                    const auto again = scene.nearestHit(next, 0.0, kInf, ctx);
                    ++spawned;
                    if (again && again->primitive == hit->primitive &&
                        again->t * glm::length(next.dir) < 1e-4 * size) {
                        ++rehits;
                        FAIL_CHECK(name << " scale " << s << ": re-hit at distance "
                                        << again->t * glm::length(next.dir) << " (error bound "
                                        << err << ")");
                    }
                }
            }
            INFO(name << " scale " << s);
            CHECK(rehits == 0);
            CHECK(spawned > 200);
        }
    }
}

TEST_CASE("render: a mirror sphere and a mirror torus over a floor look the same at every scale") {
    auto sceneAt = [](double s) {
        Scene scene;
        Material mirror = blackMaterial();
        mirror.reflect = 0.9;
        mirror.diffuse = 0.05;
        mirror.color = Vec3(0.9);
        Material floor = blackMaterial();
        floor.diffuse = 0.8;
        floor.ambient = 0.1;
        floor.color = Vec3(0.7, 0.6, 0.4);
        const int m = addMaterial(scene, mirror), f = addMaterial(scene, floor);
        // One object, so that only the spawn rule is under test.
        addObject(
            scene,
            makeBoolean(BoolOp::Union,
                        {makeMaterial(makeSphere(s * Vec3(-0.8, 1.0, 0.0), s * 1.0), m),
                         makeMaterial(makeTransform(makeTorus(s * 0.8, s * 0.3),
                                                    Affine::translate(s * Vec3(1.3, 0.3, -0.2))),
                                      m),
                         makeMaterial(makeHalfSpace(Vec3(0, 1, 0), 0.0), f)}),
            0);
        Light light;
        light.position = s * Vec3(2.0, 5.0, -3.0);
        light.power = 300.0 * s * s;
        scene.lights.push_back(light);
        scene.background = Vec3(0.3, 0.4, 0.6);
        scene.camera.eye = s * Vec3(0.0, 2.0, -6.0);
        scene.camera.lookAt = s * Vec3(0.2, 0.6, 0.0);
        scene.settings.maxDepth = 6;
        return scene;
    };
    const RenderResult unit = render(sceneAt(1.0), smallImage(48, 36));
    for (double s : {1e-6, 1e6}) {
        const RenderResult other = render(sceneAt(s), smallImage(48, 36));
        double worst = 0;
        for (size_t k = 0; k < unit.color.pixels.size(); ++k)
            worst =
                std::max(worst, double(std::fabs(unit.color.pixels[k] - other.color.pixels[k])));
        std::printf("mirror scene at scale %.0e: worst pixel difference %.3g\n", s, worst);
        INFO("scale " << s);
        CHECK(worst <= 1e-5);
        CHECK(other.stats.reflectionRays == unit.stats.reflectionRays);
        CHECK(other.stats.shadowRays == unit.stats.shadowRays);
    }
}
