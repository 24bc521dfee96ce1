// The AVX2 path of Tape::evalInterval4: the scalar kernels of csg/interval/interval_ops.h,
// csg/interval/interval.cpp and csg/interval/interval_trig.h written again on four lanes, operation
// for operation, so each lane gives evalInterval's bits (tests/csg/tape_eval4_test.cpp):
// - the same IEEE operations in the same order; no FMA (target("avx2") does not enable it, and
//   the project builds with -ffp-contract=off as ISO C++ does), so nothing is contracted;
// - the one-ulp steps of interval_round.h on the bit patterns with 64-bit integer lanes;
// - std::min / std::max / "a < b ? a : b" as vminpd / vmaxpd with the operands in the order
//   that gives the same result for equal values, signed zeros and NaN (vminpd(a, b) is
//   a < b ? a : b);
// - the rare cases go lane by lane through the scalar code itself: products with a NaN end
//   product (0·inf), and sin/cos beyond interval_trig's fast range.
// Only this file's functions carry target("avx2"); the rest of kerf builds for the baseline.
#include "csg/interval/interval_ops.h"
#include "csg/interval/interval_trig.h"
#include "csg/tape/tape_eval_interval4.h"

#include <immintrin.h>

#define KERF_AVX2 __attribute__((target("avx2")))
#define KERF_AVX2_INLINE __attribute__((target("avx2"), always_inline)) inline

namespace kerf::interval4 {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// One instruction's result over the four lanes, with sin and cos of it once either is asked
/// for (the gyroid takes both of each argument: one reduction serves the two).
struct alignas(32) Slot {
    double lo[4], hi[4];
    double sLo[4], sHi[4], cLo[4], cHi[4];
    unsigned nan;  ///< bit k: lane k's maybeNan
    bool hasTrig;
};

using V = __m256d;
using I = __m256i;

KERF_AVX2_INLINE V splat(double v) { return _mm256_set1_pd(v); }
KERF_AVX2_INLINE V neg(V v) { return _mm256_xor_pd(v, splat(-0.0)); }
KERF_AVX2_INLINE V select(V mask, V yes, V no) { return _mm256_blendv_pd(no, yes, mask); }
KERF_AVX2_INLINE V lt(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_LT_OQ); }
KERF_AVX2_INLINE V isNan(V v) { return _mm256_cmp_pd(v, v, _CMP_UNORD_Q); }
/// a < b ? a : b, lane by lane (interval_kernel::lesser; std::min(b, a)).
KERF_AVX2_INLINE V lesser(V a, V b) { return _mm256_min_pd(a, b); }
/// a > b ? a : b (interval_kernel::greater; std::max(b, a)).
KERF_AVX2_INLINE V greater(V a, V b) { return _mm256_max_pd(a, b); }

/// interval_kernel::down: positive patterns step by −1, negative ones by +1; ±0 becomes
/// −denorm_min; −inf and NaN stay put.
KERF_AVX2_INLINE V down(V v) {
    const I b = _mm256_castpd_si256(v);
    const I negative = _mm256_cmpgt_epi64(_mm256_setzero_si256(), b);  // −1 where the sign is set
    const I step = _mm256_or_si256(negative, _mm256_set1_epi64x(1));
    V r = _mm256_castsi256_pd(_mm256_sub_epi64(b, step));
    r = select(_mm256_cmp_pd(v, _mm256_setzero_pd(), _CMP_EQ_OQ),
               splat(-std::numeric_limits<double>::denorm_min()), r);
    return select(_mm256_cmp_pd(v, splat(-kInf), _CMP_GT_OQ), r, v);
}
KERF_AVX2_INLINE V up(V v) { return neg(down(neg(v))); }
KERF_AVX2_INLINE V lowerEnd(V v) { return select(isNan(v), splat(-kInf), down(v)); }
KERF_AVX2_INLINE V upperEnd(V v) { return select(isNan(v), splat(kInf), up(v)); }

KERF_AVX2_INLINE V loadLo(const Slot& s) { return _mm256_load_pd(s.lo); }
KERF_AVX2_INLINE V loadHi(const Slot& s) { return _mm256_load_pd(s.hi); }
KERF_AVX2_INLINE void store(Slot& r, V lo, V hi) {
    _mm256_store_pd(r.lo, lo);
    _mm256_store_pd(r.hi, hi);
}

