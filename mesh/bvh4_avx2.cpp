// The wide tree's walks on AVX2 lanes, in double.
// - Boxes: a node's four boxes at once: the float corners widened exactly to double, then per
//   lane the operations of Bounds3::clipRayConservative in the same order, and vmaxpd / vminpd
//   with the operands placed so NaN and equal values resolve as the scalar
//   "if (near > tmin) tmin = near" does. Rays the margins of RayReciprocal do not cover (a
//   range reaching below 0, a subnormal direction) take the scalar test.
// - Triangles: a pack's four at once, intersectWatertight's operations in its order up to t;
//   a lane whose three edge values all pass its filter (clearly away from 0) is decided here
//   with the same bits, any other lane goes to intersectWatertight itself.
// No FMA anywhere: target("avx2") does not enable it and the module builds with
// -ffp-contract=off. Only this file's code carries target("avx2"); the rest of kerf builds for
// the baseline. The shared headers are read first without it, then the walk templates under
// it (all always_inline), so the walks inline the AVX2 tests.
#include "csg/types.h"
#include "mesh/triangle_bvh.h"
#include "mesh/watertight_triangle.h"

#include <immintrin.h>

#include <cstdint>
#include <limits>
#include <vector>

// GCC takes the target from push_options; clang ignores that and needs its own attribute
// pragma, or the always_inline AVX2 tests could not be inlined into the walks.
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2")
#endif
#include "mesh/bvh4_queries.h"

#define KERF_AVX2_INLINE __attribute__((target("avx2"), always_inline)) inline

namespace kerf::bvh4 {
namespace {

struct Avx2Lanes {
    const RayReciprocal& rec;
    ScalarLanes scalar;
    __m256d origin[3], invNear[3], invFar[3];
    int nearHi[3];  ///< 1 when the near plane of axis a is the box's hi (direction negative)
    // The sheared frame (watertight_triangle.h): the permutation and the shear.
    int kx, ky, kz;
    __m256d sx, sy, sz;

    KERF_AVX2_INLINE Avx2Lanes(const RayReciprocal& r, const ShearedRay& s)
        : rec(r), scalar(r, s), kx(s.kx), ky(s.ky), kz(s.kz) {
        for (int a = 0; a < 3; ++a) {
            origin[a] = _mm256_set1_pd(r.origin[a]);
            invNear[a] = _mm256_set1_pd(r.invNear[a]);
            invFar[a] = _mm256_set1_pd(r.invFar[a]);
            nearHi[a] = r.negative[a];
        }
        sx = _mm256_set1_pd(s.sx);
        sy = _mm256_set1_pd(s.sy);
        sz = _mm256_set1_pd(s.sz);
    }

    KERF_AVX2_INLINE unsigned test(const WideNode& n, double tmin, double tmax, double t[4]) const {
        if (!rec.finite || !(tmin >= 0.0)) return scalar.test(n, tmin, tmax, t);
        __m256d t0 = _mm256_set1_pd(tmin), t1 = _mm256_set1_pd(tmax);
#pragma GCC unroll 3
        for (int a = 0; a < 3; ++a) {
            const float* nearPlane = nearHi[a] ? n.hi[a] : n.lo[a];
            const float* farPlane = nearHi[a] ? n.lo[a] : n.hi[a];
            const __m256d nearT = _mm256_mul_pd(
                _mm256_sub_pd(_mm256_cvtps_pd(_mm_load_ps(nearPlane)), origin[a]), invNear[a]);
            const __m256d farT = _mm256_mul_pd(
                _mm256_sub_pd(_mm256_cvtps_pd(_mm_load_ps(farPlane)), origin[a]), invFar[a]);
            t0 = _mm256_max_pd(nearT, t0);  // nearT > t0 ? nearT : t0 (NaN keeps t0)
            t1 = _mm256_min_pd(farT, t1);   // farT < t1 ? farT : t1
        }
        const __m256d ok = _mm256_and_pd(_mm256_cmp_pd(t0, t1, _CMP_LE_OQ),
                                         _mm256_cmp_pd(t0, _mm256_set1_pd(kInf), _CMP_LT_OQ));
        _mm256_storeu_pd(t, t0);
        return unsigned(_mm256_movemask_pd(ok));
    }

