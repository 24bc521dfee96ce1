// Tape::evalInterval4 against Tape::evalInterval, the reference: every lane of the scalar
// and the AVX2 path must be the same bits (lo, hi, maybeNan) as evalInterval over that lane's
// box, on random tapes and on each vectorised op alone, over boxes of every awkward kind.
// The AVX2 path runs only where the CPU has AVX2 (a WARN says when it does not).
#include "csg/tape/tape.h"
#include "util/interval_checks.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <random>
#include <sstream>

using namespace kerf;

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kHalfPi = 1.5707963267948966;

const char* opName(Op op) {
    static const char* names[] = {"const", "x",   "y",     "z",    "neg",  "square", "sqrt",
                                  "abs",   "sin", "cos",   "tan",  "asin", "acos",   "atan",
                                  "exp",   "log", "floor", "ceil", "+",    "-",      "*",
                                  "/",     "pow", "atan2", "min",  "max",  "powInt"};
    return names[static_cast<int>(op)];
}

bool isBinary(Op op) {
    return op == Op::Add || op == Op::Sub || op == Op::Mul || op == Op::Div || op == Op::Min ||
           op == Op::Max;
}

using kerf::test::describe;
using kerf::test::sameBits;

/// j·π/2 moved by `ulps` steps of one ulp (the ends where the quadrant test is decided).
double nearHalfPiMultiple(std::mt19937_64& rng, double maxMultiple) {
    const double j =
        std::round(std::uniform_real_distribution<double>(-maxMultiple, maxMultiple)(rng));
    double v = j * kHalfPi;
    for (int u = std::uniform_int_distribution<int>(-3, 3)(rng); u != 0; u += u > 0 ? -1 : 1)
        v = std::nextafter(v, u > 0 ? kInfinity : -kInfinity);
    return v;
}

/// A box side of one of the awkward kinds: points, ±0, tiny, straddling 0, huge, infinite ends,
/// ends near multiples of π/2 (also at the edge of interval_trig's fast range, 6.5e5), widths
/// near 2π; a NaN flag on one side in eight.
Interval randomSide(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-10.0, 10.0);
    const double a = u(rng), b = u(rng);
    Interval v;
    switch (std::uniform_int_distribution<int>(0, 13)(rng)) {
        case 0: v = {a, a}; break;
        case 1: v = {-0.0, 0.0}; break;
        case 2: v = {a, std::nextafter(a, kInfinity)}; break;
        case 3:
            v = {a, a + std::pow(10.0, std::uniform_real_distribution<double>(-15, 0)(rng))};
            break;
        case 4: v = {-std::fabs(a), std::fabs(b)}; break;
        case 5: v = {std::min(a, b) * 1e150, std::max(a, b) * 1e150}; break;
        case 6: v = {a, kInfinity}; break;
        case 7: v = {-kInfinity, a}; break;
        case 8: v = {-kInfinity, kInfinity}; break;
        case 9: {
            const double p = nearHalfPiMultiple(rng, 12.0);
            v = {p, p + std::uniform_real_distribution<double>(0.0, 4.0)(rng)};
            break;
        }
        case 10: {
            const double p = nearHalfPiMultiple(rng, 12.0), q = nearHalfPiMultiple(rng, 12.0);
            v = {std::min(p, q), std::max(p, q)};
            break;
        }
        case 11: {  // at the fast range's edge, 6.5e5 ≈ 413802·π/2
            const double p =
                nearHalfPiMultiple(rng, 1.0) + (a < 0 ? -1.0 : 1.0) * 413802.0 * kHalfPi;
            v = {p, p + std::fabs(b) * 1e-3};
            break;
        }
        case 12: {  // widths just under and over 2π
            const double w = 6.28 + std::uniform_real_distribution<double>(-1e-3, 1e-3)(rng);
            v = {a, a + w};
            break;
        }
        default: v = {std::min(a, b), std::max(a, b)}; break;
    }
    v.maybeNan = std::uniform_int_distribution<int>(0, 7)(rng) == 0;
    return v;
}

