// Thin features: spherical and cylindrical shells of thickness ε·R, ε = 1e-3 … 1e-7, cut open,
// seen along rays that graze the inner wall (impact parameter within 2ε·R of the radius). With
// the tolerance set below the thickness (ε/100 relative, the wall being ≥ ε/10 of the hit
// distance), no wall may be missed and every boundary lies within the tolerance (plus the
// root's grazing condition number, see grazing_test.cpp) of the long-double value. An implicit
// shell (interval root isolation) is held to the same rule down to ε = 1e-5.
#include "util/shell_reference.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <vector>

using namespace kerf;
using namespace kerf::test;

namespace {

/// The reference spans cut to the side of the plane y = c (at ray parameter ty) that holds the
/// open shell, y ≤ c: a span crossing the plane ends (or starts) there, exactly to 1e-15·ty.
std::vector<RefSpan> belowPlane(const std::vector<RefSpan>& spans, const Ray& ray, LD ty) {
    std::vector<RefSpan> ref;
    const bool downward = ray.dir.y < 0;
    for (RefSpan s : spans) {
        if (downward ? s.out <= ty : s.in >= ty) continue;
        if (downward && s.in < ty) s = {ty, s.out, 1e-15L * ty, s.errOut};
        if (!downward && s.out > ty) s = {s.in, ty, s.errIn, 1e-15L * ty};
        ref.push_back(s);
    }
    return ref;
}

}  // namespace

TEST_CASE("Thin spherical shells cut open, on grazing rays") {
    Random rng(301);
    const Vec3 c(0.3, -0.2, 0.1);
    const double R = 1.7;
    for (double eps : {1e-3, 1e-4, 1e-5, 1e-6, 1e-7}) {
        const double Rin = R * (1 - eps), tolerance = eps / 100;
        // The shell, cut open by removing the half y > c.y.
        const NodePtr shell = makeBoolean(
            BoolOp::Difference,
            {makeSphere(c, R), makeSphere(c, Rin), makeHalfSpace(Vec3(0, -1, 0), -c.y)});
        TraceContext ctx;
        ctx.relTolerance = tolerance;
        ShellTally tally;
        for (int i = 0; i < 1000; ++i) {
            const Vec3 u = rng.unitVector();
            const Vec3 v = rng.perpendicular(u);
            // Impact parameter in [R − 2εR, R]: half the rays pass through the wall only
            // (grazing the inner sphere from outside), half cross both walls near tangency.
            const double b = R * (1 - 2 * eps * rng.uniform(0, 1));
            const Ray ray{c + b * v - 10 * R * u, u * rng.logUniform(0.5, 2)};
            const LD a = glm::dot(ld(ray.dir), ld(ray.dir)), far = 11 * R;
            const SphereOracle oo = sphereOracle(ray, ld(c), R), oi = sphereOracle(ray, ld(c), Rin);
            if (!oo.hit()) continue;
            const RefSpan outer = chord(oo, R, far, a, tolerance),
                          inner = chord(oi, Rin, far, a, tolerance);
            // Clip to y ≤ c.y: the ray's parameter range on that side.
            const LD ty = (LD(c.y) - ray.origin.y) / ray.dir.y;
            const std::vector<RefSpan> ref = belowPlane(shellSpans(outer, oi, inner), ray, ty);
            SpanList got;
            shell->spans(ray, 0.0, kInf, ctx, got);
            ++tally.rays;
            CAPTURE(eps, i, b);
            compare(got, ref, tolerance, tally);
        }
        std::printf(
            "sphere shell eps %.0e: %d rays, %d walls found, %d thinner than the tolerance "
            "skipped, worst end error %.3g of its bound\n",
            eps, tally.rays, tally.walls, tally.thinSkipped, double(tally.worst));
        CHECK(tally.walls > 600);
        CHECK(tally.thinSkipped * 20 < tally.walls);
    }
}

