/// @file tests/util/tape_conformance_rows.h
/// @brief The rows of the tape conformance suites (tests/csg/tape_conformance_test.cpp and
/// tests/slice/section_conformance_test.cpp): one per Op, each a tape whose root is that op over
/// affine maps of x, y, z from [0, 1] onto the op's domain; and the random regions they sample.
#pragma once

#include "csg/tape/tape.h"
#include "util/test_fields.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <memory>
#include <random>

namespace kerf::test {

/// The number of ops, from the enum: Field is its last member (a new op after it must move
/// this, and then needs a row below).
constexpr int kOpCount = static_cast<int>(Op::Field) + 1;

/// Relative bound on a slope's distance from the long-double central difference.
constexpr double kSlopeTolerance = 1e-6;
/// Relative slack for a point slope (rounded doubles) against an interval slope enclosure.
constexpr double kEnclosureSlack = 1e-9;

/// One op under test: its operands are affine maps of x (a), y (b) and z (c) from [0, 1] onto
/// the op's domain, so every input is exercised and every partial derivative is nonzero.
struct Row {
    Op op;
    const char* name;
    int arity;  ///< 0: an input, 1, 2, or 3 (noise, field)
    double aLo, aHi, bLo, bHi;
    double value;  ///< Const's value, PowInt's exponent, Noise's seed
};

inline const Row kRows[] = {
    {Op::Const, "const", 0, 0, 0, 0, 0, 1.25},
    {Op::VarX, "x", 0, 0, 0, 0, 0, 0},
    {Op::VarY, "y", 0, 0, 0, 0, 0, 0},
    {Op::VarZ, "z", 0, 0, 0, 0, 0, 0},
    {Op::Neg, "neg", 1, -3, 3, 0, 0, 0},
    {Op::Square, "square", 1, -3, 3, 0, 0, 0},
    {Op::Sqrt, "sqrt", 1, 0.1, 4, 0, 0, 0},
    {Op::Abs, "abs", 1, -3, 3, 0, 0, 0},
    {Op::Sin, "sin", 1, -7, 7, 0, 0, 0},
    {Op::Cos, "cos", 1, -7, 7, 0, 0, 0},
    {Op::Tan, "tan", 1, -1.2, 1.2, 0, 0, 0},
    {Op::Asin, "asin", 1, -0.9, 0.9, 0, 0, 0},
    {Op::Acos, "acos", 1, -0.9, 0.9, 0, 0, 0},
    {Op::Atan, "atan", 1, -3, 3, 0, 0, 0},
    {Op::Exp, "exp", 1, -3, 3, 0, 0, 0},
    {Op::Log, "log", 1, 0.1, 4, 0, 0, 0},
    {Op::Floor, "floor", 1, -3, 3, 0, 0, 0},
    {Op::Ceil, "ceil", 1, -3, 3, 0, 0, 0},
    {Op::Add, "+", 2, -3, 3, -2, 2, 0},
    {Op::Sub, "-", 2, -3, 3, -2, 2, 0},
    {Op::Mul, "*", 2, -3, 3, -2, 2, 0},
    {Op::Div, "/", 2, -3, 3, 0.5, 3, 0},
    {Op::Pow, "pow", 2, 0.2, 3, -2, 2, 0},
    {Op::Atan2, "atan2", 2, -3, 3, -2, 2, 0},
    {Op::Min, "min", 2, -3, 3, -2, 2, 0},
    {Op::Max, "max", 2, -3, 3, -2, 2, 0},
    {Op::PowInt, "powInt", 1, -2, 2, 0, 0, 3},
    {Op::Noise, "noise", 3, -3, 3, -3, 3, 7},
    {Op::Field, "field", 3, -1.5, 1.5, -1.5, 1.5, 0},
};

inline const Row* rowOf(Op op) {
    for (const Row& r : kRows)
        if (r.op == op) return &r;
    return nullptr;
}

/// lo + (hi − lo)·v in the graph.
inline ExprId affine(ExprGraph& g, ExprId v, double lo, double hi) {
    return g.binary(Op::Add, g.constant(lo), g.binary(Op::Mul, g.constant(hi - lo), v));
}

/// The row's op over its operands, compiled.
inline std::shared_ptr<const Tape> rowTape(const Row& row) {
    ExprGraph g;
    const ExprId x = g.x(), y = g.y(), z = g.z();
    ExprId root = -1;
    const ExprId a = affine(g, x, row.aLo, row.aHi), b = affine(g, y, row.bLo, row.bHi);
    switch (row.arity) {
        case 0:
            root = row.op == Op::Const  ? g.constant(row.value)
                   : row.op == Op::VarX ? x
                   : row.op == Op::VarY ? y
                                        : z;
            break;
        case 1:
            root = row.op == Op::PowInt ? g.powInt(a, static_cast<int>(row.value))
                                        : g.unary(row.op, a);
            break;
        case 2: root = g.binary(row.op, a, b); break;
        default: {
            const ExprId c = affine(g, z, row.aLo, row.aHi);
            root = row.op == Op::Noise
                       ? g.noise(a, b, c, static_cast<uint64_t>(row.value))
                       : g.field(a, b, c, std::make_shared<SphereField>(Vec3(0.3, -0.2, 0.1), 1.0));
        }
    }
    auto tape = Tape::compile(g, root);
    REQUIRE(tape->instrs().back().op == row.op);  // the op under test is the root
    return tape;
}

/// A random sub-interval of [0, 1]: widths from 1 down to 1e-6, and now and then a point.
inline Interval randomRange(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    if (u(rng) < 0.1) return Interval(u(rng));
    const double width = std::pow(10.0, -6.0 * u(rng));
    const double lo = u(rng) * (1.0 - width);
    return Interval(lo, lo + width);
}

inline double sampleIn(std::mt19937_64& rng, const Interval& r) {
    return r.lo + std::uniform_real_distribution<double>(0.0, 1.0)(rng) * (r.hi - r.lo);
}

inline bool holds(const Interval& r, double v, double slack) {
    if (std::isnan(v)) return r.maybeNan;
    const double pad = slack * (1.0 + std::fabs(v));
    return r.lo - pad <= v && v <= r.hi + pad;
}

}  // namespace kerf::test
