/// @file csg/interval/interval_ops.h
/// @brief The meaning of each expression Op on intervals: shared by the interval evaluator and
/// the interval-along-a-ray evaluator.
#pragma once

#include "csg/interval/interval.h"
#include "csg/tape/expr.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>

namespace kerf {

/// The rounding steps and the arithmetic that evaluators run millions of times per image,
/// inline so the interval-along-a-ray evaluator pays no call per operation. The operators of
/// csg/interval/interval.h are these same functions (one definition of the arithmetic).
namespace interval_kernel {

/// A lower end from a value that may be NaN (from inf − inf and the like): NaN means unbounded.
inline double lowerEnd(double v) {
    return std::isnan(v) ? -std::numeric_limits<double>::infinity() : down(v);
}
inline double upperEnd(double v) {
    return std::isnan(v) ? std::numeric_limits<double>::infinity() : up(v);
}

/// A product of two interval ends, where 0·inf is 0 (the ends are bounds of finite reals).
inline double endProduct(double a, double b) {
    const double p = a * b;
    return std::isnan(p) ? 0.0 : p;
}

[[gnu::always_inline]] inline Interval add(const Interval& a, const Interval& b) {
    return {lowerEnd(a.lo + b.lo), upperEnd(a.hi + b.hi), a.maybeNan || b.maybeNan};
}

[[gnu::always_inline]] inline Interval sub(const Interval& a, const Interval& b) {
    return {lowerEnd(a.lo - b.hi), upperEnd(a.hi - b.lo), a.maybeNan || b.maybeNan};
}

/// a·k for a finite k: two end products instead of four (root isolation multiplies by ray
/// directions and constants all the time). The same bounds as the general product.
inline Interval scale(const Interval& a, double k, bool nan) {
    double lo = endProduct(a.lo, k), hi = endProduct(a.hi, k);
    if (k < 0.0) std::swap(lo, hi);
    return {down(lo), up(hi), nan};
}

/// The general product: infinite ends (0·inf counts as 0) and point operands.
inline Interval mulGeneral(const Interval& a, const Interval& b, bool nan) {
    if (b.lo == b.hi && std::isfinite(b.lo)) return scale(a, b.lo, nan);
    if (a.lo == a.hi && std::isfinite(a.lo)) return scale(b, a.lo, nan);
    const double p0 = endProduct(a.lo, b.lo), p1 = endProduct(a.lo, b.hi);
    const double p2 = endProduct(a.hi, b.lo), p3 = endProduct(a.hi, b.hi);
    const double lo = std::min(std::min(p0, p1), std::min(p2, p3));
    const double hi = std::max(std::max(p0, p1), std::max(p2, p3));
    return {down(lo), up(hi), nan};
}

/// The lesser / greater of two doubles by value (std::min returns a reference, and GCC then
/// selects through memory instead of emitting minsd / maxsd). b when either is NaN.
[[gnu::always_inline]] inline double lesser(double a, double b) { return a < b ? a : b; }
[[gnu::always_inline]] inline double greater(double a, double b) { return a > b ? a : b; }

/// a·b. Only 0·inf makes an end product NaN, and then mulGeneral handles it (0·inf counts as
/// 0); otherwise the extremes are the min and max of the four end products, as in mulGeneral
/// (a point operand's two equal products change nothing), so the bounds are the same.
[[gnu::always_inline]] inline Interval mul(const Interval& a, const Interval& b) {
    const bool nan = a.maybeNan || b.maybeNan;
    const double p0 = a.lo * b.lo, p1 = a.lo * b.hi, p2 = a.hi * b.lo, p3 = a.hi * b.hi;
    // NaN when a product is NaN (or when infinite products of both signs meet: also rare).
    if (__builtin_expect(std::isnan((p0 + p1) + (p2 + p3)), 0)) return mulGeneral(a, b, nan);
    const double lo = lesser(lesser(p0, p1), lesser(p2, p3));
    const double hi = greater(greater(p0, p1), greater(p2, p3));
    return {down(lo), up(hi), nan};
}

}  // namespace interval_kernel

/// sin(a) and cos(a) together, with one libm sincos per end and one range reduction: what
/// forward-mode differentiation of either needs (the slope of sin is cos and vice versa).
/// Each equals what sin(a) and cos(a) return.
void sinCos(const Interval& a, Interval& s, Interval& c);

/// op(a, b) on intervals; `value` is the PowInt exponent. Const and the variables are not
/// handled here (they have no operands).
inline Interval applyIntervalOp(Op op, const Interval& a, const Interval& b, double value) {
    switch (op) {
        case Op::Neg: return -a;
        case Op::Square: return sqr(a);
        case Op::Sqrt: return sqrt(a);
        case Op::Abs: return abs(a);
        case Op::Sin: return sin(a);
        case Op::Cos: return cos(a);
        case Op::Tan: return tan(a);
        case Op::Asin: return asin(a);
        case Op::Acos: return acos(a);
        case Op::Atan: return atan(a);
        case Op::Exp: return exp(a);
        case Op::Log: return log(a);
        case Op::Floor: return floor(a);
        case Op::Ceil: return ceil(a);
        case Op::Add: return a + b;
        case Op::Sub: return a - b;
        case Op::Mul: return a * b;
        case Op::Div: return a / b;
        case Op::Pow: return pow(a, b);
        case Op::Atan2: return atan2(a, b);
        case Op::Min: return min(a, b);
        case Op::Max: return max(a, b);
        case Op::PowInt: return powInt(a, static_cast<int>(value));
        default: return a;
    }
}

}  // namespace kerf
