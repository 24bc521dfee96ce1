// Gradient noise as a tape op (csg/tape/noise.h): the value against long double, the gradient
// against central differences, the enclosures of value and slope against dense sampling, the
// global slope bound, every tape evaluator against the others, and tracing a displaced
// sphere against a dense long-double search for its first crossing.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "csg/primitives/implicit_expr.h"
#include "csg/tape/expr.h"
#include "csg/tape/noise.h"
#include "csg/tape/tape.h"
#include "csg/trace_context.h"
#include "csg/tree/solids.h"

using namespace kerf;

namespace {

constexpr uint64_t kSeed = 7;

/// |p| − 1 − 0.15·noise(2.5·p): a sphere displaced by noise, the shape `displace` builds.
std::shared_ptr<const Tape> displacedSphere() {
    ExprGraph g;
    ExprBuilder e{g};
    const ExprId x = g.x(), y = g.y(), z = g.z();
    const ExprId r = e.sqrt(e.add(e.add(e.sqr(x), e.sqr(y)), e.sqr(z)));
    const ExprId n = g.noise(e.mul(x, e.c(2.5)), e.mul(y, e.c(2.5)), e.mul(z, e.c(2.5)), kSeed);
    return Tape::compile(g, e.sub(e.sub(r, e.c(1.0)), e.mul(e.c(0.15), n)));
}

long double displacedSphereLD(const glm::tvec3<long double>& p) {
    const long double r = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
    return r - 1.0L - 0.15L * gradientNoise(p * 2.5L, kSeed);
}

}  // namespace

TEST_CASE("noise: the value against long double, the gradient against central differences") {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> coord(-40.0, 40.0);
    double worstValue = 0.0, worstGradient = 0.0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 p(coord(rng), coord(rng), coord(rng));
        Vec3 g;
        const double v = gradientNoise(p, kSeed, g);
        CHECK(v == gradientNoise(p, kSeed));  // the same bits with and without the gradient
        CHECK(std::fabs(v) <= 1.0);
        const long double ref = gradientNoise(glm::tvec3<long double>(p), kSeed);
        worstValue = std::max(worstValue, double(std::fabs(v - ref)));
        const long double h = 1e-7L;
        for (int k = 0; k < 3; ++k) {
            glm::tvec3<long double> a(p), b(p);
            a[k] += h, b[k] -= h;
            const long double fd = (gradientNoise(a, kSeed) - gradientNoise(b, kSeed)) / (2 * h);
            worstGradient = std::max(worstGradient, double(std::fabs(g[k] - fd)));
        }
    }
    CHECK(worstValue <= 1e-14);
    CHECK(worstGradient <= 1e-6);  // the difference quotient's own error is O(h²·f‴) + rounding
    // Lattice points are zeros; NaN propagates; far out every double is a lattice point.
    CHECK(gradientNoise(Vec3(3.0, -2.0, 5.0), kSeed) == 0.0);
    CHECK(std::isnan(gradientNoise(Vec3(NAN, 0.0, 0.0), kSeed)));
    CHECK(gradientNoise(Vec3(0x1p60, 0.5, 0.5), kSeed) == 0.0);
}

TEST_CASE("noise: enclosures hold every sampled value and slope, in one cell, a few, many") {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int checked = 0;
    for (double size : {1e-9, 1e-3, 0.05, 0.4, 1.5, 30.0}) {
        for (int i = 0; i < 400; ++i) {
            Vec3 lo(unit(rng), unit(rng), unit(rng));
            lo = (lo - 0.5) * 20.0;
            const Vec3 hi = lo + Vec3(unit(rng), unit(rng), unit(rng)) * size;
            Interval slope[3];
            const Interval f =
                gradientNoiseRange({lo.x, hi.x}, {lo.y, hi.y}, {lo.z, hi.z}, kSeed, slope);
            const Interval alone =
                gradientNoiseRange({lo.x, hi.x}, {lo.y, hi.y}, {lo.z, hi.z}, kSeed);
            CHECK((f.lo == alone.lo && f.hi == alone.hi));
            for (int s = 0; s < 40; ++s) {
                const Vec3 p = lo + (hi - lo) * Vec3(unit(rng), unit(rng), unit(rng));
                Vec3 g;
                const double v = gradientNoise(p, kSeed, g);
                CHECK(f.contains(v));
                for (int k = 0; k < 3; ++k) CHECK(slope[k].contains(g[k]));
                ++checked;
            }
        }
    }
    CHECK(checked == 6 * 400 * 40);
    // The slope bound holds wherever sampled, and is not absurdly loose (the sampled maximum
    // is within a factor of four of it).
    double steepest = 0.0;
    std::uniform_real_distribution<double> coord(-100.0, 100.0);
    for (int i = 0; i < 200000; ++i) {
        Vec3 g;
        gradientNoise(Vec3(coord(rng), coord(rng), coord(rng)), kSeed, g);
        steepest = std::max({steepest, std::fabs(g.x), std::fabs(g.y), std::fabs(g.z)});
    }
    CHECK(steepest <= kNoiseSlopeBound);
    CHECK(steepest >= kNoiseSlopeBound / 4.0);
}