    /// edgeFunction's fast branch on four lanes: q × p, and whether it is clearly away from 0
    /// (else the lane goes to the reference test).
    KERF_AVX2_INLINE static __m256d edge(__m256d px, __m256d py, __m256d qx, __m256d qy,
                                         __m256d& sure) {
        const __m256d absMask = _mm256_castsi256_pd(_mm256_set1_epi64x(0x7fffffffffffffffLL));
        const __m256d m = _mm256_mul_pd(qx, py), n = _mm256_mul_pd(qy, px);
        const __m256d r = _mm256_sub_pd(m, n);
        const __m256d bound =
            _mm256_mul_pd(_mm256_set1_pd(0x1p-50),
                          _mm256_add_pd(_mm256_and_pd(m, absMask), _mm256_and_pd(n, absMask)));
        sure = _mm256_and_pd(sure, _mm256_cmp_pd(_mm256_and_pd(r, absMask), bound, _CMP_GT_OQ));
        return r;
    }

    /// intersectWatertight on four lanes up to t, operation for operation: lanes whose edge
    /// signs the rounded values settle are decided here, the rest left exact.
    KERF_AVX2_INLINE void packTest(const TriPack& p, unsigned lanes, PackResult& out) const {
        __m256d x[3], y[3], z[3];
#pragma GCC unroll 3
        for (int j = 0; j < 3; ++j) {
            const __m256d dx = _mm256_sub_pd(_mm256_load_pd(p.p[j][kx]), origin[kx]);
            const __m256d dy = _mm256_sub_pd(_mm256_load_pd(p.p[j][ky]), origin[ky]);
            const __m256d dz = _mm256_sub_pd(_mm256_load_pd(p.p[j][kz]), origin[kz]);
            x[j] = _mm256_sub_pd(dx, _mm256_mul_pd(sx, dz));
            y[j] = _mm256_sub_pd(dy, _mm256_mul_pd(sy, dz));
            z[j] = _mm256_mul_pd(sz, dz);
        }
        __m256d sure = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
        const __m256d u = edge(x[1], y[1], x[2], y[2], sure);  // edge p1 → p2
        const __m256d v = edge(x[2], y[2], x[0], y[0], sure);  // edge p2 → p0
        const __m256d w = edge(x[0], y[0], x[1], y[1], sure);  // edge p0 → p1
        const __m256d det = _mm256_add_pd(_mm256_add_pd(u, v), w);
        // Signs differ where the xor has its sign bit; NaN and a zero area miss.
        const __m256d differ = _mm256_or_pd(_mm256_xor_pd(u, v), _mm256_xor_pd(u, w));
        const __m256d numerator = _mm256_add_pd(
            _mm256_add_pd(_mm256_mul_pd(u, z[0]), _mm256_mul_pd(v, z[1])), _mm256_mul_pd(w, z[2]));
        const __m256d t = _mm256_div_pd(numerator, det);
        const unsigned sureMask = unsigned(_mm256_movemask_pd(sure)) & lanes;
        const unsigned missMask =
            unsigned(_mm256_movemask_pd(differ)) |
            unsigned(_mm256_movemask_pd(_mm256_cmp_pd(det, det, _CMP_UNORD_Q))) |
            unsigned(_mm256_movemask_pd(_mm256_cmp_pd(det, _mm256_setzero_pd(), _CMP_EQ_OQ)));
        out.exact = lanes & ~sureMask;
        out.hit = sureMask & ~missMask;
        _mm256_storeu_pd(out.t, t);
        _mm256_storeu_pd(out.det, det);
        _mm256_storeu_pd(out.v, v);
        _mm256_storeu_pd(out.w, w);
    }
};

}  // namespace

namespace avx2 {

bool closestHit(const View& v, const Ray& ray, double tmin, double tmax, TriangleHit& hit,
                BvhStats& stats) {
    return bvh4::closestHit<Avx2Lanes>(v, ray, tmin, tmax, hit, stats);
}

bool anyHit(const View& v, const Ray& ray, double tmin, double tmax, BvhStats& stats) {
    return bvh4::anyHit<Avx2Lanes>(v, ray, tmin, tmax, stats);
}

void allCrossings(const View& v, const Ray& ray, double tmin, double tmax,
                  std::vector<TriangleCrossing>& out, BvhStats& stats) {
    bvh4::allCrossings<Avx2Lanes>(v, ray, tmin, tmax, out, stats);
}

}  // namespace avx2
}  // namespace kerf::bvh4

#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif
