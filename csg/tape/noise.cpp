// Gradient noise: the value in double and long double, the gradient, and enclosures over a
// box. The value's operations are those of the noise kerf's patterns have always used, in the
// same order, so pattern colours keep their bits.
#include "csg/tape/noise.h"

#include "csg/interval/interval_ops.h"
#include "csg/mix_bits.h"

#include <algorithm>
#include <cmath>

namespace kerf {
namespace {

/// The 12 directions to the edges' midpoints of a cube (Perlin 2002).
constexpr double kGradients[12][3] = {{1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0},
                                      {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
                                      {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}};

/// A bound on the rounding error of a point value (about 40 operations on numbers of
/// magnitude below 2, each rounding by at most 2⁻⁵³ of its result).
constexpr double kNoiseRounding = 1e-13;

/// Beyond this every double is an integer: the offset into the cell, and so the noise, is 0
/// (and the lattice index would overflow further out).
constexpr double kLatticeLimit = 0x1p52;

const double* gradientAt(int64_t i, int64_t j, int64_t k, uint64_t seed) {
    const uint64_t h = mixBits(mixBits(mixBits(seed ^ uint64_t(i)) ^ uint64_t(j)) ^ uint64_t(k));
    return kGradients[h % 12];
}

/// 6t⁵ − 15t⁴ + 10t³: zero first and second derivatives at 0 and 1.
template <typename T>
T fade(T t) {
    return t * t * t * (t * (t * T(6) - T(15)) + T(10));
}

/// fade′(t) = 30t²(t − 1)².
template <typename T>
T fadeSlope(T t) {
    return T(30) * t * t * (t - T(1)) * (t - T(1));
}

template <typename T>
T lerp(T a, T b, T t) {
    return a + t * (b - a);
}

/// The lattice cell of p and p's offset in it; false where p is NaN or too far out.
template <typename T>
bool locate(const T p[3], int64_t cell[3], T offset[3]) {
    for (int a = 0; a < 3; ++a) {
        if (!(std::fabs(p[a]) < T(kLatticeLimit))) return false;
        const T f = std::floor(p[a]);
        cell[a] = int64_t(f);
        offset[a] = p[a] - f;
    }
    return true;
}

template <typename T>
T noiseValue(const T p[3], uint64_t seed) {
    int64_t cell[3];
    T o[3];
    if (!locate(p, cell, o)) return std::isnan(p[0] + p[1] + p[2]) ? p[0] + p[1] + p[2] : T(0);
    T c[2][2][2];
    for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b)
            for (int d = 0; d < 2; ++d) {
                const double* g = gradientAt(cell[0] + a, cell[1] + b, cell[2] + d, seed);
                c[a][b][d] =
                    T(g[0]) * (o[0] - T(a)) + T(g[1]) * (o[1] - T(b)) + T(g[2]) * (o[2] - T(d));
            }
    const T u = fade(o[0]), v = fade(o[1]), w = fade(o[2]);
    const T v0 = lerp(lerp(c[0][0][0], c[1][0][0], u), lerp(c[0][1][0], c[1][1][0], u), v);
    const T v1 = lerp(lerp(c[0][0][1], c[1][0][1], u), lerp(c[0][1][1], c[1][1][1], u), v);
    return std::clamp(lerp(v0, v1, w), T(-1), T(1));
}

/// A value with its gradient, for the point gradient.
struct GradDual {
    double v;
    Vec3 g;
};

GradDual lerp(const GradDual& a, const GradDual& b, const GradDual& t) {
    return {a.v + t.v * (b.v - a.v), a.g + t.g * (b.v - a.v) + t.v * (b.g - a.g)};
}

// ---- Enclosures ----

Interval clampUnit(const Interval& t) {
    return {std::clamp(t.lo, 0.0, 1.0), std::clamp(t.hi, 0.0, 1.0)};
}

// The enclosures run inline, with the evaluators' kernels (csg/interval/interval_ops.h): they are
// most of the cost of tracing a displaced solid.
using interval_kernel::down;
using interval_kernel::up;

[[gnu::always_inline]] inline Interval join(const Interval& a, const Interval& b) {
    return {std::min(a.lo, b.lo), std::max(a.hi, b.hi), a.maybeNan || b.maybeNan};
}

/// (1 − t)·A + t·B for one t in [0, 1], enclosed: both weights are ≥ 0, so each end of the
/// result comes from the matching ends of A and B (1 − t is enclosed, as it may round).
[[gnu::always_inline]] inline Interval mixAt(const Interval& A, const Interval& B, double t) {
    const double wLo = down(1.0 - t), wHi = up(1.0 - t);
    const double lo = down(down((A.lo >= 0.0 ? wLo : wHi) * A.lo) + down(t * B.lo));
    const double hi = up(up((A.hi >= 0.0 ? wHi : wLo) * A.hi) + up(t * B.hi));
    return {std::max(lo, std::min(A.lo, B.lo)), std::min(hi, std::max(A.hi, B.hi)),
            A.maybeNan || B.maybeNan};
}

/// The range of a + t·(b − a) for a ∈ A, b ∈ B, t ∈ T ⊂ [0, 1], taking a, b and t as
/// independent: it is (1 − t)·a + t·b with both weights ≥ 0, so linear in each argument, and
/// its extremes are at T's ends with A's and B's matching ends. (A convex combination never
/// leaves [min(A.lo, B.lo), max(A.hi, B.hi)]: mixAt clips its rounding to that.)
Interval lerpRange(const Interval& A, const Interval& B, const Interval& T) {
    return T.lo == T.hi ? mixAt(A, B, T.lo) : join(mixAt(A, B, T.lo), mixAt(A, B, T.hi));
}

/// fade over [0, 1] is increasing: its range over [lo, hi] is its values at the ends, each
/// enclosed by interval arithmetic on the point.
Interval fadeRange(const Interval& o) {
    const auto at = [](double t) {
        using namespace interval_kernel;
        const Interval T(t);
        const Interval inner =
            add(mul(T, sub(mul(T, Interval(6.0)), Interval(15.0))), Interval(10.0));
        return mul(mul(mul(T, T), T), inner);
    };
    return {std::clamp(at(o.lo).lo, 0.0, 1.0), std::clamp(at(o.hi).hi, 0.0, 1.0)};
}

/// Interpolates c over the axes other than `skip` (lower axis first) with weights W; with
/// skip = −1, over all three.
Interval interpolate(const Interval c[2][2][2], const Interval W[3], int skip, int side) {
    Interval face[2][2];  // over the two remaining axes
    for (int m = 0; m < 2; ++m)
        for (int n = 0; n < 2; ++n) {
            if (skip == 0) face[m][n] = c[side][m][n];
            if (skip == 1) face[m][n] = c[m][side][n];
            if (skip == 2) face[m][n] = c[m][n][side];
        }
    if (skip < 0) {
        Interval edges[2][2];
        for (int b = 0; b < 2; ++b)
            for (int d = 0; d < 2; ++d) edges[b][d] = lerpRange(c[0][b][d], c[1][b][d], W[0]);
        return lerpRange(lerpRange(edges[0][0], edges[1][0], W[1]),
                         lerpRange(edges[0][1], edges[1][1], W[1]), W[2]);
    }
    const int first = skip == 0 ? 1 : 0, second = skip == 2 ? 1 : 2;
    return lerpRange(lerpRange(face[0][0], face[1][0], W[first]),
                     lerpRange(face[0][1], face[1][1], W[first]), W[second]);
}

/// The noise over a box inside one lattice cell (lo = the cell's corner), and its gradient
/// when `gradient` is not null.
Interval cellRange(const int64_t cell[3], const Interval box[3], uint64_t seed,
                   Interval* gradient) {
    using interval_kernel::add;
    using interval_kernel::sub;
    Interval o[2][3], W[3];  // o[s][a]: the offset from the cell's corner s (0 or 1) along a
    for (int a = 0; a < 3; ++a) {
        o[0][a] = clampUnit(sub(box[a], Interval(double(cell[a]))));
        o[1][a] = sub(o[0][a], Interval(1.0));
        W[a] = fadeRange(o[0][a]);
    }
    Interval c[2][2][2], g[3][2][2][2];
    for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b)
            for (int d = 0; d < 2; ++d) {
                const double* k = gradientAt(cell[0] + a, cell[1] + b, cell[2] + d, seed);
                // g · offset with every g component −1, 0 or 1: sums and negations, exact.
                const int side[3] = {a, b, d};
                Interval sum(0.0);
                for (int axis = 0; axis < 3; ++axis) {
                    const Interval& off = o[side[axis]][axis];
                    if (k[axis] > 0.0) sum = add(sum, off);
                    if (k[axis] < 0.0) sum = sub(sum, off);
                    g[axis][a][b][d] = Interval(k[axis]);
                }
                c[a][b][d] = sum;
            }
    const Interval value = interpolate(c, W, -1, 0);
    if (!gradient) return value;
    // ∂n/∂x_k = fade′(o_k)·(the far face's interpolation − the near face's) + the gradients'
    // own interpolation.
    for (int axis = 0; axis < 3; ++axis) {
        using interval_kernel::mul;
        const Interval across = sub(interpolate(c, W, axis, 1), interpolate(c, W, axis, 0));
        const Interval t = o[0][axis];
        const Interval slope = mul(mul(Interval(30.0), mul(t, t)), mul(o[1][axis], o[1][axis]));
        gradient[axis] = add(mul(slope, across), interpolate(g[axis], W, -1, 0));
    }
    return value;
}

/// The clamp to [−1, 1] applied to an enclosure N of the unclamped noise and to its slopes
/// (if any).
Interval clampNoise(Interval N, Interval* gradient) {
    if (N.lo >= -1.0 && N.hi <= 1.0) return N;
    const bool flat = N.hi <= -1.0 || N.lo >= 1.0;  // the clamp holds all over
    for (int a = 0; gradient && a < 3; ++a)
        gradient[a] = flat ? Interval(0.0) : hull(gradient[a], Interval(0.0));
    return {std::clamp(N.lo, -1.0, 1.0), std::clamp(N.hi, -1.0, 1.0), N.maybeNan};
}

}  // namespace