/// interval_kernel::mul; lanes whose end products sum to NaN take mulGeneral, as there.
KERF_AVX2_INLINE void mul(const Slot& a, const Slot& b, Slot& r) {
    const V aLo = loadLo(a), aHi = loadHi(a), bLo = loadLo(b), bHi = loadHi(b);
    const V p0 = _mm256_mul_pd(aLo, bLo), p1 = _mm256_mul_pd(aLo, bHi);
    const V p2 = _mm256_mul_pd(aHi, bLo), p3 = _mm256_mul_pd(aHi, bHi);
    const V sum = _mm256_add_pd(_mm256_add_pd(p0, p1), _mm256_add_pd(p2, p3));
    store(r, down(lesser(lesser(p0, p1), lesser(p2, p3))),
          up(greater(greater(p0, p1), greater(p2, p3))));
    int general = _mm256_movemask_pd(isNan(sum));
    while (general) {
        const int k = __builtin_ctz(general);
        general &= general - 1;
        const Interval v =
            interval_kernel::mulGeneral({a.lo[k], a.hi[k]}, {b.lo[k], b.hi[k]}, false);
        r.lo[k] = v.lo, r.hi[k] = v.hi;
    }
}

/// sqr (csg/interval/interval.cpp): by the sign of the operand, with std::max(0.0, ·) on the lower
/// end.
KERF_AVX2_INLINE void square(const Slot& a, Slot& r) {
    const V lo = loadLo(a), hi = loadHi(a), zero = _mm256_setzero_pd();
    const V nonNegative = _mm256_cmp_pd(lo, zero, _CMP_GE_OQ);
    const V nonPositive = _mm256_cmp_pd(hi, zero, _CMP_LE_OQ);
    const V ll = _mm256_mul_pd(lo, lo), hh = _mm256_mul_pd(hi, hi);
    const V m = greater(hi, neg(lo));  // std::max(−lo, hi)
    const V mm = _mm256_mul_pd(m, m);
    const V oneSign = _mm256_or_pd(nonNegative, nonPositive);
    const V rLo = select(oneSign, greater(down(select(nonNegative, ll, hh)), zero), zero);
    const V rHi = up(select(nonNegative, hh, select(nonPositive, ll, mm)));
    store(r, rLo, rHi);
}

/// abs (csg/interval/interval.cpp): a, −a, or [0, std::max(−lo, hi)].
KERF_AVX2_INLINE void absolute(const Slot& a, Slot& r) {
    const V lo = loadLo(a), hi = loadHi(a), zero = _mm256_setzero_pd();
    const V nonNegative = _mm256_cmp_pd(lo, zero, _CMP_GE_OQ);
    const V nonPositive = _mm256_cmp_pd(hi, zero, _CMP_LE_OQ);
    const V rLo = select(nonNegative, lo, select(nonPositive, neg(hi), zero));
    const V rHi = select(nonNegative, hi, select(nonPositive, neg(lo), greater(hi, neg(lo))));
    store(r, rLo, rHi);
}

/// interval_trig::pointTrig on four doubles: sin, cos, the reduced argument and k (a double).
struct PointTrig4 {
    V s, c, r, k;
};

/// c + s·acc: one step of Horner's rule.
KERF_AVX2_INLINE V horner(V s, V acc, double c) {
    return _mm256_add_pd(splat(c), _mm256_mul_pd(s, acc));
}

KERF_AVX2_INLINE PointTrig4 pointTrig(V x) {
    using namespace interval_trig;
    const V shift = splat(0x1.8p52);
    // x·2/π + 1.5·2⁵² holds round(x·2/π) in its low mantissa bits (two's complement mod 4).
    const V shifted = _mm256_add_pd(_mm256_mul_pd(x, splat(kTwoOverPi)), shift);
    const V kd = _mm256_sub_pd(shifted, shift);
    const V r = _mm256_sub_pd(_mm256_sub_pd(_mm256_sub_pd(x, _mm256_mul_pd(kd, splat(kP1))),
                                            _mm256_mul_pd(kd, splat(kP2))),
                              _mm256_mul_pd(kd, splat(kP3)));
    const V s = _mm256_mul_pd(r, r);
    // Horner from the innermost coefficient out, as interval_trig.h's nested expressions.
    V q = splat(-0x1.ae7f3e733b81fp-41);
    q = horner(s, q, 0x1.6124613a86d09p-33);
    q = horner(s, q, -0x1.ae64567f544e4p-26);
    q = horner(s, q, 0x1.71de3a556c734p-19);
    q = horner(s, q, -0x1.a01a01a01a01ap-13);
    q = horner(s, q, 0x1.1111111111111p-7);
    q = horner(s, q, -0x1.5555555555555p-3);
    q = horner(s, q, 1.0);
    V p = splat(0x1.ae7f3e733b81fp-45);
    p = horner(s, p, -0x1.93974a8c07c9dp-37);
    p = horner(s, p, 0x1.1eed8eff8d898p-29);
    p = horner(s, p, -0x1.27e4fb7789f5cp-22);
    p = horner(s, p, 0x1.a01a01a01a01ap-16);
    p = horner(s, p, -0x1.6c16c16c16c17p-10);
    p = horner(s, p, 0x1.5555555555555p-5);
    p = horner(s, p, -0.5);
    p = horner(s, p, 1.0);
    const V sr = _mm256_mul_pd(r, q);
    // By k mod 4: (sin, cos) = (sr, p), (p, −sr), (−sr, −p), (−p, sr).
    const I one = _mm256_set1_epi64x(1), two = _mm256_set1_epi64x(2);
    const I quadrant = _mm256_and_si256(_mm256_castpd_si256(shifted), _mm256_set1_epi64x(3));
    const V odd = _mm256_castsi256_pd(_mm256_cmpeq_epi64(_mm256_and_si256(quadrant, one), one));
    const V sinSign = _mm256_castsi256_pd(_mm256_slli_epi64(_mm256_and_si256(quadrant, two), 62));
    const V cosSign = _mm256_castsi256_pd(
        _mm256_slli_epi64(_mm256_and_si256(_mm256_add_epi64(quadrant, one), two), 62));
    return {_mm256_xor_pd(select(odd, p, sr), sinSign), _mm256_xor_pd(select(odd, sr, p), cosSign),
            r, kd};
}

