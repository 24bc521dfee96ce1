/// @file csg/interval/interval_trig.h
/// @brief Sound sin and cos of an interval without a libm call, for |x| ≤ kTrigFastLimit:
/// one Cody–Waite range reduction per end, Taylor polynomials on the reduced argument, and
/// each end value widened by a proved absolute error bound. Internal to csg/ (interval.cpp
/// and the along-ray evaluator call sinCos, which uses this when the ends are in range).
///
/// Error bound (u = 2⁻⁵³, the unit roundoff; all bounds absolute, on values in [−1, 1]):
/// - Reduction: k = round(x·2/π), |k| < 2²⁰; π/2 = P1 + P2 + P3 + δ with P1, P2 of 33
///   significant bits (so k·P1 and k·P2 are exact) and |δ| < 2⁻¹²². r = ((x − kP1) − kP2) −
///   kP3 rounds three times on values below 0.79 and once in kP3: |r̂ − r| ≤ 3u.
///   |r| ≤ π/4 + |k|·2⁻⁵²·(rounding of x·2/π) < 0.7854, so |r̂| < 0.79.
/// - sin r̂ = r̂·q(s), s = r̂², q the Taylor polynomial through r¹⁵ (remainder
///   ≤ 0.79¹⁷/17! < 0.5u); cos r̂ = p(s), through r¹⁶ (remainder < 0.1u). Horner in s
///   (Higham, Thm 5.1: error ≤ γ₂ₙ·Σ|cᵢ|sⁱ): cos ≤ 16u·cosh 0.79 < 21.5u, sin ≤ (14u·1.11 +
///   u)·0.79 < 13.2u; the rounding of the coefficients ≤ u·cosh 0.79 < 1.4u; the rounding
///   of s moves the result by ≤ 0.56·u·s < 0.4u.
/// - So each of sin x, cos x is within 3 + 0.5 + 21.5 + 1.4 + 0.4 < 27u of the computed value;
///   widening by kTrigError = 32u, whose subtraction rounds by at most 1u more, holds it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "csg/interval/interval.h"