double gradientNoise(const Vec3& p, uint64_t seed) {
    const double q[3] = {p.x, p.y, p.z};
    return noiseValue(q, seed);
}

long double gradientNoise(const glm::tvec3<long double>& p, uint64_t seed) {
    const long double q[3] = {p.x, p.y, p.z};
    return noiseValue(q, seed);
}

double gradientNoise(const Vec3& p, uint64_t seed, Vec3& gradient) {
    const double q[3] = {p.x, p.y, p.z};
    gradient = Vec3(0.0);
    int64_t cell[3];
    double o[3];
    if (!locate(q, cell, o)) return noiseValue(q, seed);  // NaN, or 0 far out
    GradDual c[2][2][2];
    for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b)
            for (int d = 0; d < 2; ++d) {
                const double* g = gradientAt(cell[0] + a, cell[1] + b, cell[2] + d, seed);
                c[a][b][d] = {g[0] * (o[0] - a) + g[1] * (o[1] - b) + g[2] * (o[2] - d),
                              Vec3(g[0], g[1], g[2])};
            }
    const GradDual u{fade(o[0]), Vec3(fadeSlope(o[0]), 0, 0)},
        v{fade(o[1]), Vec3(0, fadeSlope(o[1]), 0)}, w{fade(o[2]), Vec3(0, 0, fadeSlope(o[2]))};
    const GradDual v0 = lerp(lerp(c[0][0][0], c[1][0][0], u), lerp(c[0][1][0], c[1][1][0], u), v);
    const GradDual v1 = lerp(lerp(c[0][0][1], c[1][0][1], u), lerp(c[0][1][1], c[1][1][1], u), v);
    // The same operations as noiseValue's on the values, so the same bits.
    const GradDual n = lerp(v0, v1, w);
    const double value = std::clamp(n.v, -1.0, 1.0);
    if (std::fabs(value) != 1.0) gradient = n.g;  // 0 where the clamp holds
    return value;
}

