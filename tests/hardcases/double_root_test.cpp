// Double and near-double roots in implicits: f = (|p|² − 1)², a shell of zero thickness, gives
// no span wider than the tolerance at any tolerance or scale; two spheres touching at a point
// (closed forms in a union, and the implicit product of their forms, which has a double root
// at the contact) give one span through the point and two where the gap is wider than the
// tolerance; f = (|p|² − 1)² − ε, a shell of thickness ≈ √ε, is found whenever it is thicker
// than the tolerance. (tests/csg/implicit_test.cpp checks (|p|² − 1)² on 300 random rays at
// one tolerance.)
#include "util/shell_reference.h"

#include <catch2/catch.hpp>

#include <cstdio>

using namespace kerf;
using namespace kerf::test;

namespace {

/// (|p − c|² − r²) as an expression.
ExprId offsetSphere(ExprGraph& g, const Vec3& c, double r) {
    auto sq = [&](ExprId v, double k) {
        return g.unary(Op::Square, g.binary(Op::Sub, v, g.constant(k)));
    };
    return g.binary(
        Op::Sub,
        g.binary(Op::Add, g.binary(Op::Add, sq(g.x(), c.x), sq(g.y(), c.y)), sq(g.z(), c.z)),
        g.constant(r * r));
}

}  // namespace

TEST_CASE("Implicit::spans of (|p|² − r²)²: no span wider than the tolerance") {
    Random rng(401);
    for (double s : {1e-6, 1.0, 1e6}) {
        ExprGraph g;
        const NodePtr shell = makeImplicit(Tape::compile(g, g.unary(Op::Square, sphereExpr(g, s))),
                                           Bounds3{Vec3(-2 * s), Vec3(2 * s)});
        for (double tolerance : {1e-6, 1e-9, 1e-12}) {
            TraceContext ctx;
            ctx.relTolerance = tolerance;
            int widest = 0;
            for (int i = 0; i < 100; ++i) {
                // Through the sphere, grazing it, and from inside it.
                const Vec3 o = i % 3 == 2 ? s * 0.5 * rng.inBall() : s * 5.0 * rng.unitVector();
                const Vec3 target = i % 3 == 1 ? s * rng.perpendicular(o) : s * 0.9 * rng.inBall();
                const Ray ray{o, target - o};
                SpanList spans;
                shell->spans(ray, 0.0, kInf, ctx, spans);
                for (const Span& sp : spans) {
                    CAPTURE(s, tolerance, i);
                    CHECK(sp.out.t - sp.in.t <= tolerance * std::fabs(sp.out.t));
                    ++widest;
                }
                const SceneGeometry scene({shell});
                CHECK_FALSE(scene.nearestHit(ray, 0.0, kInf, ctx));
            }
            CHECK(widest == 0);
        }
    }
}

