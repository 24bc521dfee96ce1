/// @file csg/interval/interval.h
/// @brief Closed intervals [lo, hi] of doubles with outward rounding.
///
/// Contract: for every operation op and all reals a ∈ A, b ∈ B where op(a, b) is defined,
/// op(a, b) ∈ op(A, B). Results are widened by one ulp outward (a step on the bit pattern,
/// csg/interval/interval_round.h) after each
/// rounded operation instead of switching the FPU rounding mode, so the code is portable
/// and thread safe. Where an operation is undefined on part of its input (sqrt or log of
/// negatives, division by an interval holding 0), the result covers the defined part and
/// `maybeNan` is set; such an interval never classifies as Empty or Filled.
#pragma once

#include <cmath>
#include <limits>

#include "csg/check.h"
#include "csg/interval/interval_round.h"

namespace kerf {

/// How an implicit function's range over a region classifies that region (f ≤ 0 is inside).
enum class Classification { Empty, Filled, Ambiguous };

struct Interval {
    double lo = 0.0;
    double hi = 0.0;
    bool maybeNan = false;

    constexpr Interval() = default;
    /// A point is an interval; a NaN point is flagged, so a NaN constant (sqrt(-1) folded)
    /// reaches every evaluator's result as maybeNan rather than as NaN ends nobody checks.
    constexpr Interval(double v) : lo(v), hi(v), maybeNan(v != v) {}  // NOLINT: implicit
    constexpr Interval(double l, double h, bool nan = false) : lo(l), hi(h), maybeNan(nan) {
        KERF_DCHECK(!(l > h) || nan);  // lo ≤ hi (or an end NaN), or flagged
    }

    static Interval entire() {
        return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                true};
    }
    double mid() const { return 0.5 * lo + 0.5 * hi; }
    double width() const { return hi - lo; }
    bool contains(double v) const { return lo <= v && v <= hi; }
    bool containsZero() const { return lo <= 0.0 && hi >= 0.0; }
    /// Empty: f > 0 everywhere (outside); Filled: f ≤ 0 everywhere (inside).
    Classification classify() const {
        if (maybeNan) return Classification::Ambiguous;
        if (lo > 0.0) return Classification::Empty;
        if (hi <= 0.0) return Classification::Filled;
        return Classification::Ambiguous;
    }
};

/// `a` for a quantity that cannot be negative (a sum of squares), its lower end clamped at 0:
/// outward rounding of an exact 0 (0 + 0 rounds down to −2⁻¹⁰⁷⁴) would otherwise make sqrt
/// report a possible NaN, and nothing holding it could ever be classified.
inline Interval nonNegative(Interval a) {
    if (a.lo < 0.0) a.lo = 0.0;
    return a;
}

/// One ulp down / up (csg/interval/interval_round.h): −inf stays put going down and +inf going up.
inline double roundDown(double v) { return interval_kernel::down(v); }
inline double roundUp(double v) { return interval_kernel::up(v); }

Interval operator+(const Interval& a, const Interval& b);
Interval operator-(const Interval& a, const Interval& b);
inline Interval operator-(const Interval& a) { return {-a.hi, -a.lo, a.maybeNan}; }  // exact
Interval operator*(const Interval& a, const Interval& b);
Interval operator/(const Interval& a, const Interval& b);

Interval sqr(const Interval& a);                     ///< a², tighter than a·a when a holds 0
Interval powInt(const Interval& a, int n);           ///< aⁿ for integer n (negative n via 1/aⁿ)
Interval pow(const Interval& a, const Interval& b);  ///< exp(b·log a), a > 0 part only
Interval sqrt(const Interval& a);
Interval abs(const Interval& a);
Interval exp(const Interval& a);
Interval log(const Interval& a);
Interval sin(const Interval& a);
Interval cos(const Interval& a);
Interval tan(const Interval& a);
Interval asin(const Interval& a);
Interval acos(const Interval& a);
Interval atan(const Interval& a);
Interval atan2(const Interval& y, const Interval& x);
Interval min(const Interval& a, const Interval& b);
Interval max(const Interval& a, const Interval& b);
Interval floor(const Interval& a);
Interval ceil(const Interval& a);
/// The smallest interval holding both.
Interval hull(const Interval& a, const Interval& b);

}  // namespace kerf