/// A random expression DAG of `size` nodes over x, y, z and constants (kept in `g`, nodes in
/// `nodes`), its ops drawn from `ops`.
void randomGraph(std::mt19937_64& rng, const std::vector<Op>& ops, int size, ExprGraph& g,
                 std::vector<ExprId>& nodes) {
    nodes = {g.x(), g.y(), g.z()};
    std::uniform_real_distribution<double> constant(-8.0, 8.0);
    for (int i = 0; i < 2; ++i) nodes.push_back(g.constant(constant(rng)));
    nodes.push_back(g.constant(0.0));
    nodes.push_back(g.constant(1e300));
    for (int i = 0; i < size; ++i) {
        const Op op = ops[std::uniform_int_distribution<size_t>(0, ops.size() - 1)(rng)];
        auto pick = [&] {  // favour recent nodes: deep tapes rather than flat fans
            const size_t n = nodes.size();
            const size_t back =
                std::min<size_t>(n - 1, std::geometric_distribution<size_t>(0.3)(rng));
            return nodes[n - 1 - back];
        };
        nodes.push_back(isBinary(op) ? g.binary(op, pick(), pick()) : g.unary(op, pick()));
    }
}

/// The paths under test: the scalar one always, AVX2 where the CPU has it.
std::vector<Tape::Lanes4> paths() {
    if (!Tape::hasAvx2()) {
        WARN("this CPU has no AVX2: only the scalar path of evalInterval4 is tested");
        return {Tape::Lanes4::Scalar};
    }
    return {Tape::Lanes4::Scalar, Tape::Lanes4::Avx2, Tape::Lanes4::Auto};
}

const char* pathName(Tape::Lanes4 p) {
    return p == Tape::Lanes4::Scalar ? "scalar" : p == Tape::Lanes4::Avx2 ? "avx2" : "auto";
}

/// For a tape whose lane k differs from evalInterval: the first node of the graph whose own
/// tape differs there, with its op, operands and both results.
std::string firstDifference(const ExprGraph& g, const std::vector<ExprId>& nodes, Tape::Lanes4 p,
                            const Interval x[4], const Interval y[4], const Interval z[4], int k) {
    for (ExprId id : nodes) {
        const auto t = Tape::compile(g, id);
        Interval out[4];
        t->evalInterval4(x, y, z, out, p);
        const Interval ref = t->evalInterval(x[k], y[k], z[k]);
        if (sameBits(out[k], ref)) continue;
        const ExprNode& node = g.nodes()[id];
        std::ostringstream m;
        m << "first differing op " << opName(node.op);
        if (node.a >= 0)
            m << " of a = " << describe(Tape::compile(g, node.a)->evalInterval(x[k], y[k], z[k]));
        if (node.b >= 0)
            m << ", b = " << describe(Tape::compile(g, node.b)->evalInterval(x[k], y[k], z[k]));
        m << ": " << describe(out[k]) << " vs evalInterval " << describe(ref);
        return m.str();
    }
    return "no single node differs";
}

void checkRandomTapes(const std::vector<Op>& ops, uint64_t seed, int tapes) {
    std::mt19937_64 rng(seed);
    int failures = 0;
    const auto lanes = paths();
    for (int tape = 0; tape < tapes && failures < 10; ++tape) {
        ExprGraph g;
        std::vector<ExprId> nodes;
        randomGraph(rng, ops, std::uniform_int_distribution<int>(1, 30)(rng), g, nodes);
        const auto f = Tape::compile(g, nodes.back());
        for (int trial = 0; trial < 25; ++trial) {
            Interval x[4], y[4], z[4], out[4];
            for (int k = 0; k < 4; ++k)
                x[k] = randomSide(rng), y[k] = randomSide(rng), z[k] = randomSide(rng);
            for (Tape::Lanes4 p : lanes) {
                f->evalInterval4(x, y, z, out, p);
                for (int k = 0; k < 4; ++k) {
                    const Interval ref = f->evalInterval(x[k], y[k], z[k]);
                    if (sameBits(out[k], ref)) continue;
                    std::ostringstream msg;
                    msg << pathName(p) << " path, lane " << k << ", tape of " << f->size()
                        << " instructions, box " << describe(x[k]) << " × " << describe(y[k])
                        << " × " << describe(z[k]) << ": " << describe(out[k])
                        << " vs evalInterval " << describe(ref) << "; "
                        << firstDifference(g, nodes, p, x, y, z, k);
                    FAIL_CHECK(msg.str());
                    ++failures;
                }
            }
        }
    }
    CHECK(failures == 0);
}

}  // namespace

