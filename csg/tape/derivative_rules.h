/// @file csg/tape/derivative_rules.h
/// @brief The forward-mode derivative of each Op, written once and templated on the number
/// type: N is the value (double at a point, Interval over a region) and G the derivative carried
/// per slot (a double slope, a Vec3 gradient, or an Interval slope). Used by the gradient
/// evaluator, the along-ray evaluators (point and interval) and the section tape's slopes
/// (slice/section_tape.cpp), so an op's derivative is one place. Internal to csg/ and slice/.
///
/// Where an op is not differentiable or not continuous, the point rule takes a one-sided
/// derivative (abs, min, max at a tie) or 0 (floor, ceil), and the interval rule widens the
/// enclosure to hold every one-sided slope (kinks) or makes it entire (jumps), so that
/// "0 ∉ df/dt" still proves strict monotonicity.
#pragma once

#include <cmath>

#include "csg/interval/interval.h"
#include "csg/tape/expr.h"
#include "csg/types.h"

namespace kerf::derivative_rules {

// The elementary functions on both number types, named apart so that a rule reads the same
// for each. The double forms are the libm calls (the interval forms round outward).
inline double sq(double x) { return x * x; }
inline Interval sq(const Interval& x) { return sqr(x); }
inline double sqrtOf(double x) { return std::sqrt(x); }
inline Interval sqrtOf(const Interval& x) { return sqrt(x); }
inline double sinOf(double x) { return std::sin(x); }
inline Interval sinOf(const Interval& x) { return sin(x); }
inline double cosOf(double x) { return std::cos(x); }
inline Interval cosOf(const Interval& x) { return cos(x); }
inline double logOf(double x) { return std::log(x); }
inline Interval logOf(const Interval& x) { return log(x); }
inline double powOf(double x, double y) { return std::pow(x, y); }
inline Interval powOf(const Interval& x, const Interval& y) { return pow(x, y); }
inline double powIntOf(double x, int n) { return std::pow(x, n); }
inline Interval powIntOf(const Interval& x, int n) { return powInt(x, n); }

/// Whether a derivative is exactly zero (the operand does not vary).
inline bool isZero(double g) { return g == 0.0; }
inline bool isZero(const Vec3& g) { return g == Vec3(0.0); }
inline bool isZero(const Interval& g) { return g.lo == 0.0 && g.hi == 0.0; }

/// A zero derivative of type G.
template <typename G>
G zero() {
    return G(0.0);
}

// The kinks and jumps: a point takes one side; a region that straddles the kink takes the hull.

/// d|a|: the sign of a decides.
template <typename G>
G absSlope(double av, const G& ad) {
    return av < 0.0 ? -ad : ad;
}
inline Interval absSlope(const Interval& av, const Interval& ad) {
    if (av.lo >= 0.0) return ad;
    if (av.hi <= 0.0) return -ad;
    return hull(ad, -ad);
}

/// d min(a, b) (isMin) or d max(a, b): the operand that gives the value; a at a tie.
template <typename G>
G minMaxSlope(bool isMin, double av, const G& ad, double bv, const G& bd) {
    return (isMin ? av <= bv : av >= bv) ? ad : bd;
}
inline Interval minMaxSlope(bool isMin, const Interval& av, const Interval& ad, const Interval& bv,
                            const Interval& bd) {
    // a ≤ b over the whole region makes min(a, b) the function a there (touching included).
    const bool aGives = isMin ? av.hi <= bv.lo : av.lo >= bv.hi;
    const bool bGives = isMin ? bv.hi <= av.lo : bv.lo >= av.hi;
    if (aGives) return ad;
    if (bGives) return bd;
    return hull(ad, bd);
}

/// d floor(a), d ceil(a): 0 at a point (piecewise constant); over a region 0 only where the
/// result holds no integer step, else a jump (entire).
template <typename G>
G stepSlope(double, const G&) {
    return zero<G>();
}
inline Interval stepSlope(const Interval& result, const Interval& ad) {
    return result.lo == result.hi ? Interval(0.0, 0.0, ad.maybeNan) : Interval::entire();
}

/// The derivative for an op that has none here (inputs, noise, fields: their evaluators apply
/// the chain rule themselves).
inline double unknownSlope(double) { return 0.0; }
inline Vec3 unknownSlope(const Vec3&) { return Vec3(0.0); }
inline Interval unknownSlope(const Interval&) { return Interval::entire(); }

/// d sin(a) from cos(a), and d cos(a) from sin(a): for evaluators that compute sin and cos of
/// an operand in one reduction.
template <typename N, typename G>
G sinSlope(const N& cosA, const G& ad) {
    return cosA * ad;
}
template <typename N, typename G>
G cosSlope(const N& sinA, const G& ad) {
    return -(sinA * ad);
}

/// The chain rule through a function of three operands (noise, fields) whose gradient there
/// is g: g·(a', b', c').
template <typename N, typename G>
G chainSlope(const N g[3], const G& ad, const G& bd, const G& cd) {
    return g[0] * ad + g[1] * bd + g[2] * cd;
}

/// d op(a, b) from the operands' values av, bv and derivatives ad, bd, the instruction's
/// `value` (PowInt's exponent) and the op's own result (r = op(a, b), which several rules
/// reuse). Unary ops ignore b.
template <typename N, typename G>
G derivative(Op op, const N& av, const G& ad, const N& bv, const G& bd, double value, const N& r) {
    const N one(1.0), two(2.0);
    switch (op) {
        case Op::Neg: return -ad;
        case Op::Square: return two * av * ad;
        case Op::Sqrt: return ad / (two * r);
        case Op::Abs: return absSlope(av, ad);
        case Op::Sin: return sinSlope(cosOf(av), ad);
        case Op::Cos: return cosSlope(sinOf(av), ad);
        case Op::Tan: return (one + sq(r)) * ad;
        case Op::Asin: return ad / sqrtOf(one - sq(av));
        case Op::Acos: return -(ad / sqrtOf(one - sq(av)));
        case Op::Atan: return ad / (one + sq(av));
        case Op::Exp: return r * ad;
        case Op::Log: return ad / av;
        case Op::Floor:
        case Op::Ceil: return stepSlope(r, ad);
        case Op::Add: return ad + bd;
        case Op::Sub: return ad - bd;
        case Op::Mul: return ad * bv + av * bd;
        case Op::Div: return (ad - r * bd) / bv;
        case Op::Pow: {
            // d(aᵇ) = b·aᵇ⁻¹·da + aᵇ·ln a·db; the second term only when b varies, so that a
            // constant exponent at a = 0 does not bring in 0·ln 0.
            G d = bv * powOf(av, bv - one) * ad;
            if (!isZero(bd)) d = d + r * logOf(av) * bd;
            return d;
        }
        case Op::Atan2: return (bv * ad - av * bd) / (sq(av) + sq(bv));
        case Op::Min:
        case Op::Max: return minMaxSlope(op == Op::Min, av, ad, bv, bd);
        case Op::PowInt: {
            const int n = static_cast<int>(value);
            return n == 0 ? zero<G>() : N(value) * powIntOf(av, n - 1) * ad;
        }
        default: return unknownSlope(ad);
    }
}

}  // namespace kerf::derivative_rules
