// TapeRayProgram (csg/tape/tape_ray_program.h), the comparison interval method's evaluator: on
// random tapes (sqrt, squares, products, min/max, sin, abs, affine forms), random rays and
// random t-intervals, every value sampled along the ray lies in its enclosure of f, every
// difference quotient in its enclosure of df/dt; and it is never looser than
// Tape::evalIntervalAlongRay on sums of squares of affine forms.
#include "csg/tape/tape_ray_program.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "csg/tape/expr.h"
#include "csg/tape/tape.h"
#include "csg/tree/node.h"
#include "util/oracles.h"

using namespace kerf;
using kerf::test::Random;

namespace {

/// A random expression of depth ≤ `depth` over x, y, z: the shapes the primitives' implicit
/// forms are made of (affine forms, squares, sums of squares under sqrt) mixed with min, max,
/// sin, abs and products.
ExprId randomExpr(ExprGraph& g, Random& rng, int depth) {
    const auto affine = [&] {
        ExprId e = g.constant(rng.uniform(-3.0, 3.0));
        const ExprId axes[3] = {g.x(), g.y(), g.z()};
        for (ExprId a : axes)
            if (rng.uniform(0.0, 1.0) < 0.7)
                e = g.binary(Op::Add, e, g.binary(Op::Mul, a, g.constant(rng.uniform(-2.0, 2.0))));
        return e;
    };
    if (depth <= 0) return affine();
    const int pick = static_cast<int>(rng.uniform(0.0, 11.0));
    const auto sub = [&] { return randomExpr(g, rng, depth - 1); };
    // The operands in a fixed order: as g.binary(op, sub(), sub()) the order is the compiler's
    // (GCC draws the right one first, clang the left), so each made different tapes.
    const auto pair = [&](Op op) {
        const ExprId a = sub();
        const ExprId b = sub();
        return g.binary(op, a, b);
    };
    switch (pick) {
        case 0: {  // a sphere-like distance: sqrt of a sum of squares of affine forms, minus r
            ExprId s = g.unary(Op::Square, affine());
            s = g.binary(Op::Add, s, g.unary(Op::Square, affine()));
            if (rng.uniform(0.0, 1.0) < 0.6)
                s = g.binary(Op::Add, s, g.unary(Op::Square, affine()));
            return g.binary(Op::Sub, g.unary(Op::Sqrt, s), g.constant(rng.uniform(0.1, 3.0)));
        }
        case 1: return g.unary(Op::Square, sub());
        case 2: return pair(Op::Min);
        case 3: return pair(Op::Max);
        case 4: return g.unary(Op::Sin, sub());
        case 5: return pair(Op::Mul);
        case 6: return pair(Op::Add);
        case 7: {
            const ExprId a = sub();
            return g.binary(Op::Sub, a, g.binary(Op::Mul, sub(), g.constant(0.5)));
        }
        case 8: return g.unary(Op::Abs, sub());
        case 9:  // sqrt of something that can be negative: NaN flags must come through
            return g.unary(Op::Sqrt, sub());
        default: return g.binary(Op::Div, sub(), g.constant(rng.uniform(0.5, 2.0)));
    }
}

/// f at o + t·d, all in long double.
long double along(const Tape& f, const Ray& ray, long double t) {
    const glm::tvec3<long double> o(ray.origin.x, ray.origin.y, ray.origin.z);
    const glm::tvec3<long double> d(ray.dir.x, ray.dir.y, ray.dir.z);
    return f.evalExtended(o + t * d);
}

/// v in [lo, hi] up to `slack` (the long-double reference's own rounding).
bool within(long double v, const Interval& e, long double slack) {
    if (std::isnan(static_cast<double>(v))) return false;
    return v >= e.lo - slack && v <= e.hi + slack;
}

}  // namespace

