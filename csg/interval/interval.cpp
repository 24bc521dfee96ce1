// Interval arithmetic with outward rounding (see csg/interval/interval.h for the contract).
//
// Rounding: every rounded operation steps its result one ulp outward. IEEE +, −, ×, ÷ and sqrt
// are correctly rounded, so one ulp suffices. The libm functions (exp, log, sin, cos, sincos,
// tan, asin, acos, atan, atan2) are not guaranteed correctly rounded: glibc documents errors of
// at most a few ulps, so their results are widened by kLibmUlps ulps on each side.
//
// Infinite ends: an end at ±inf is a bound, not a value; 0·inf therefore counts as 0 in
// products, and an undefined combination of bounds (inf − inf, inf/inf) widens the result
// to the side it could lie on.
#include "csg/interval/interval.h"
#include "csg/interval/interval_ops.h"
#include "csg/interval/interval_trig.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace kerf {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr int kLibmUlps = 4;
// Upper bounds of π, π/2 and lower bound of π (the doubles nearest them, one ulp out).
constexpr double kPiLo = 3.141592653589793;   // below π
constexpr double kPiHi = 3.1415926535897936;  // above π
constexpr double kTwoPi = 6.283185307179586;
constexpr double k2OverPi = 0.6366197723675814;  // 2/π to double precision

using interval_kernel::bitsOf;
using interval_kernel::down;
using interval_kernel::endProduct;
using interval_kernel::fromBits;
using interval_kernel::up;

/// n ulps towards −inf (for libm results), n ≥ 1: the bit-pattern steps of down(v), n at once.
double down(double v, int n) {
    const uint64_t b = bitsOf(v), steps = static_cast<uint64_t>(n);
    if (v > 0.0 && b > steps) return fromBits(b - steps);
    if (v < 0.0) return fromBits(std::min(b + steps, bitsOf(-kInfinity)));
    for (; n > 0 && v != -kInfinity; --n) v = down(v);  // 0, the smallest subnormals, NaN
    return v;
}
/// n ulps towards +inf (the mirror of down).
double up(double v, int n) { return -down(-v, n); }

bool anyNan(const Interval& a) { return a.maybeNan; }
bool anyNan(const Interval& a, const Interval& b) { return a.maybeNan || b.maybeNan; }

/// For a monotonically increasing libm function: widened image of [lo, hi].
template <typename F>
Interval increasing(const Interval& a, F f) {
    return {down(f(a.lo), kLibmUlps), up(f(a.hi), kLibmUlps), a.maybeNan};
}

/// True when some x0 + k·period (k integer) may lie in [lo, hi]. Errs towards true: the
/// quotients are rounded, so the test is widened by a relative margin far above their error.
bool mayHoldPhase(double lo, double hi, double x0, double period) {
    const double qLo = (lo - x0) / period, qHi = (hi - x0) / period;
    const double margin = 1e-12 * (1.0 + std::max(std::fabs(qLo), std::fabs(qHi)));
    return std::floor(qHi + margin) >= std::ceil(qLo - margin);
}

/// xⁿ for x ≥ 0 by repeated squaring, each product rounded the same way (all factors are
/// non-negative, so rounding every step down gives a lower bound, and up an upper bound).
double powNonNegative(double x, unsigned n, bool roundUpward) {
    double result = 1.0, base = x;
    while (n) {
        if (n & 1u) result = roundUpward ? up(result * base) : std::max(0.0, down(result * base));
        n >>= 1;
        if (n) base = roundUpward ? up(base * base) : std::max(0.0, down(base * base));
    }
    return result;
}

}  // namespace

Interval operator+(const Interval& a, const Interval& b) { return interval_kernel::add(a, b); }

Interval operator-(const Interval& a, const Interval& b) { return interval_kernel::sub(a, b); }

Interval operator*(const Interval& a, const Interval& b) { return interval_kernel::mul(a, b); }

Interval operator/(const Interval& a, const Interval& b) {
    const bool nan = anyNan(a, b);
    if (b.lo > 0.0 || b.hi < 0.0) {
        // 0 ∉ b: the extremes are among the four end quotients. inf/inf has a known sign but
        // any magnitude, so it stands for [0, inf] (or [−inf, 0]).
        double lo = kInfinity, hi = -kInfinity;
        const double as[2] = {a.lo, a.hi}, bs[2] = {b.lo, b.hi};
        for (double x : as)
            for (double y : bs) {
                const double q = x / y;
                if (std::isnan(q)) {
                    const bool negative = std::signbit(x) != std::signbit(y);
                    lo = std::min(lo, negative ? -kInfinity : 0.0);
                    hi = std::max(hi, negative ? 0.0 : kInfinity);
                } else {
                    lo = std::min(lo, q);
                    hi = std::max(hi, q);
                }
            }
        return {down(lo), up(hi), nan};
    }
    // 0 ∈ b: x/0 is undefined, so maybeNan is always set. The cases:
    //   b = [0, 0], or 0 ∈ a (0/0 possible)  → entire;
    //   b = [0, h], a > 0 → [a.lo/h, inf];    a < 0 → [−inf, a.hi/h];
    //   b = [l, 0], a > 0 → [−inf, a.lo/l];   a < 0 → [a.hi/l, inf];
    //   l < 0 < h          → both semi-infinite pieces, whose hull is entire.
    if ((b.lo == 0.0 && b.hi == 0.0) || a.containsZero() || (b.lo < 0.0 && b.hi > 0.0))
        return Interval::entire();
    if (b.lo == 0.0) {
        if (a.lo > 0.0) return {down(a.lo / b.hi), kInfinity, true};
        return {-kInfinity, up(a.hi / b.hi), true};
    }
    if (a.lo > 0.0) return {-kInfinity, up(a.lo / b.lo), true};
    return {down(a.hi / b.lo), kInfinity, true};
}

