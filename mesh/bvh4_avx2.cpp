// The wide tree's walks with the four boxes of a node tested at once on AVX2 lanes in double:
// the float corners widened exactly to double, then per lane the operations of
// Bounds3::clipRayConservative in the same order (no FMA: target("avx2") does not enable it
// and the module builds with -ffp-contract=off), and vmaxpd / vminpd with the operands placed
// so NaN and equal values resolve as the scalar "if (near > tmin) tmin = near" does. So every
// lane gives the scalar test's bits. Rays the margins of RayReciprocal do not cover (a range
// reaching below 0, a subnormal direction) take the scalar test. Only this file's functions
// carry target("avx2"); the rest of kerf builds for the baseline. The shared headers are read
// first without it, then the walk templates under it, so they inline the AVX2 box test.
#include "csg/types.h"
#include "mesh/triangle_bvh.h"
#include "mesh/watertight_triangle.h"

#include <immintrin.h>

#include <vector>

#pragma GCC push_options
#pragma GCC target("avx2")
#include "mesh/bvh4_queries.h"

#define KERF_AVX2_INLINE __attribute__((target("avx2"), always_inline)) inline

namespace kerf::bvh4 {
namespace {

struct Avx2Boxes {
    const RayReciprocal& rec;
    ScalarBoxes scalar;
    __m256d origin[3], invNear[3], invFar[3];
    int nearHi[3];  ///< 1 when the near plane of axis a is the box's hi (direction negative)

    KERF_AVX2_INLINE explicit Avx2Boxes(const RayReciprocal& r) : rec(r), scalar(r) {
        for (int a = 0; a < 3; ++a) {
            origin[a] = _mm256_set1_pd(r.origin[a]);
            invNear[a] = _mm256_set1_pd(r.invNear[a]);
            invFar[a] = _mm256_set1_pd(r.invFar[a]);
            nearHi[a] = r.negative[a];
        }
    }

    KERF_AVX2_INLINE unsigned test(const WideNode& n, double tmin, double tmax,
                                   double t[4]) const {
        if (!rec.finite || !(tmin >= 0.0)) return scalar.test(n, tmin, tmax, t);
        __m256d t0 = _mm256_set1_pd(tmin), t1 = _mm256_set1_pd(tmax);
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
        const __m256d ok = _mm256_and_pd(
            _mm256_cmp_pd(t0, t1, _CMP_LE_OQ),
            _mm256_cmp_pd(t0, _mm256_set1_pd(kInf), _CMP_LT_OQ));
        _mm256_storeu_pd(t, t0);
        return unsigned(_mm256_movemask_pd(ok));
    }
};

}  // namespace

namespace avx2 {

bool closestHit(const View& v, const Ray& ray, double tmin, double tmax,
                          TriangleHit& hit, BvhStats& stats) {
    return bvh4::closestHit<Avx2Boxes>(v, ray, tmin, tmax, hit, stats);
}

bool anyHit(const View& v, const Ray& ray, double tmin, double tmax,
                      BvhStats& stats) {
    return bvh4::anyHit<Avx2Boxes>(v, ray, tmin, tmax, stats);
}

void allCrossings(const View& v, const Ray& ray, double tmin, double tmax,
                            std::vector<TriangleCrossing>& out, BvhStats& stats) {
    bvh4::allCrossings<Avx2Boxes>(v, ray, tmin, tmax, out, stats);
}

}  // namespace avx2
}  // namespace kerf::bvh4

#pragma GCC pop_options