TEST_CASE("Tape::evalInterval4: each vectorised op alone gives evalInterval's bits per lane") {
    std::mt19937_64 rng(11);
    const auto lanes = paths();
    int failures = 0;
    for (Op op : {Op::Add, Op::Sub, Op::Mul, Op::Neg, Op::Square, Op::Sin, Op::Cos, Op::Min,
                  Op::Max, Op::Abs}) {
        ExprGraph g;
        const auto f =
            Tape::compile(g, isBinary(op) ? g.binary(op, g.x(), g.y()) : g.unary(op, g.x()));
        for (int trial = 0; trial < 20000 && failures < 10; ++trial) {
            Interval x[4], y[4], z[4], out[4];
            for (int k = 0; k < 4; ++k) x[k] = randomSide(rng), y[k] = randomSide(rng), z[k] = 0.0;
            for (Tape::Lanes4 p : lanes) {
                f->evalInterval4(x, y, z, out, p);
                for (int k = 0; k < 4; ++k) {
                    const Interval ref = f->evalInterval(x[k], y[k], z[k]);
                    if (sameBits(out[k], ref)) continue;
                    FAIL_CHECK(pathName(p)
                               << " path, lane " << k << ": " << opName(op) << " of "
                               << describe(x[k]) << (isBinary(op) ? " and " + describe(y[k]) : "")
                               << " = " << describe(out[k]) << " vs evalInterval "
                               << describe(ref));
                    ++failures;
                }
            }
        }
    }
    CHECK(failures == 0);
}

TEST_CASE("Tape::evalInterval4: random tapes of the vectorised ops give evalInterval's bits") {
    checkRandomTapes({Op::Add, Op::Sub, Op::Mul, Op::Neg, Op::Square, Op::Sin, Op::Cos, Op::Min,
                      Op::Max, Op::Abs},
                     7, 400);
}

TEST_CASE(
    "Tape::evalInterval4: tapes with other ops (the scalar fallback) give evalInterval's bits") {
    checkRandomTapes({Op::Add, Op::Mul, Op::Sin, Op::Sqrt, Op::Div, Op::Exp, Op::Min}, 13, 150);
}

TEST_CASE("Tape::evalInterval4: the gyroid over octree-like boxes gives evalInterval's bits") {
    // sin 2πx cos 2πy + sin 2πy cos 2πz + sin 2πz cos 2πx, the tape the octree classifies.
    ExprGraph g;
    const ExprId k = g.constant(2.0 * M_PI);
    const ExprId u = g.binary(Op::Mul, k, g.x()), v = g.binary(Op::Mul, k, g.y()),
                 w = g.binary(Op::Mul, k, g.z());
    auto term = [&](ExprId a, ExprId b) {
        return g.binary(Op::Mul, g.unary(Op::Sin, a), g.unary(Op::Cos, b));
    };
    const auto f =
        Tape::compile(g, g.binary(Op::Add, g.binary(Op::Add, term(u, v), term(v, w)), term(w, u)));
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> corner(-3.0, 3.0);
    int failures = 0;
    for (Tape::Lanes4 p : paths())
        for (int trial = 0; trial < 20000 && failures < 10; ++trial) {
            Interval x[4], y[4], z[4], out[4];
            const double size = std::ldexp(6.0, -std::uniform_int_distribution<int>(0, 12)(rng));
            for (int c = 0; c < 4; ++c) {
                const double a = corner(rng), b = corner(rng), d = corner(rng);
                x[c] = {a, a + size}, y[c] = {b, b + size}, z[c] = {d, d + size};
            }
            f->evalInterval4(x, y, z, out, p);
            for (int c = 0; c < 4; ++c) {
                const Interval ref = f->evalInterval(x[c], y[c], z[c]);
                if (sameBits(out[c], ref)) continue;
                FAIL_CHECK(pathName(p)
                           << " path, lane " << c << ": gyroid over " << describe(x[c]) << " × "
                           << describe(y[c]) << " × " << describe(z[c]) << " = " << describe(out[c])
                           << " vs evalInterval " << describe(ref));
                ++failures;
            }
        }
    CHECK(failures == 0);
}