TEST_CASE("noise: every tape evaluator agrees on a tape with noise") {
    const auto tape = displacedSphere();
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 2000; ++i) {
        const Vec3 p = (Vec3(unit(rng), unit(rng), unit(rng)) - 0.5) * 3.0;
        Vec3 grad;
        const double v = tape->eval(p);
        CHECK(tape->evalGradient(p, grad) == v);
        CHECK(std::fabs(v - double(displacedSphereLD(glm::tvec3<long double>(p)))) <= 1e-14);
        CHECK(std::fabs(tape->evalExtended(glm::tvec3<long double>(p)) -
                        displacedSphereLD(glm::tvec3<long double>(p))) <= 1e-15L);
        // Boxes around p, one and four at a time (the four-lane path equals the one-box path).
        Interval xs[4], ys[4], zs[4], out[4];
        for (int k = 0; k < 4; ++k) {
            const double h = 0.3 * unit(rng) * (k + 1) / 4.0;
            xs[k] = {p.x - h, p.x + h}, ys[k] = {p.y - h, p.y + h}, zs[k] = {p.z - h, p.z + h};
        }
        tape->evalInterval4(xs, ys, zs, out);
        for (int k = 0; k < 4; ++k) {
            const Interval one = tape->evalInterval(xs[k], ys[k], zs[k]);
            CHECK(one.lo == out[k].lo);
            CHECK(one.hi == out[k].hi);
            CHECK(one.contains(v));
        }
        // Along a ray through p: f and df/dt at t enclosed over a t-interval around it.
        const Ray ray{p - grad,
                      glm::normalize(Vec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5))};
        const double t = 0.7;
        double dfdt;
        const double ft = tape->evalAlongRay(ray, t, dfdt);
        Interval F, D;
        tape->evalIntervalAlongRay(ray, Interval(t - 0.01, t + 0.01), F, D);
        CHECK(F.contains(ft));
        CHECK(D.contains(dfdt));
        // A simplified tape computes the same doubles inside its box.
        std::vector<Choice> choices;
        tape->evalInterval(xs[0], ys[0], zs[0], choices);
        CHECK(tape->simplified(choices)->eval(p) == v);
    }
}

TEST_CASE("noise: a displaced sphere's first hit is its first crossing") {
    const NodePtr solid = makeImplicit(displacedSphere(), {Vec3(-1.3), Vec3(1.3)});
    std::mt19937_64 rng(21);
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    TraceContext ctx;
    ctx.relTolerance = 1e-9;
    int hits = 0;
    for (int i = 0; i < 300; ++i) {
        const Vec3 origin = glm::normalize(Vec3(normal(rng), normal(rng), normal(rng))) * 4.0;
        // Aim near the silhouette as often as at the middle: grazing rays find thin crossings.
        const Vec3 target =
            glm::normalize(Vec3(normal(rng), normal(rng), normal(rng))) * (1.2 * unit(rng));
        const Ray ray{origin, glm::normalize(target - origin)};
        // The reference: the first sign change of f on a grid of 20000 steps over [2, 6], in
        // long double, refined by bisection.
        const auto f = [&](long double t) {
            return displacedSphereLD(glm::tvec3<long double>(ray.origin) +
                                     t * glm::tvec3<long double>(ray.dir));
        };
        long double first = -1.0L;
        long double a = 2.0L, fa = f(a);
        for (int k = 1; k <= 20000 && first < 0; ++k) {
            const long double b = 2.0L + 4.0L * k / 20000.0L, fb = f(b);
            if ((fa > 0) != (fb > 0)) {
                long double lo = a, hi = b;
                for (int it = 0; it < 80; ++it) {
                    const long double mid = 0.5L * (lo + hi);
                    ((f(mid) > 0) == (fa > 0) ? lo : hi) = mid;
                }
                first = lo;
            }
            a = b, fa = fb;
        }
        Boundary hit;
        bool entering = false;
        const bool found = solid->firstSurface(ray, 0.0, kInf, ctx, hit, entering);
        INFO("ray " << i);
        if (first < 0) {
            // No crossing on the grid: any hit must be a crossing thinner than a grid step.
            if (found) CHECK(std::fabs(f(hit.t)) <= 1e-6L);
            continue;
        }
        REQUIRE(found);
        ++hits;
        // Never behind the reference's first crossing; ahead of it only at a real crossing the
        // grid stepped over (f changes sign around hit.t).
        CHECK(hit.t <= double(first) + 1e-8);
        if (hit.t < double(first) - 1e-8) {
            CHECK((f(hit.t - 1e-8L) > 0) != (f(hit.t + 1e-8L) > 0));
        } else {
            CHECK(std::fabs(hit.t - double(first)) <= 1e-8);
        }
    }
    CHECK(hits > 100);
}