TEST_CASE("TapeRayProgram encloses f and df/dt along random rays (property)") {
    Random rng(20261127);
    int checked = 0, quotients = 0, tapes = 0, nanEnclosures = 0;
    double programWidth = 0.0, tapeWidth = 0.0;
    for (int k = 0; k < 400; ++k) {
        ExprGraph g;
        const ExprId root = randomExpr(g, rng, 1 + k % 4);
        const auto tape = Tape::compile(g, root);
        const TapeRayPlan plan(*tape);
        ++tapes;
        for (int r = 0; r < 20; ++r) {
            const Ray ray{rng.inBall() * rng.uniform(0.0, 6.0),
                          rng.unitVector() * rng.logUniform(0.1, 10.0)};
            TapeRayProgram program;
            program.prepare(plan, ray);
            const double a = rng.uniform(-4.0, 4.0);
            const double b = a + rng.logUniform(1e-9, 8.0);
            Interval f, slope;
            program.eval(Interval(a, b), f, slope);
            Interval tf, tslope;
            tape->evalIntervalAlongRay(ray, Interval(a, b), tf, tslope);
            if (std::isfinite(f.width()) && std::isfinite(tf.width()) && !f.maybeNan &&
                !tf.maybeNan) {
                programWidth += f.width();
                tapeWidth += tf.width();
            }
            // A possible NaN (sqrt or division of a part that may be negative or 0) promises
            // nothing more: min and max pass either operand on for a NaN, so the values can
            // leave the enclosure, Tape::evalIntervalAlongRay's as well. Root isolation
            // classifies such an enclosure as undecided and bisects.
            if (f.maybeNan) {
                ++nanEnclosures;
                continue;
            }
            long double prev = 0.0L, prevT = 0.0L;
            constexpr int kSamples = 24;
            for (int i = 0; i <= kSamples; ++i) {
                // Both ends, the middle and random points (as doubles: the rays' t are).
                const long double t = i == 0          ? a
                                      : i == kSamples ? b
                                      : i == 1        ? 0.5 * a + 0.5 * b
                                                      : rng.uniform(a, b);
                const long double v = along(*tape, ray, t);
                const long double slack = 1e-15L * (std::fabs(v) + 1.0L);
                INFO("tape " << k << " ray " << r << " t " << static_cast<double>(t) << " in [" << a
                             << ", " << b << "] value " << static_cast<double>(v) << " enclosure ["
                             << f.lo << ", " << f.hi << "]");
                CHECK(within(v, f, slack));  // no NaN either: f.maybeNan is not set
                ++checked;
                // Mean value: a difference quotient over a wide enough step lies in df/dt
                // (kinks of min, max and abs included: dfdt holds every one-sided slope).
                if (i > 0 && !std::isnan(static_cast<double>(v)) &&
                    !std::isnan(static_cast<double>(prev)) && !slope.maybeNan) {
                    const long double h = t - prevT;
                    if (std::fabs(h) > 1e-4L * (b - a) && std::fabs(h) > 1e-12L) {
                        const long double q = (v - prev) / h;
                        const long double qSlack =
                            (1e-15L * (std::fabs(v) + std::fabs(prev) + 1.0L)) / std::fabs(h);
                        CHECK(within(q, slope, qSlack));
                        ++quotients;
                    }
                }
                prev = v, prevT = t;
            }
            // The point values approximate the tape's.
            const double m = 0.5 * a + 0.5 * b;
            double d = 0.0;
            const double pv = program.valueAndSlope(m, d);
            const double tv = tape->eval(ray.at(m));
            if (std::isfinite(tv) && std::isfinite(pv))
                CHECK(std::fabs(pv - tv) <= 1e-9 * (std::fabs(tv) + 1.0));
        }
    }
    CHECK(checked > 100000);
    CHECK(nanEnclosures < 4000);
    CHECK(quotients > 50000);
    WARN(tapes << " tapes: summed enclosure width " << programWidth << " (TapeRayProgram) vs "
               << tapeWidth << " (Tape::evalIntervalAlongRay)");
    CHECK(programWidth <= tapeWidth);
}

TEST_CASE("TapeRayProgram: a sum of squares of affine forms has its exact range") {
    // (x − 1)² + (y + 2)² + z² along a ray, over intervals holding the vertex or not: the
    // range is that of the quadratic in t, to rounding.
    ExprGraph g;
    const ExprId e =
        g.binary(Op::Add,
                 g.binary(Op::Add, g.unary(Op::Square, g.binary(Op::Sub, g.x(), g.constant(1.0))),
                          g.unary(Op::Square, g.binary(Op::Add, g.y(), g.constant(2.0)))),
                 g.unary(Op::Square, g.z()));
    const auto tape = Tape::compile(g, e);
    const TapeRayPlan plan(*tape);
    CHECK(plan.steps().size() == 1);  // one folded quadratic, nothing else to run
    Random rng(5);
    for (int i = 0; i < 2000; ++i) {
        const Ray ray{rng.inBall() * 5.0, rng.unitVector()};
        TapeRayProgram program;
        program.prepare(plan, ray);
        const double a = rng.uniform(-8.0, 8.0), b = a + rng.uniform(0.0, 6.0);
        Interval f, slope;
        program.eval(Interval(a, b), f, slope);
        // The true range from the closed form of the quadratic, in long double.
        const auto q = [&](long double t) { return along(*tape, ray, t); };
        const LVec3 o(ray.origin.x - 1.0L, ray.origin.y + 2.0L, ray.origin.z);
        const LVec3 d(ray.dir.x, ray.dir.y, ray.dir.z);
        const long double vertex = -glm::dot(o, d) / glm::dot(d, d);
        long double lo = std::min(q(a), q(b)), hi = std::max(q(a), q(b));
        if (vertex > a && vertex < b) lo = std::min(lo, q(vertex));
        const long double scale = hi + 1.0L;
        CHECK(f.lo <= lo);
        CHECK(f.hi >= hi);
        CHECK(lo - f.lo <= 1e-13L * scale);
        CHECK(f.hi - hi <= 1e-13L * scale);
        // Its slope 2·(o + t·d)·d is exact too: 0 is in it only when the vertex is.
        if (vertex < a - 1e-9 || vertex > b + 1e-9) CHECK_FALSE(slope.containsZero());
    }
}

TEST_CASE("a NaN constant is flagged along a ray: TapeRayProgram and the lean path") {
    // sqrt(-1) folds to a NaN constant; max passes its other operand on for a NaN, so only the
    // flag says the value may be NaN. Found by a clang build, whose operand order made a random
    // tape with one (GCC's made none).
    ExprGraph g;
    const ExprId nan = g.constant(std::nan(""));  // what sqrt(-1) folds to
    const ExprId f = g.unary(Op::Square, g.binary(Op::Max, g.binary(Op::Add, g.x(), g.y()), nan));
    const auto tape = Tape::compile(g, f);
    const TapeRayPlan plan(*tape);
    const Ray ray{Vec3(0.1, 0.2, 0.3), Vec3(1.0, -0.5, 0.25)};
    TapeRayProgram program;
    program.prepare(plan, ray);
    Interval value, slope;
    program.eval(Interval(-1.0, 2.0), value, slope);
    CHECK(value.maybeNan);
    Interval tv, tslope;
    tape->evalIntervalAlongRay(ray, Interval(-1.0, 2.0), tv, tslope);
    CHECK(tv.maybeNan);
    CHECK(tape->evalInterval(Interval(0.0, 1.0), Interval(0.0, 1.0), Interval(0.0, 1.0)).maybeNan);
    CHECK(Interval(std::nan("")).maybeNan);
}