TEST_CASE("Two spheres touching at a point: one span through it") {
    // Centres (±1, 0, 0), radius 1: they touch at the origin.
    const Vec3 c1(-1, 0, 0), c2(1, 0, 0);
    ExprGraph g;
    const NodePtr closed = makeBoolean(BoolOp::Union, {makeSphere(c1, 1.0), makeSphere(c2, 1.0)});
    // g1·g2 ≤ 0 exactly where one factor is ≤ 0 (the interiors are disjoint): the union, with
    // a double root of the product at the contact along the line of centres.
    const NodePtr product = makeImplicit(
        Tape::compile(g, g.binary(Op::Mul, offsetSphere(g, c1, 1.0), offsetSphere(g, c2, 1.0))),
        Bounds3{Vec3(-2.5, -1.5, -1.5), Vec3(2.5, 1.5, 1.5)});
    Random rng(402);
    TraceContext ctx;
    ctx.relTolerance = 1e-10;
    SECTION("every non-tangent ray through the contact point gives one span") {
        for (int i = 0; i < 300; ++i) {
            Vec3 u = rng.unitVector();
            if (std::fabs(u.x) < 0.2) continue;  // too near the tangent plane x = 0
            const Ray ray{-5.0 * u, u};          // through the origin at t = 5
            // Enters one sphere, leaves the other: |o + t u − c|² = 1 with the origin on both.
            const LV3 lu = ld(u);
            auto far = [&](const Vec3& c) { return 5 + 2 * glm::dot(ld(c), lu); };  // second root
            const LD tIn = std::min(far(c1), far(c2)), tOut = std::max(far(c1), far(c2));
            for (const NodePtr& node : {closed, product}) {
                SpanList s;
                node->spans(ray, 0.0, kInf, ctx, s);
                const bool closedForm = node == closed;
                CAPTURE(i, closedForm, u.x, u.y, u.z);
                REQUIRE(s.size() == 1);
                const LD bound = closedForm ? 1e-12L : 2e-10L;
                CHECK(relativeError(s[0].in.t, tIn) <= bound);
                CHECK(relativeError(s[0].out.t, tOut) <= bound);
            }
        }
    }
    SECTION("in the tangent plane through the contact: touches only, no span") {
        // The rounded ray may pass a few ulps inside a sphere, where its honest chord is
        // 2·√(2·k·ulp)·r: spans up to that of k = 8 are the tangency's own uncertainty.
        const double graze = 2 * std::sqrt(16 * kUlp);
        for (int i = 0; i < 100; ++i) {
            const double phi = rng.uniform(0, 6.283185307179586);
            const Vec3 u(0.0, std::cos(phi), std::sin(phi));
            for (const NodePtr& node : {closed, product}) {
                SpanList s;
                node->spans(Ray{-3.0 * u, u}, 0.0, kInf, ctx, s);
                for (const Span& sp : s)
                    CHECK(sp.out.t - sp.in.t <= std::max(ctx.relTolerance * sp.out.t, graze));
            }
        }
    }
    SECTION(
        "along the line of centres offset by δ: a gap of δ² where it is wider than the tolerance") {
        for (double delta : {1e-2, 1e-3, 1e-4}) {
            const Ray ray{Vec3(-5, delta, 0), Vec3(1, 0, 0)};
            // Gap |x| ≤ 1 − √(1 − δ²) on each side of the origin.
            const LD h = 1 - std::sqrt(1 - LD(delta) * delta), w = std::sqrt(1 - LD(delta) * delta);
            for (const NodePtr& node : {closed, product}) {
                SpanList s;
                node->spans(ray, 0.0, kInf, ctx, s);
                CAPTURE(delta, node == closed);
                REQUIRE(s.size() == 2);
                const LD bound = node == closed ? 1e-12L : 2e-10L;
                CHECK(relativeError(s[0].in.t, 5 - 1 - w) <= bound);
                CHECK(relativeError(s[0].out.t, 5 - h) <= bound);
                CHECK(relativeError(s[1].in.t, 5 + h) <= bound);
                CHECK(relativeError(s[1].out.t, 5 + 1 + w) <= bound);
            }
        }
    }
}

TEST_CASE(
    "Implicit::spans of (|p|² − 1)² − ε: a thin shell found when thicker than the tolerance") {
    // {f ≤ 0} = {1 − √ε ≤ |p|² ≤ 1 + √ε}: radii √(1 ± √ε), thickness ≈ √ε. Near-double roots:
    // f's two sign changes across each wall are √ε apart and f is O(ε) between them.
    Random rng(403);
    for (double eps : {1e-3, 1e-5, 1e-7, 1e-9}) {
        ExprGraph g;
        const ExprId f =
            g.binary(Op::Sub, g.unary(Op::Square, sphereExpr(g, 1.0)), g.constant(eps));
        const NodePtr shell = makeImplicit(Tape::compile(g, f), Bounds3{Vec3(-2), Vec3(2)});
        const LD root = std::sqrt(LD(eps)), Ro = std::sqrt(1 + root), Ri = std::sqrt(1 - root);
        const double tolerance = double(root) / 1000;
        TraceContext ctx;
        ctx.relTolerance = tolerance;
        ShellTally tally;
        for (int i = 0; i < 200; ++i) {
            const Vec3 u = rng.unitVector(), v = rng.perpendicular(u);
            // Half through the middle, half grazing the inner radius.
            const double b = i % 2 ? rng.uniform(0, 0.9)
                                   : double(Ri) * (1 + rng.uniform(-1, 1) * double(root) / 4);
            const Ray ray{b * v - 5.0 * u, u};
            const SphereOracle oo = sphereOracle(ray, LV3(0), Ro),
                               oi = sphereOracle(ray, LV3(0), Ri);
            const RefSpan outer = chord(oo, Ro, 6, 1, 2 * tolerance),
                          inner = chord(oi, Ri, 6, 1, 2 * tolerance);
            SpanList got;
            shell->spans(ray, 0.0, kInf, ctx, got);
            ++tally.rays;
            CAPTURE(eps, i, b);
            compare(got, shellSpans(outer, oi, inner), tolerance, tally);
        }
        std::printf("(|p|^2-1)^2 - %.0e: %d rays, %d walls, %d thin skipped, worst %.3g of bound\n",
                    eps, tally.rays, tally.walls, tally.thinSkipped, double(tally.worst));
        CHECK(tally.walls > 200);
    }
}
