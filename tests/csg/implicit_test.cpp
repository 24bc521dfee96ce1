// The implicit primitive: a sphere against its closed form, a double root, and a gyroid in a
// box against dense long-double sampling along each ray.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <random>

#include "csg/tape/expr.h"
#include "csg/tape/tape.h"
#include "csg/tree/solids.h"
#include "util/oracles.h"

using namespace kerf;
using kerf::test::gaussianUnit;
using kerf::test::gyroidExpr;
using kerf::test::sphereExpr;

namespace {

long double gyroidLD(long double x, long double y, long double z) {
    return std::sin(x) * std::cos(y) + std::sin(y) * std::cos(z) + std::sin(z) * std::cos(x);
}

}  // namespace

TEST_CASE("Implicit::spans of a sphere against the closed form") {
    ExprGraph g;
    const NodePtr sphere =
        makeImplicit(Tape::compile(g, sphereExpr(g, 1.0)), {Vec3(-2.0), Vec3(2.0)});
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    TraceContext ctx;
    double worst = 0.0;
    for (double tolerance : {1e-9, 1e-12}) {
        ctx.relTolerance = tolerance;
        for (int i = 0; i < 2000; ++i) {
            Ray ray{gaussianUnit(rng) * (2.0 + 8.0 * unit(rng)), Vec3(0.0)};
            ray.dir = (gaussianUnit(rng) * 1.2 * unit(rng) - ray.origin) * (0.1 + 3.0 * unit(rng));
            SpanList s;
            sphere->spans(ray, 0.0, kInf, ctx, s);
            // |o + t d|² = 1, in long double.
            const long double a = glm::dot(ray.dir, ray.dir), b = glm::dot(ray.origin, ray.dir),
                              c = (long double)glm::dot(ray.origin, ray.origin) - 1.0L;
            const long double disc = b * b - a * c;
            INFO("o=(" << ray.origin.x << "," << ray.origin.y << "," << ray.origin.z << ") d=("
                       << ray.dir.x << "," << ray.dir.y << "," << ray.dir.z << ")");
            if (disc <= 0) {
                CHECK(s.empty());
                continue;
            }
            const long double t0 = (-b - std::sqrt(disc)) / a, t1 = (-b + std::sqrt(disc)) / a;
            if (disc < 1e-12L * b * b) continue;  // near-tangent: within the reference's own doubt
            REQUIRE(s.size() == 1);
            const double e0 = double(std::fabs(s[0].in.t - t0) / t0),
                         e1 = double(std::fabs(s[0].out.t - t1) / t1);
            worst = std::max(worst, std::max(e0, e1));
            CHECK(e0 <= tolerance);
            CHECK(e1 <= tolerance);
            // The normal is the gradient 2p: parallel to the hit point.
            const Vec3 p = ray.at(s[0].in.t), n = s[0].in.normal;
            CHECK(glm::length(glm::cross(n / glm::length(n), p / glm::length(p))) < 1e-9);
            CHECK(glm::dot(n, p) > 0.0);
        }
    }
    std::printf("implicit sphere: worst relative error %.3g\n", worst);
}

TEST_CASE("Implicit::spans of a double root") {
    // f = (|p|² − 1)² ≥ 0 is zero only on the unit sphere: {f ≤ 0} is a shell of zero
    // thickness, so rays only touch it and no span wider than the tolerance may appear.
    ExprGraph g;
    const ExprId root = g.unary(Op::Square, sphereExpr(g, 1.0));
    const NodePtr shell = makeImplicit(Tape::compile(g, root), {Vec3(-2.0), Vec3(2.0)});
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    TraceContext ctx;
    ctx.relTolerance = 1e-9;
    int spans = 0;
    for (int i = 0; i < 300; ++i) {
        Ray ray{gaussianUnit(rng) * 5.0, Vec3(0.0)};
        ray.dir = gaussianUnit(rng) * 0.5 * unit(rng) - ray.origin;
        SpanList s;
        shell->spans(ray, 0.0, kInf, ctx, s);
        for (const Span& sp : s) {
            ++spans;
            CHECK(sp.out.t - sp.in.t <= ctx.relTolerance * std::fabs(sp.out.t));
        }
    }
    CHECK(spans == 0);
}