namespace kerf::interval_trig {

/// Ends beyond this take the libm path: |k| = |x·2/π| stays below 2²⁰ (exact k·P1, k·P2).
constexpr double kTrigFastLimit = 6.5e5;
/// The proved bound above, rounded up to a power of two: 32u = 2⁻⁴⁸.
constexpr double kTrigError = 0x1p-48;

constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;
constexpr double kP1 = 0x1.921fb54400000p+0;
constexpr double kP2 = 0x1.0b4611a600000p-34;
constexpr double kP3 = 0x1.3198a2e037073p-69;

/// sin and cos of a double x, |x| ≤ kTrigFastLimit, to within 27u each (see the file header),
/// and the quadrant k = round(x·2/π) with the reduced argument r̂ ≈ x − k·π/2.
struct PointTrig {
    double s, c;  ///< approximations of sin x, cos x
    double r;     ///< the reduced argument
    int64_t k;
};

inline PointTrig pointTrig(double x) {
    // Round to nearest integer with the 1.5·2⁵² shift: exact for |x·2/π| < 2⁵¹.
    constexpr double kShift = 0x1.8p52;
    const double kd = (x * kTwoOverPi + kShift) - kShift;
    const double r = ((x - kd * kP1) - kd * kP2) - kd * kP3;
    const double s = r * r;
    // Taylor coefficients ±1/n!, rounded to nearest.
    const double q =
        1.0 +
        s * (-0x1.5555555555555p-3 +
             s * (0x1.1111111111111p-7 +
                  s * (-0x1.a01a01a01a01ap-13 +
                       s * (0x1.71de3a556c734p-19 +
                            s * (-0x1.ae64567f544e4p-26 +
                                 s * (0x1.6124613a86d09p-33 + s * -0x1.ae7f3e733b81fp-41))))));
    const double p =
        1.0 +
        s * (-0.5 +
             s * (0x1.5555555555555p-5 +
                  s * (-0x1.6c16c16c16c17p-10 +
                       s * (0x1.a01a01a01a01ap-16 +
                            s * (-0x1.27e4fb7789f5cp-22 +
                                 s * (0x1.1eed8eff8d898p-29 + s * (-0x1.93974a8c07c9dp-37 +
                                                                   s * 0x1.ae7f3e733b81fp-45)))))));
    const double sr = r * q;
    const int64_t k = static_cast<int64_t>(kd);
    PointTrig t{0.0, 0.0, r, k};
    switch (k & 3) {  // two's complement: k mod 4
        case 0: t.s = sr, t.c = p; break;
        case 1: t.s = p, t.c = -sr; break;
        case 2: t.s = -sr, t.c = -p; break;
        default: t.s = -p, t.c = sr; break;
    }
    return t;
}

/// sin x and cos x in doubles for the point evaluators: pointTrig (within 27u, one call for
/// both) where it applies, libm beyond. Not an enclosure: point values only.
inline void pointSinCos(double x, double& s, double& c) {
    if (std::fabs(x) <= kTrigFastLimit) {
        const PointTrig t = pointTrig(x);
        s = t.s, c = t.c;
    } else {
        s = std::sin(x), c = std::cos(x);
    }
}

/// sin(a) and cos(a) for finite ends with |a.lo|, |a.hi| ≤ kTrigFastLimit and a.hi − a.lo <
/// 2π (the caller checks). The extremes inside [lo, hi] are at the multiples j·π/2 it may
/// hold: by j mod 4, cos = 1, sin = 1, cos = −1, sin = −1. The first such j is k(lo), or
/// k(lo) + 1 once r̂(lo) > 3u proves lo > k(lo)·π/2; the last is k(hi), or k(hi) − 1 likewise.
/// A multiple counted that is not inside only widens the result.
inline void sinCosFast(const Interval& a, Interval& s, Interval& c) {
    constexpr double kReductionError = 0x1p-51;  // ≥ 3u, the bound on |r̂ − r|
    const PointTrig l = pointTrig(a.lo), h = a.hi == a.lo ? l : pointTrig(a.hi);
    const int64_t first = l.k + (l.r > kReductionError ? 1 : 0);
    const int64_t last = h.k - (h.r < -kReductionError ? 1 : 0);
    unsigned extremes = 0;  // bit j mod 4: a multiple j·π/2 may lie inside
    if (last - first >= 3)
        extremes = 15u;
    else
        for (int64_t j = first; j <= last; ++j) extremes |= 1u << (j & 3);
    const double sLo = extremes & 8u ? -1.0 : std::max(-1.0, (l.s < h.s ? l.s : h.s) - kTrigError);
    const double sHi = extremes & 2u ? 1.0 : std::min(1.0, (l.s > h.s ? l.s : h.s) + kTrigError);
    const double cLo = extremes & 4u ? -1.0 : std::max(-1.0, (l.c < h.c ? l.c : h.c) - kTrigError);
    const double cHi = extremes & 1u ? 1.0 : std::min(1.0, (l.c > h.c ? l.c : h.c) + kTrigError);
    s = {sLo, sHi, a.maybeNan};
    c = {cLo, cHi, a.maybeNan};
}

/// sinCosFast when it applies (finite ends within ±kTrigFastLimit, width below 2π, where
/// sinCos would not answer [−1, 1] anyway); false otherwise, for the caller's libm path.
inline bool trySinCosFast(const Interval& a, Interval& s, Interval& c) {
    // NaN or infinite ends fail every comparison below; so does a reversed interval (lo > hi,
    // outside the contract), whose width would be negative and its quadrant walk endless.
    if (!(a.lo >= -kTrigFastLimit && a.hi <= kTrigFastLimit && a.lo <= a.hi && a.hi - a.lo < 6.28))
        return false;
    sinCosFast(a, s, c);
    return true;
}

}  // namespace kerf::interval_trig