// The global slope bound. Write n = Σ W_a(u) W_b(v) W_d(w) c_abd with W_0(s) = 1 − s,
// W_1(s) = s, u = fade(x − i) and c_abd = g_abd · (offset to the corner). Then
// ∂n/∂x = fade′(x − i)·(L₁ − L₀) + Σ W W W g_x, where L_a interpolates c_abd over v and w.
// Each g has two components ±1 and one 0 and every offset component is in [−1, 1], so
// |c| ≤ 2, |L₁ − L₀| ≤ 4; fade′ ≤ 30/16 (at ½); the weights sum to 1 and |g_x| ≤ 1. So
// |∂n/∂x| ≤ 1.875·4 + 1 = 8.5, and the same for y and z; the clamp only lowers slopes.
Interval gradientNoiseRange(const Interval& x, const Interval& y, const Interval& z, uint64_t seed,
                            Interval* gradient) {
    const Interval box[3] = {x, y, z};
    const bool nan = x.maybeNan || y.maybeNan || z.maybeNan;
    // The cells the box meets along each axis.
    double first[3], count[3];
    bool nearby = true;
    for (int a = 0; a < 3; ++a) {
        nearby =
            nearby && std::fabs(box[a].lo) < kLatticeLimit && std::fabs(box[a].hi) < kLatticeLimit;
        if (!nearby) break;
        first[a] = std::floor(box[a].lo);
        count[a] = std::floor(box[a].hi) - first[a] + 1.0;
    }
    for (int a = 0; gradient && a < 3; ++a)
        gradient[a] = Interval(-kNoiseSlopeBound, kNoiseSlopeBound);
    if (!nearby) return {-1.0, 1.0, nan};
    if (count[0] * count[1] * count[2] > 1.0) {
        // Across cell walls: the mean-value form about a point c of the box, n(c) ± 8.5·Σ w_k
        // (w_k the farthest reach from c along axis k), which is as tight as enclosing each
        // cell for the small boxes that straddle a wall and far cheaper; wide boxes end at
        // [−1, 1] either way. kNoiseRounding covers the rounding of n(c) (a nearby dozen
        // operations on numbers below 2).
        double c[3], reach = 0.0;
        for (int a = 0; a < 3; ++a) {
            c[a] = std::clamp(box[a].mid(), box[a].lo, box[a].hi);
            reach = roundUp(
                reach + roundUp(std::max(roundUp(box[a].hi - c[a]), roundUp(c[a] - box[a].lo))));
        }
        const double centre = gradientNoise(Vec3(c[0], c[1], c[2]), seed);
        const double spread = roundUp(roundUp(kNoiseSlopeBound * reach) + kNoiseRounding);
        return {std::max(-1.0, roundDown(centre - spread)), std::min(1.0, roundUp(centre + spread)),
                nan};
    }
    // Inside one cell: the interpolation itself, enclosed.
    const int64_t cell[3] = {int64_t(first[0]), int64_t(first[1]), int64_t(first[2])};
    Interval result = clampNoise(cellRange(cell, box, seed, gradient), gradient);
    result.maybeNan = result.maybeNan || nan;
    return result;
}

}  // namespace kerf