TEST_CASE("Thin cylindrical tubes, on grazing rays across the axis") {
    Random rng(302);
    const double R = 0.9;
    for (double eps : {1e-3, 1e-4, 1e-5, 1e-6, 1e-7}) {
        const double Rin = R * (1 - eps), tolerance = eps / 100;
        // A tube along y, open at both ends (the bore is longer than the tube).
        const NodePtr tube =
            makeBoolean(BoolOp::Difference, {makeCylinder(Vec3(0, -1, 0), Vec3(0, 1, 0), R),
                                             makeCylinder(Vec3(0, -2, 0), Vec3(0, 2, 0), Rin)});
        TraceContext ctx;
        ctx.relTolerance = tolerance;
        ShellTally tally;
        for (int i = 0; i < 1000; ++i) {
            const double phi = rng.uniform(0, 6.283185307179586);
            const Vec3 u(std::cos(phi), 0.0, std::sin(phi)), v(-u.z, 0.0, u.x);
            const double b = R * (1 - 2 * eps * rng.uniform(0, 1));
            const Ray ray{b * v - 10 * R * u + Vec3(0, rng.uniform(-0.9, 0.9), 0),
                          u * rng.logUniform(0.5, 2)};
            // Across the axis (d.y = 0): the cross-section is a circle, the sphere oracle in xz.
            const LV3 f(ray.origin.x, 0, ray.origin.z), d = ld(ray.dir);
            const LD a = glm::dot(d, d), far = 11 * R;
            const SphereOracle oo = sphereOracleLD(f, d, R), oi = sphereOracleLD(f, d, Rin);
            if (!oo.hit()) continue;
            const RefSpan outer = chord(oo, R, far, a, tolerance),
                          inner = chord(oi, Rin, far, a, tolerance);
            SpanList got;
            tube->spans(ray, 0.0, kInf, ctx, got);
            ++tally.rays;
            CAPTURE(eps, i, b);
            compare(got, shellSpans(outer, oi, inner), tolerance, tally);
        }
        std::printf(
            "tube eps %.0e: %d rays, %d walls found, %d thinner than the tolerance skipped, "
            "worst end error %.3g of its bound\n",
            eps, tally.rays, tally.walls, tally.thinSkipped, double(tally.worst));
        CHECK(tally.walls > 1000);
        CHECK(tally.thinSkipped * 20 < tally.walls);
    }
}

TEST_CASE("Thin implicit shells found by interval root isolation") {
    // max(|p|² − 1, r_in² − |p|²) ≤ 0: the shell 1 − ε ≤ |p| ≤ 1 as one implicit, cut open by a
    // box. Root-found, so each end is within the tolerance (twice, for the bracket's width).
    Random rng(303);
    for (double eps : {1e-3, 1e-4, 1e-5}) {
        const double Rin = 1 - eps, tolerance = eps / 100;
        ExprGraph g;
        const ExprId outer = sphereExpr(g, 1.0);
        const ExprId inner = g.unary(Op::Neg, sphereExpr(g, Rin));
        const NodePtr shell = makeImplicit(Tape::compile(g, g.binary(Op::Max, outer, inner)),
                                           Bounds3{Vec3(-1.5), Vec3(1.5, 0.0, 1.5)});
        TraceContext ctx;
        ctx.relTolerance = tolerance;
        ShellTally tally;
        for (int i = 0; i < 300; ++i) {
            const Vec3 u = rng.unitVector(), v = rng.perpendicular(u);
            const double b = 1 - 2 * eps * rng.uniform(0, 1);
            const Ray ray{b * v - 10.0 * u, u};
            const LD far = 11;
            const SphereOracle oo = sphereOracle(ray, LV3(0), 1),
                               oi = sphereOracle(ray, LV3(0), Rin);
            if (!oo.hit()) continue;
            const RefSpan o = chord(oo, 1, far, 1, 2 * tolerance),
                          in = chord(oi, Rin, far, 1, 2 * tolerance);
            const LD ty = -LD(ray.origin.y) / ray.dir.y;  // the box's top face y = 0
            const std::vector<RefSpan> ref = belowPlane(shellSpans(o, oi, in), ray, ty);
            SpanList got;
            shell->spans(ray, 0.0, kInf, ctx, got);
            ++tally.rays;
            CAPTURE(eps, i, b);
            compare(got, ref, tolerance, tally);
        }
        std::printf(
            "implicit shell eps %.0e: %d rays, %d walls, %d thin skipped, worst %.3g of bound\n",
            eps, tally.rays, tally.walls, tally.thinSkipped, double(tally.worst));
        CHECK(tally.walls > 100);
    }
}