/// All ones in the lanes of `bits` (64-bit integers) that have `bit` set.
KERF_AVX2_INLINE V hasBit(I bits, long long bit) {
    const I b = _mm256_set1_epi64x(bit);
    return _mm256_castsi256_pd(_mm256_cmpeq_epi64(_mm256_and_si256(bits, b), b));
}

/// sin and cos of slot a into its cache: interval_trig::sinCosFast on the lanes trySinCosFast
/// accepts, the scalar sinCos (its libm path) on the others.
KERF_AVX2_INLINE void sinCos(Slot& a) {
    using namespace interval_trig;
    const V lo = loadLo(a), hi = loadHi(a);
    const V fast =
        _mm256_and_pd(_mm256_and_pd(_mm256_cmp_pd(lo, splat(-kTrigFastLimit), _CMP_GE_OQ),
                                    _mm256_cmp_pd(hi, splat(kTrigFastLimit), _CMP_LE_OQ)),
                      lt(_mm256_sub_pd(hi, lo), splat(6.28)));
    const PointTrig4 l = pointTrig(lo);
    PointTrig4 h = pointTrig(hi);
    // sinCosFast reuses lo's values when hi == lo (the sign of a zero r may differ otherwise).
    const V same = _mm256_cmp_pd(lo, hi, _CMP_EQ_OQ);
    h.s = select(same, l.s, h.s), h.c = select(same, l.c, h.c);
    h.r = select(same, l.r, h.r), h.k = select(same, l.k, h.k);
    // The multiples j·π/2 that may lie inside: first ≤ j ≤ last (integers held exactly).
    const V reduction = splat(0x1p-51);
    const V first = _mm256_add_pd(l.k, _mm256_and_pd(lt(reduction, l.r), splat(1.0)));
    const V last = _mm256_sub_pd(h.k, _mm256_and_pd(lt(h.r, neg(reduction)), splat(1.0)));
    const V span = _mm256_sub_pd(last, first);
    // count = min(max(span + 1, 0), 4) multiples, as bits first mod 4 … rotated into 4 bits.
    I count = _mm256_setzero_si256();
    for (double d : {0.0, 1.0, 2.0, 3.0})
        count =
            _mm256_sub_epi64(count, _mm256_castpd_si256(_mm256_cmp_pd(span, splat(d), _CMP_GE_OQ)));
    const I one = _mm256_set1_epi64x(1);
    const I run = _mm256_sub_epi64(_mm256_sllv_epi64(one, count), one);
    const I start = _mm256_and_si256(_mm256_castpd_si256(_mm256_add_pd(first, splat(0x1.8p52))),
                                     _mm256_set1_epi64x(3));
    const I extremes = _mm256_and_si256(
        _mm256_or_si256(_mm256_sllv_epi64(run, start),
                        _mm256_srlv_epi64(run, _mm256_sub_epi64(_mm256_set1_epi64x(4), start))),
        _mm256_set1_epi64x(15));
    const V error = splat(kTrigError), one_ = splat(1.0), minusOne = splat(-1.0);
    const V sLo = select(hasBit(extremes, 8), minusOne,
                         greater(_mm256_sub_pd(lesser(l.s, h.s), error), minusOne));
    const V sHi =
        select(hasBit(extremes, 2), one_, lesser(_mm256_add_pd(greater(l.s, h.s), error), one_));
    const V cLo = select(hasBit(extremes, 4), minusOne,
                         greater(_mm256_sub_pd(lesser(l.c, h.c), error), minusOne));
    const V cHi =
        select(hasBit(extremes, 1), one_, lesser(_mm256_add_pd(greater(l.c, h.c), error), one_));
    _mm256_store_pd(a.sLo, sLo);
    _mm256_store_pd(a.sHi, sHi);
    _mm256_store_pd(a.cLo, cLo);
    _mm256_store_pd(a.cHi, cHi);
    int slow = _mm256_movemask_pd(fast) ^ 15;
    while (slow) {
        const int k = __builtin_ctz(slow);
        slow &= slow - 1;
        Interval s, c;
        kerf::sinCos({a.lo[k], a.hi[k]}, s, c);
        a.sLo[k] = s.lo, a.sHi[k] = s.hi, a.cLo[k] = c.lo, a.cHi[k] = c.hi;
    }
    a.hasTrig = true;
}