Interval sqr(const Interval& a) {
    if (a.lo >= 0.0) return {std::max(0.0, down(a.lo * a.lo)), up(a.hi * a.hi), a.maybeNan};
    if (a.hi <= 0.0) return {std::max(0.0, down(a.hi * a.hi)), up(a.lo * a.lo), a.maybeNan};
    const double m = std::max(-a.lo, a.hi);
    return {0.0, up(m * m), a.maybeNan};
}

Interval powInt(const Interval& a, int n) {
    if (n == 0) return {1.0, 1.0, a.maybeNan};  // x⁰ = 1, including 0⁰ by convention
    if (n < 0) return Interval(1.0) / powInt(a, n == std::numeric_limits<int>::min() ? n + 2 : -n);
    const unsigned m = static_cast<unsigned>(n);
    if (a.lo >= 0.0)
        return {powNonNegative(a.lo, m, false), powNonNegative(a.hi, m, true), a.maybeNan};
    if (m % 2 == 1) {
        // Odd: increasing everywhere, and (−x)ⁿ = −xⁿ.
        const double lo =
            a.lo < 0.0 ? -powNonNegative(-a.lo, m, true) : powNonNegative(a.lo, m, false);
        const double hi =
            a.hi < 0.0 ? -powNonNegative(-a.hi, m, false) : powNonNegative(a.hi, m, true);
        return {lo, hi, a.maybeNan};
    }
    // Even: a function of |x|.
    const Interval m2 = abs(a);
    return {powNonNegative(m2.lo, m, false), powNonNegative(m2.hi, m, true), a.maybeNan};
}

Interval pow(const Interval& a, const Interval& b) {
    // Real powers are defined for a ≥ 0 only; the negative part of a makes maybeNan.
    const bool nan = anyNan(a, b) || a.lo < 0.0;
    if (a.hi < 0.0) return Interval::entire();
    const Interval base{std::max(a.lo, 0.0), a.hi};
    Interval r = exp(b * log(base));
    r.maybeNan = nan;
    return r;
}

Interval sqrt(const Interval& a) {
    // Partly negative input: the defined part [0, sqrt(hi)], with maybeNan.
    if (a.hi < 0.0) return Interval::entire();
    const bool nan = a.maybeNan || a.lo < 0.0;
    const double lo = a.lo <= 0.0 ? 0.0 : std::max(0.0, down(std::sqrt(a.lo)));
    return {lo, up(std::sqrt(a.hi)), nan};
}

Interval abs(const Interval& a) {
    if (a.lo >= 0.0) return a;
    if (a.hi <= 0.0) return -a;
    return {0.0, std::max(-a.lo, a.hi), a.maybeNan};
}

Interval exp(const Interval& a) {
    Interval r = increasing(a, [](double x) { return std::exp(x); });
    r.lo = std::max(r.lo, 0.0);
    return r;
}

Interval log(const Interval& a) {
    // log(0) = −inf is the lower bound; a negative part makes maybeNan.
    if (a.hi < 0.0) return Interval::entire();
    const bool nan = a.maybeNan || a.lo < 0.0;
    const double lo = a.lo <= 0.0 ? -kInfinity : down(std::log(a.lo), kLibmUlps);
    return {lo, up(std::log(a.hi), kLibmUlps), nan};
}

