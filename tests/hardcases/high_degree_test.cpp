// High-degree surfaces: tori with R/r from 1.01 to 1000 through SceneGeometry::nearestHit under
// rotation and scale (tests/csg/torus_test.cpp checks the untransformed spans), and two
// implicits of degree 4 and 6 (the tangle cube and Barth's sextic): every hit lies on its
// surface to the tolerance (|f(p)| / |∇f(p)·d̂| ≤ 2·tolerance·t·|d|) and hit or miss agrees with
// dense long-double sampling of the implicit with bisection, except where that sampling cannot
// resolve the feature.
#include "util/torus_reference.h"

#include <catch2/catch.hpp>

#include <cstdio>

using namespace kerf;
using namespace kerf::test;

namespace {

/// The golden ratio, as Barth's sextic needs it.
constexpr double kPhi = 1.6180339887498948482;

/// (1 + 2φ)(x² + y² + z² − 1)² − 4(φ²x² − y²)(φ²y² − z²)(φ²z² − x²): Barth's sextic with
/// the sign that makes the solid the bounded part near the unit sphere (with the usual sign,
/// ≤ 0 holds almost everywhere in the box and the test would mostly hit its faces).
ExprId barthSextic(ExprGraph& g) {
    const ExprId x2 = g.unary(Op::Square, g.x()), y2 = g.unary(Op::Square, g.y()),
                 z2 = g.unary(Op::Square, g.z());
    const ExprId p2 = g.constant(kPhi * kPhi);
    auto factor = [&](ExprId a, ExprId b) {
        return g.binary(Op::Sub, g.binary(Op::Mul, p2, a), b);
    };
    const ExprId product =
        g.binary(Op::Mul, g.binary(Op::Mul, factor(x2, y2), factor(y2, z2)), factor(z2, x2));
    const ExprId s =
        g.binary(Op::Sub, g.binary(Op::Add, g.binary(Op::Add, x2, y2), z2), g.constant(1.0));
    return g.binary(Op::Sub, g.binary(Op::Mul, g.constant(1 + 2 * kPhi), g.unary(Op::Square, s)),
                    g.binary(Op::Mul, g.constant(4.0), product));
}

/// x⁴ − 5x² + y⁴ − 5y² + z⁴ − 5z² + 11.8
ExprId tangleCube(ExprGraph& g) {
    auto term = [&](ExprId v) {
        return g.binary(Op::Sub, g.powInt(v, 4),
                        g.binary(Op::Mul, g.constant(5.0), g.unary(Op::Square, v)));
    };
    return g.binary(Op::Add,
                    g.binary(Op::Add, g.binary(Op::Add, term(g.x()), term(g.y())), term(g.z())),
                    g.constant(11.8));
}

}  // namespace

TEST_CASE("SceneGeometry::nearestHit on rotated and scaled tori, R/r from 1.01 to 1000") {
    Random rng(501);
    for (double ratio : {1.01, 2.0, 10.0, 100.0, 1000.0}) {
        for (double tolerance : {1e-6, 1e-9, 1e-12}) {
            const double r = 0.5, R = ratio * r, s = 0.37;
            const Affine map = Affine::translate(Vec3(0.2, -0.3, 0.1))
                                   .after(Affine::rotateDegrees(Vec3(21, -34, 55)))
                                   .after(Affine::scale(Vec3(s)));
            const SceneGeometry scene({makeTransform(makeTorus(R, r), map)});
            TraceContext ctx;
            ctx.relTolerance = tolerance;
            int hits = 0, tangent = 0;
            LD worst = 0;
            for (int i = 0; i < 300; ++i) {
                // Local rays: from outside toward a point near the tube or anywhere in the box.
                const double S = R + r;
                const Vec3 lo = rng.unitVector() * (S * rng.uniform(1.5, 3.0));
                const double phi = rng.uniform(0, 6.283185307179586);
                const Vec3 target =
                    i % 2
                        ? Vec3(R * std::cos(phi), 0.0, R * std::sin(phi)) + rng.inBall() * (1.2 * r)
                        : Vec3(rng.uniform(-S, S), rng.uniform(-r, r), rng.uniform(-S, S));
                const Ray world{map.point(lo), map.vector(target - lo)};
                // The reference sees the world ray mapped back in long double.
                const glm::tmat3x3<LD> back = glm::inverse(glm::tmat3x3<LD>(map.linear));
                const LV3 o = back * (ld(world.origin) - ld(map.offset)), d = back * ld(world.dir);
                const TorusReference ref = torusReference(o, d, R, r);
                const auto hit = scene.nearestHit(world, 0.0, kInf, ctx);
                CAPTURE(ratio, tolerance, i);
                if (ref.nearTangent && bool(hit) != !ref.crossings.empty()) {
                    ++tangent;
                    continue;
                }
                REQUIRE(bool(hit) == !ref.crossings.empty());
                if (!hit) continue;
                ++hits;
                const LD e = relativeError(hit->t, ref.crossings.front());
                worst = std::max(worst, e / tolerance);
                // Root-found: the requested tolerance, plus rounding of the mapped ray.
                CHECK(e <= tolerance + 64 * kUlp * ratio);
            }
            std::printf(
                "torus R/r %g tol %.0e: %d hits, %d tangent, worst error %.3g of the tolerance\n",
                ratio, tolerance, hits, tangent, double(worst));
            CHECK(hits > 60);
            CHECK(tangent <= 3);
        }
    }
}