TEST_CASE("Implicit::spans of a gyroid in a box against dense sampling") {
    ExprGraph g;
    const Bounds3 box{Vec3(-4.0, -3.0, -5.0), Vec3(4.0, 3.5, 5.0)};
    const NodePtr solid = makeImplicit(Tape::compile(g, gyroidExpr(g)), box);
    const auto tape = Tape::compile(g, gyroidExpr(g));
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    TraceContext ctx;
    ctx.relTolerance = 1e-9;
    int rays = 0, boundaries = 0, boxFaces = 0, mismatches = 0;
    for (int i = 0; i < 300; ++i) {
        Ray ray{gaussianUnit(rng) * 12.0, Vec3(0.0)};
        ray.dir = Vec3(unit(rng) * 6 - 3, unit(rng) * 6 - 3, unit(rng) * 6 - 3) - ray.origin;
        if (i % 5 == 0) ray.dir[i % 3] = -0.0;
        double t0 = 0.0, t1 = kInf;
        if (!box.clipRay(ray, t0, t1)) continue;
        ++rays;
        SpanList s;
        solid->spans(ray, 0.0, kInf, ctx, s);
        INFO("o=(" << ray.origin.x << "," << ray.origin.y << "," << ray.origin.z << ") d=("
                   << ray.dir.x << "," << ray.dir.y << "," << ray.dir.z << ")");
        // Each surface boundary: |f| within what a relative error of the tolerance in t allows.
        for (const Span& sp : s)
            for (const Boundary* b : {&sp.in, &sp.out}) {
                ++boundaries;
                REQUIRE(b->primitive != 0);
                const Vec3 p = ray.at(b->t);
                Vec3 grad;
                const double f = tape->evalGradient(p, grad);
                const bool onFace = b->t == t0 || b->t == t1;
                if (onFace) {
                    ++boxFaces;
                    CHECK(f <= 0.0);
                    CHECK(glm::length(b->normal) == 1.0);
                    CHECK(glm::dot(b->normal, ray.dir) * (b == &sp.in ? 1.0 : -1.0) < 0.0);
                } else {
                    CHECK(std::fabs(f) <=
                          2.0 * std::fabs(glm::dot(grad, ray.dir)) * ctx.relTolerance * b->t +
                              1e-15);
                }
            }
        // Dense long-double sampling: the sign of f agrees with the spans, except within the
        // tolerance of a boundary.
        const int n = 3000;
        for (int k = 0; k <= n; ++k) {
            const long double t = t0 + (t1 - t0) * (long double)k / n;
            const long double f =
                gyroidLD(ray.origin.x + t * ray.dir.x, ray.origin.y + t * ray.dir.y,
                         ray.origin.z + t * ray.dir.z);
            bool inSpan = false;
            double nearest = kInf;
            for (const Span& sp : s) {
                inSpan |= sp.in.t <= t && t <= sp.out.t;
                nearest = std::min(
                    nearest, double(std::min(std::fabs(t - sp.in.t), std::fabs(t - sp.out.t))));
            }
            if ((f <= 0) != inSpan && nearest > 4.0 * ctx.relTolerance * double(t)) {
                ++mismatches;
                FAIL_CHECK("sample t=" << double(t) << " f=" << double(f) << " but spans say "
                                       << inSpan);
            }
        }
    }
    std::printf(
        "gyroid: %d rays, %d boundaries (%d on box faces), %.1f root steps/ray, %.1f interval "
        "evals/ray\n",
        rays, boundaries, boxFaces, double(ctx.stats.rootSteps) / rays,
        double(ctx.stats.intervalEvals) / rays);
    CHECK(mismatches == 0);
    CHECK(rays > 200);
    CHECK(boxFaces > 0);
}

TEST_CASE("Implicit::value") {
    ExprGraph g;
    const NodePtr sphere =
        makeImplicit(Tape::compile(g, sphereExpr(g, 1.0)), {Vec3(-2.0), Vec3(0.5, 2.0, 2.0)});
    CHECK(sphere->value(Vec3(0.0)) == -0.5);  // the box face x = 0.5 is nearer than f says
    CHECK(sphere->value(Vec3(0.0, 1.5, 0.0)) == 1.25);
    CHECK(sphere->value(Vec3(0.9, 0.0, 0.0)) == Approx(0.4));  // cut by the box at x = 0.5
    const Interval v =
        sphere->valueInterval({Interval(0.8, 1.0), Interval(-0.1, 0.1), Interval(-0.1, 0.1)});
    CHECK(v.lo <= 0.3);
    CHECK(v.lo >= 0.29);
    CHECK(v.hi >= 0.5);
}