void sinCos(const Interval& a, Interval& s, Interval& c) {
    // The common case: no libm call (csg/interval/interval_trig.h).
    if (interval_trig::trySinCosFast(a, s, c)) return;
    // Beyond 2^50 the spacing of doubles exceeds what the quadrant test can resolve.
    if (!(a.hi - a.lo < kTwoPi) || std::fabs(a.lo) > 0x1p50 || std::fabs(a.hi) > 0x1p50) {
        s = c = {-1.0, 1.0, a.maybeNan};
        return;
    }
    // The extremes inside are at the multiples k·π/2 that may lie in [lo, hi]: by k mod 4,
    // cos = 1, sin = 1, cos = −1, sin = −1. One range reduction serves both functions; the
    // quotients are rounded, so the test is widened by a relative margin far above their error.
    const double qLo = a.lo * k2OverPi, qHi = a.hi * k2OverPi;
    const double margin = 1e-12 * (1.0 + std::max(std::fabs(qLo), std::fabs(qHi)));
    const double kLo = std::ceil(qLo - margin), kHi = std::floor(qHi + margin);
    unsigned extremes = 0;  // bit r: a multiple with k ≡ r (mod 4) may lie inside
    for (double k = kLo; k <= kHi && extremes != 15u; ++k)
        extremes |= 1u << (static_cast<int64_t>(k) & 3);  // two's complement: k mod 4
    const bool cosFull = (extremes & 5u) == 5u, sinFull = (extremes & 10u) == 10u;
    if (cosFull && sinFull) {  // wide pieces: no libm call at all
        s = c = {-1.0, 1.0, a.maybeNan};
        return;
    }
    double sl, cl, sh, ch;
    ::sincos(a.lo, &sl, &cl);
    ::sincos(a.hi, &sh, &ch);
    const double sLo = extremes & 8u ? -1.0 : down(std::min(sl, sh), kLibmUlps);
    const double sHi = extremes & 2u ? 1.0 : up(std::max(sl, sh), kLibmUlps);
    const double cLo = extremes & 4u ? -1.0 : down(std::min(cl, ch), kLibmUlps);
    const double cHi = extremes & 1u ? 1.0 : up(std::max(cl, ch), kLibmUlps);
    s = {std::max(sLo, -1.0), std::min(sHi, 1.0), a.maybeNan};
    c = {std::max(cLo, -1.0), std::min(cHi, 1.0), a.maybeNan};
}

Interval sin(const Interval& a) {
    Interval s, c;
    sinCos(a, s, c);
    return s;
}

Interval cos(const Interval& a) {
    Interval s, c;
    sinCos(a, s, c);
    return c;
}

Interval tan(const Interval& a) {
    // Increasing between poles at π/2 + kπ; a pole that may lie inside gives entire
    // (tan is undefined at the pole, hence maybeNan).
    if (!(a.hi - a.lo < kPiLo) || std::fabs(a.lo) > 0x1p50 || std::fabs(a.hi) > 0x1p50)
        return Interval::entire();
    if (mayHoldPhase(a.lo, a.hi, 0.5 * kPiLo, kPiLo)) return Interval::entire();
    return increasing(a, [](double x) { return std::tan(x); });
}

Interval asin(const Interval& a) {
    // Defined on [−1, 1]: clamp, and flag the part outside.
    if (a.lo > 1.0 || a.hi < -1.0) return Interval::entire();
    const bool nan = a.maybeNan || a.lo < -1.0 || a.hi > 1.0;
    Interval r = increasing(Interval{std::max(a.lo, -1.0), std::min(a.hi, 1.0)},
                            [](double x) { return std::asin(x); });
    r.maybeNan = nan;
    return r;
}

Interval acos(const Interval& a) {
    if (a.lo > 1.0 || a.hi < -1.0) return Interval::entire();
    const bool nan = a.maybeNan || a.lo < -1.0 || a.hi > 1.0;
    const double lo = std::min(a.hi, 1.0), hi = std::max(a.lo, -1.0);  // decreasing
    return {std::max(0.0, down(std::acos(lo), kLibmUlps)), up(std::acos(hi), kLibmUlps), nan};
}

Interval atan(const Interval& a) {
    return increasing(a, [](double x) { return std::atan(x); });
}

Interval atan2(const Interval& y, const Interval& x) {
    const bool nan = anyNan(y, x);
    // The box holds the origin: every angle (atan2(±0, ±0) returns 0 or ±π, all inside).
    // The box crosses the branch cut (x < 0, y = 0, with y < 0 also inside): the values
    // jump between −π and π. Both give [−π, π].
    const bool crossesCut = x.lo < 0.0 && y.lo < 0.0 && y.hi >= 0.0;
    if ((x.containsZero() && y.containsZero()) || crossesCut) return {-kPiHi, kPiHi, nan};
    // Otherwise atan2 is continuous on the box and, since the box is convex and misses the
    // origin, the extreme angles are at its corners. y = 0 counts as +0: atan2(0, x<0) = π.
    const double ys[2] = {y.lo + 0.0, y.hi + 0.0}, xs[2] = {x.lo, x.hi};
    double lo = kInfinity, hi = -kInfinity;
    for (double yy : ys)
        for (double xx : xs) {
            const double v = std::atan2(yy, xx);
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    return {std::max(-kPiHi, down(lo, kLibmUlps)), std::min(kPiHi, up(hi, kLibmUlps)), nan};
}

Interval min(const Interval& a, const Interval& b) {
    return {std::min(a.lo, b.lo), std::min(a.hi, b.hi), anyNan(a, b)};
}

Interval max(const Interval& a, const Interval& b) {
    return {std::max(a.lo, b.lo), std::max(a.hi, b.hi), anyNan(a, b)};
}

Interval floor(const Interval& a) { return {std::floor(a.lo), std::floor(a.hi), anyNan(a)}; }

Interval ceil(const Interval& a) { return {std::ceil(a.lo), std::ceil(a.hi), anyNan(a)}; }

Interval hull(const Interval& a, const Interval& b) {
    return {std::min(a.lo, b.lo), std::max(a.hi, b.hi), anyNan(a, b)};
}

}  // namespace kerf
