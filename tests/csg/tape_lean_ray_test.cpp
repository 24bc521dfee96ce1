// The lean along-ray path of Tape::evalIntervalAlongRay (no NaN flags, for tapes of +, −, ×,
// negation, square, sin, cos over constants and axes) against the general evaluator: the same
// bits on random tapes, rays and t-intervals of every awkward kind; tapes with other ops keep
// the general path.
#include "csg/tape/tape.h"
#include "util/interval_checks.h"

#include <catch2/catch.hpp>
#include <cstring>
#include <random>
#include <sstream>

using namespace kerf;

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// A random expression DAG of `size` nodes over x, y, z and constants, its ops drawn from
/// `ops` (unary ones take one earlier node, binary ones two).
std::shared_ptr<const Tape> randomTape(std::mt19937_64& rng, const std::vector<Op>& ops, int size) {
    ExprGraph g;
    std::vector<ExprId> nodes = {g.x(), g.y(), g.z()};
    std::uniform_real_distribution<double> constant(-4.0, 4.0);
    for (int i = 0; i < 2; ++i) nodes.push_back(g.constant(constant(rng)));
    nodes.push_back(g.constant(0.0));
    for (int i = 0; i < size; ++i) {
        const Op op = ops[std::uniform_int_distribution<size_t>(0, ops.size() - 1)(rng)];
        auto pick = [&] {
            // Favour recent nodes, so the tape is deep rather than a flat fan.
            const size_t n = nodes.size();
            const size_t back =
                std::min<size_t>(n - 1, std::geometric_distribution<size_t>(0.3)(rng));
            return nodes[n - 1 - back];
        };
        const bool binary = op == Op::Add || op == Op::Sub || op == Op::Mul || op == Op::Div ||
                            op == Op::Min || op == Op::Max;
        nodes.push_back(binary ? g.binary(op, pick(), pick()) : g.unary(op, pick()));
    }
    return Tape::compile(g, nodes.back());
}

Interval randomT(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-20.0, 20.0);
    const double a = u(rng), b = u(rng);
    switch (std::uniform_int_distribution<int>(0, 5)(rng)) {
        case 0: return {a, a};
        case 1: return {a, kInfinity};
        case 2: return {-kInfinity, a};
        case 3: {
            const double w = std::pow(10.0, std::uniform_real_distribution<double>(-15, 0)(rng));
            return {a, a + w};
        }
        case 4: return {std::min(a, b) * 1e150, std::max(a, b) * 1e150};
        default: return {std::min(a, b), std::max(a, b)};
    }
}

Ray randomRay(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-5.0, 5.0);
    Vec3 d(u(rng), u(rng), u(rng));
    // Axis-parallel rays often: their slopes are exactly 0 on two axes.
    if (std::uniform_int_distribution<int>(0, 3)(rng) == 0) d.x = 0.0, d.y = 0.0;
    return Ray{Vec3(u(rng), u(rng), u(rng)), d};
}

using kerf::test::describe;
using kerf::test::sameBits;

void checkSameAsReference(const std::vector<Op>& ops, uint64_t seed) {
    std::mt19937_64 rng(seed);
    int failures = 0;
    for (int tape = 0; tape < 300 && failures < 10; ++tape) {
        const auto f = randomTape(rng, ops, std::uniform_int_distribution<int>(1, 30)(rng));
        for (int k = 0; k < 40; ++k) {
            const Ray ray = randomRay(rng);
            const Interval t = randomT(rng);
            Interval v, d, vr, dr;
            f->evalIntervalAlongRay(ray, t, v, d);
            f->evalIntervalAlongRayReference(ray, t, vr, dr);
            if (sameBits(v, vr) && sameBits(d, dr)) continue;
            std::ostringstream msg;
            msg << "tape of " << f->size() << " instructions, t = " << describe(t) << ": f "
                << describe(v) << " vs reference " << describe(vr) << ", df/dt " << describe(d)
                << " vs " << describe(dr);
            FAIL_CHECK(msg.str());
            ++failures;
        }
    }
    CHECK(failures == 0);
}

}  // namespace

TEST_CASE("Tape::evalIntervalAlongRay: the lean path gives the reference's bits") {
    checkSameAsReference({Op::Add, Op::Sub, Op::Mul, Op::Neg, Op::Square, Op::Sin, Op::Cos}, 3);
}

TEST_CASE("Tape::evalIntervalAlongRay: tapes with other ops give the reference's bits") {
    // sqrt, division and min raise NaN flags or are not in the lean list: the general path.
    checkSameAsReference({Op::Add, Op::Mul, Op::Sin, Op::Sqrt, Op::Div, Op::Min}, 5);
}
