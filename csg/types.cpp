// Bounds and affine maps: the small geometric helpers behind every module.
#include "csg/types.h"

#include "csg/affine_check.h"
#include "csg/bvh/clip_ray.h"

#include <algorithm>

namespace kerf {

bool Bounds3::finite() const {
    for (int a = 0; a < 3; ++a)
        if (!std::isfinite(lo[a]) || !std::isfinite(hi[a])) return false;
    return true;
}

Bounds3 Bounds3::hull(const Bounds3& a, const Bounds3& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    return {glm::min(a.lo, b.lo), glm::max(a.hi, b.hi)};
}

Bounds3 Bounds3::overlap(const Bounds3& a, const Bounds3& b) {
    return {glm::max(a.lo, b.lo), glm::min(a.hi, b.hi)};
}

bool Bounds3::contains(const Vec3& p) const {
    return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
}

bool Bounds3::clipRay(const Ray& ray, double& tmin, double& tmax) const {
    return clipRayExact(*this, ray, tmin, tmax);
}

namespace {
/// The slab test by division, widened by a few ulps of t at the end: for rays whose
/// reciprocal overflows or ranges that reach below t = 0, where RayReciprocal's margins do not
/// hold. The division's rounding (≤ 3 ulps of t) must not cull a box the exact segment meets.
template <class T>
bool clipRayWidened(const RayReciprocal& r, const T* lo, const T* hi, double& tmin, double& tmax) {
    double t0 = -kInf, t1 = kInf;
    for (int a = 0; a < 3; ++a) {
        const double o = r.origin[a], d = r.dir[a];
        if (d == 0.0) {  // also −0: parallel to the slab, inside it or not (exact)
            if (o < lo[a] || o > hi[a]) return false;
            continue;
        }
        double s0 = (lo[a] - o) / d, s1 = (hi[a] - o) / d;
        if (s0 > s1) std::swap(s0, s1);
        t0 = std::max(t0, s0);
        t1 = std::min(t1, s1);
    }
    constexpr double kWiden = 0x1p-50, kTiny = 0x1p-1074;
    t0 = t0 * (t0 > 0.0 ? 1.0 - kWiden : 1.0 + kWiden) - kTiny;
    t1 = t1 * (t1 > 0.0 ? 1.0 + kWiden : 1.0 - kWiden) + kTiny;
    tmin = std::max(tmin, t0);
    tmax = std::min(tmax, t1);
    return tmin <= tmax;
}
}  // namespace

bool Bounds3::clipRayDividing(const RayReciprocal& r, const float* lo, const float* hi,
                              double& tmin, double& tmax) {
    return clipRayWidened(r, lo, hi, tmin, tmax);
}

bool Bounds3::clipRayDividing(const RayReciprocal& r, const double* lo, const double* hi,
                              double& tmin, double& tmax) {
    return clipRayWidened(r, lo, hi, tmin, tmax);
}

Affine Affine::inverse() const {
    // glm::inverse forms the determinant, a product of three entries: it overflows for a map
    // scaled by 1e103 and underflows for 1e-103. The equilibrated matrix n has entries near 1,
    // and linear⁻¹ = 2^-colExp · n⁻¹ · 2^-rowExp. Power-of-two scaling is exact, so in the
    // normal range this gives the same bits as inverting `linear` directly.
    int rowExp[3], colExp[3];
    const Mat3 ni = glm::inverse(equilibrate(linear, rowExp, colExp));
    Affine r;
    for (int c = 0; c < 3; ++c)
        for (int row = 0; row < 3; ++row)
            r.linear[c][row] = std::ldexp(ni[c][row], -colExp[row] - rowExp[c]);
    r.offset = -(r.linear * offset);
    return r;
}

Affine Affine::after(const Affine& inner) const {
    Affine r;
    r.linear = linear * inner.linear;
    r.offset = linear * inner.offset + offset;
    return r;
}

Bounds3 Affine::map(const Bounds3& b) const {
    if (b.empty()) return b;
    // Arvo's method: each output axis is offset + Σ over input axes of the extreme products.
    Bounds3 r{offset, offset};
    for (int row = 0; row < 3; ++row) {
        for (int col = 0; col < 3; ++col) {
            const double m = linear[col][row];
            if (m == 0.0) continue;  // avoids 0·inf for unbounded boxes
            const double e = m * b.lo[col], f = m * b.hi[col];
            r.lo[row] += std::min(e, f);
            r.hi[row] += std::max(e, f);
        }
    }
    return r;
}

Affine Affine::translate(const Vec3& t) {
    Affine r;
    r.offset = t;
    return r;
}

Affine Affine::scale(const Vec3& s) {
    Affine r;
    r.linear = Mat3(s.x, 0, 0, 0, s.y, 0, 0, 0, s.z);
    return r;
}

namespace {
// cos/sin of an angle in degrees, exact at multiples of 90° so axis-aligned rotations stay exact.
void cosSinDegrees(double deg, double& c, double& s) {
    const double q = deg / 90.0;
    if (q == std::floor(q) && std::fabs(q) < 1e15) {
        const long k = ((static_cast<long>(q) % 4) + 4) % 4;
        const double cs[4] = {1, 0, -1, 0}, sn[4] = {0, 1, 0, -1};
        c = cs[k];
        s = sn[k];
        return;
    }
    const double r = deg * (M_PI / 180.0);
    c = std::cos(r);
    s = std::sin(r);
}
}  // namespace

Affine Affine::rotateDegrees(const Vec3& xyz) {
    double c, s;
    cosSinDegrees(xyz.x, c, s);
    const Mat3 rx(1, 0, 0, 0, c, s, 0, -s, c);
    cosSinDegrees(xyz.y, c, s);
    const Mat3 ry(c, 0, -s, 0, 1, 0, s, 0, c);
    cosSinDegrees(xyz.z, c, s);
    const Mat3 rz(c, s, 0, -s, c, 0, 0, 0, 1);
    Affine r;
    r.linear = rz * ry * rx;  // x first, then y, then z
    return r;
}

Affine Affine::fromRowMajor(const double m[12]) {
    Affine r;
    for (int row = 0; row < 3; ++row) {
        for (int col = 0; col < 3; ++col) r.linear[col][row] = m[row * 4 + col];
        r.offset[row] = m[row * 4 + 3];
    }
    return r;
}

}  // namespace kerf