TEST_CASE(
    "Implicit quartic and sextic: hits on the surface, hit/miss as dense long-double sampling") {
    Random rng(502);
    struct Shape {
        const char* name;
        ExprId (*build)(ExprGraph&);
        Bounds3 bound;
    };
    for (const Shape& shape : {Shape{"tangle cube", tangleCube, {Vec3(-2.6), Vec3(2.6)}},
                               Shape{"Barth sextic", barthSextic, {Vec3(-1.6), Vec3(1.6)}}}) {
        for (double tolerance : {1e-6, 1e-10}) {
            ExprGraph g;
            const ExprId root = shape.build(g);
            const auto tape = Tape::compile(g, root);
            const NodePtr solid = makeImplicit(tape, shape.bound);
            const SceneGeometry scene({solid});
            TraceContext ctx;
            ctx.relTolerance = tolerance;
            int hits = 0, unresolved = 0, onBox = 0;
            for (int i = 0; i < 200; ++i) {
                const double size = shape.bound.hi.x;
                const Vec3 o = rng.unitVector() * (3.0 * size);
                const Ray ray{o, (rng.inBall() * size - o) * rng.logUniform(0.3, 3)};
                LD t0, t1, tRef = 0;
                const bool inBounds = boundsRange(*solid, ray, t0, t1);
                const SampledReference ref =
                    inBounds ? sampledReference(*solid, ray, t0, t1, 4000) : SampledReference{};
                const bool refHit = ref.firstHit(tRef);
                const auto hit = scene.nearestHit(ray, 0.0, kInf, ctx);
                CAPTURE(shape.name, tolerance, i);
                if (bool(hit) != refHit) {
                    // Only a feature thinner than two samples may escape the sampling.
                    SpanList spans;
                    solid->spans(ray, 0.0, kInf, ctx, spans);
                    REQUIRE(hit);
                    REQUIRE(!spans.empty());
                    CHECK(spans[0].out.t - spans[0].in.t <= 2 * double(ref.step));
                    ++unresolved;
                    continue;
                }
                if (!hit) continue;
                ++hits;
                CHECK(relativeError(hit->t, tRef) <= 2 * tolerance + 1e-15);
                const Vec3 p = ray.at(hit->t);
                const Vec3 q = glm::abs(p);
                const bool faceHit = std::max({q.x, q.y, q.z}) >= size * (1 - 1e-12);
                if (faceHit) {
                    ++onBox;
                    continue;
                }
                // On the surface: |f| over its rate of change along the ray within 2·tol·t.
                Vec3 grad;
                const double f = tape->evalGradient(p, grad);
                const double slope = std::fabs(glm::dot(grad, ray.dir));
                CHECK(std::fabs(f) <=
                      2 * tolerance * hit->t * slope + 1e-13 * glm::length(grad) * size);
            }
            std::printf(
                "%s tol %.0e: %d hits (%d on the bounding box), %d unresolved by sampling\n",
                shape.name, tolerance, hits, onBox, unresolved);
            CHECK(hits > 60);
            CHECK(unresolved <= 2);
        }
    }
}