KERF_AVX2_INLINE void loadVariable(Slot& r, const Interval v[4]) {
    store(r, _mm256_setr_pd(v[0].lo, v[1].lo, v[2].lo, v[3].lo),
          _mm256_setr_pd(v[0].hi, v[1].hi, v[2].hi, v[3].hi));
    r.nan = unsigned(v[0].maybeNan) | unsigned(v[1].maybeNan) << 1 | unsigned(v[2].maybeNan) << 2 |
            unsigned(v[3].maybeNan) << 3;
}

}  // namespace

KERF_AVX2 bool evalAvx2(const std::vector<TapeInstr>& instrs, const Interval x[4],
                        const Interval y[4], const Interval z[4], Interval out[4]) {
    thread_local std::vector<Slot> slots;
    const size_t n = instrs.size();
    if (slots.size() < n) slots.resize(n);
    Slot* s = slots.data();
    for (size_t i = 0; i < n; ++i) {
        const TapeInstr& in = instrs[i];
        Slot& r = s[i];
        r.hasTrig = false;
        switch (in.op) {
            case Op::Const:
                store(r, splat(in.value), splat(in.value));
                r.nan = std::isnan(in.value) ? 0xFu : 0u;  // as Interval(NaN): flagged
                continue;
            case Op::VarX: loadVariable(r, x); continue;
            case Op::VarY: loadVariable(r, y); continue;
            case Op::VarZ: loadVariable(r, z); continue;
            default: break;
        }
        // Every other op's flag is its operands' flags or-ed (interval_ops.h, interval.cpp).
        Slot& a = s[in.a];
        r.nan = a.nan | (in.b >= 0 ? s[in.b].nan : 0u);
        switch (in.op) {
            case Op::Add:
                store(r, lowerEnd(_mm256_add_pd(loadLo(a), loadLo(s[in.b]))),
                      upperEnd(_mm256_add_pd(loadHi(a), loadHi(s[in.b]))));
                break;
            case Op::Sub:
                store(r, lowerEnd(_mm256_sub_pd(loadLo(a), loadHi(s[in.b]))),
                      upperEnd(_mm256_sub_pd(loadHi(a), loadLo(s[in.b]))));
                break;
            case Op::Mul: mul(a, s[in.b], r); break;
            case Op::Neg: store(r, neg(loadHi(a)), neg(loadLo(a))); break;
            case Op::Square: square(a, r); break;
            case Op::Abs: absolute(a, r); break;
            case Op::Min:  // std::min(a, b) is b < a ? b : a
                store(r, lesser(loadLo(s[in.b]), loadLo(a)), lesser(loadHi(s[in.b]), loadHi(a)));
                break;
            case Op::Max:  // std::max(a, b) is a < b ? b : a
                store(r, greater(loadLo(s[in.b]), loadLo(a)), greater(loadHi(s[in.b]), loadHi(a)));
                break;
            case Op::Sin:
                if (!a.hasTrig) sinCos(a);
                store(r, _mm256_load_pd(a.sLo), _mm256_load_pd(a.sHi));
                break;
            case Op::Cos:
                if (!a.hasTrig) sinCos(a);
                store(r, _mm256_load_pd(a.cLo), _mm256_load_pd(a.cHi));
                break;
            default: return false;  // not vectorised: the caller runs the scalar path
        }
    }
    const Slot& f = s[n - 1];
    for (int k = 0; k < 4; ++k) out[k] = {f.lo[k], f.hi[k], bool(f.nan >> k & 1u)};
    return true;
}

}  // namespace kerf::interval4
