/// @file tests/util/oracles.h
/// @brief Long-double closed-form oracles and small helpers shared by the hard-case tests:
/// ray–sphere, ray–box, ray–infinite-cylinder in extended precision, seeded random vectors,
/// ulp stepping, and expression builders for the implicit test solids.
#pragma once

#include "csg/bvh/scene_geometry.h"
#include "csg/tape/expr.h"
#include "csg/tape/tape.h"
#include "csg/tree/solids.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <utility>

namespace kerf::test {

using LD = long double;
using LV3 = glm::tvec3<long double>;

inline LV3 ld(const Vec3& v) { return LV3(v.x, v.y, v.z); }
inline Vec3 unit(const Vec3& v) { return v / glm::length(v); }

/// One double ulp at 1 (2^-52).
constexpr double kUlp = 0x1p-52;

/// x moved k representable doubles toward `toward`.
inline double stepUlps(double x, int k, double toward) {
    for (int i = 0; i < k; ++i) x = std::nextafter(x, toward);
    return x;
}

/// A unit vector from three normal deviates (a fresh distribution per call, as the tests that
/// use it always drew them).
inline Vec3 gaussianUnit(std::mt19937_64& rng) {
    std::normal_distribution<double> n;
    const Vec3 v(n(rng), n(rng), n(rng));
    return v / glm::length(v);
}

/// Seeded random numbers for reproducible cases.
class Random {
public:
    explicit Random(uint64_t seed = std::mt19937_64::default_seed) : mRng(seed) {}
    /// Restarts the sequence, so a test case's numbers do not depend on which others ran.
    void seed(uint64_t s) { mRng.seed(s); }
    double uniform(double a, double b) {
        return std::uniform_real_distribution<double>(a, b)(mRng);
    }
    /// exp of a uniform value in [log a, log b]: magnitudes spread over decades.
    double logUniform(double a, double b) { return std::exp(uniform(std::log(a), std::log(b))); }
    Vec3 unitVector() {
        for (;;) {
            const Vec3 v(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
            const double l = glm::length(v);
            if (l > 0.1 && l <= 1.0) return v / l;
        }
    }
    Vec3 inBall() {
        for (;;) {
            const Vec3 v(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
            if (glm::dot(v, v) <= 1.0) return v;
        }
    }
    /// A unit vector perpendicular to u.
    Vec3 perpendicular(const Vec3& u) { return unit(glm::cross(u, unitVector())); }
    /// A unit vector from normal deviates (another sequence than unitVector's).
    Vec3 gaussianUnitVector() { return gaussianUnit(mRng); }
    std::mt19937_64& engine() { return mRng; }

private:
    std::mt19937_64 mRng;
};

/// Where a line meets a sphere, in long double: the chord through the line's point nearest the
/// centre (well conditioned even far away), and the miss margin (distance − r)/r.
struct SphereOracle {
    LD tMid = 0;       ///< parameter of the point nearest the centre
    LD halfChord = 0;  ///< in t units; 0 on a miss
    LD margin = 0;     ///< (line distance − r)/r: < 0 hit, > 0 miss
    bool hit() const { return margin < 0; }
    LD tIn() const { return tMid - halfChord; }
    LD tOut() const { return tMid + halfChord; }
};

/// The same from the origin relative to the centre, f, and the direction d, in long double
/// (also the cross-section of a cylinder or cone: f and d projected across the axis).
inline SphereOracle sphereOracleLD(const LV3& f, const LV3& d, LD r) {
    const LD a = glm::dot(d, d);
    SphereOracle o;
    o.tMid = -glm::dot(f, d) / a;
    const LV3 l = f + o.tMid * d;
    const LD dist2 = glm::dot(l, l);
    o.margin = (std::sqrt(dist2) - r) / r;
    if (dist2 < r * r) o.halfChord = std::sqrt((r * r - dist2) / a);
    return o;
}

inline SphereOracle sphereOracle(const Ray& ray, const LV3& c, LD r) {
    return sphereOracleLD(ld(ray.origin) - c, ld(ray.dir), r);
}

/// The entry of a line into a sphere (centre c, radius r) in long double, by SphereOracle's
/// chord; `normal` gets the outward normal there (not unit). Only for lines that hit.
inline LD sphereEntry(const Vec3& c, double r, const Ray& ray, LV3& normal) {
    const LV3 f = ld(ray.origin) - ld(c), d = ld(ray.dir);
    const SphereOracle o = sphereOracleLD(f, d, r);
    normal = (f + o.tMid * d) - o.halfChord * d;
    return o.tIn();
}

/// The slab test in long double; nullopt when the open box misses the line.
inline std::optional<std::pair<LD, LD>> boxOracle(const Ray& ray, const Vec3& lo, const Vec3& hi) {
    LD tin = -INFINITY, tout = INFINITY;
    for (int a = 0; a < 3; ++a) {
        const LD o = ray.origin[a], d = ray.dir[a];
        if (d == 0) {
            if (o < lo[a] || o > hi[a]) return std::nullopt;
            continue;
        }
        LD t0 = (LD(lo[a]) - o) / d, t1 = (LD(hi[a]) - o) / d;
        if (t0 > t1) std::swap(t0, t1);
        tin = std::max(tin, t0);
        tout = std::min(tout, t1);
    }
    if (!(tin < tout)) return std::nullopt;
    return std::make_pair(tin, tout);
}

/// Distance between a line and the infinite line through a along unit-ish axis u, in long
/// double (for grazing cylinder rays).
inline LD lineDistance(const Ray& ray, const LV3& a, const LV3& u) {
    const LV3 n = glm::cross(ld(ray.dir), u);
    return std::fabs(glm::dot(ld(ray.origin) - a, n)) / std::sqrt(glm::dot(n, n));
}

/// |p|² − r², the implicit sphere.
inline ExprId sphereExpr(ExprGraph& g, double r) {
    const ExprId s =
        g.binary(Op::Add, g.binary(Op::Add, g.unary(Op::Square, g.x()), g.unary(Op::Square, g.y())),
                 g.unary(Op::Square, g.z()));
    return g.binary(Op::Sub, s, g.constant(r * r));
}

/// sin x cos y + sin y cos z + sin z cos x
inline ExprId gyroidExpr(ExprGraph& g) {
    auto term = [&](ExprId a, ExprId b) {
        return g.binary(Op::Mul, g.unary(Op::Sin, a), g.unary(Op::Cos, b));
    };
    return g.binary(Op::Add, g.binary(Op::Add, term(g.x(), g.y()), term(g.y(), g.z())),
                    term(g.z(), g.x()));
}

/// |a − b| / |b| for a finite reference b ≠ 0.
inline LD relativeError(LD a, LD b) { return std::fabs(a - b) / std::fabs(b); }

}  // namespace kerf::test
