/// @file mesh/bvh4_queries.h
/// @brief The three ray queries over the wide tree (closest hit, any hit, every crossing) as
/// templates on the box test, instantiated once for the scalar path (mesh/triangle_bvh.cpp)
/// and once for AVX2 (mesh/bvh4_avx2.cpp). The triangles go through the one watertight test.
#pragma once

#include "mesh/bvh4.h"
#include "mesh/watertight_triangle.h"

namespace kerf::bvh4 {

template <class Boxes>
KERF_BVH_INLINE bool closestHit(const View& v, const Ray& ray, double tmin, double tmax,
                                TriangleHit& hit, BvhStats& stats) {
    const RayReciprocal rec(ray);
    const Boxes boxes(rec);
    const ShearedRay sr(ray);
    bool found = false;
    walk(v, boxes, rec, tmin, tmax, stats,
         [&](uint32_t first, uint32_t count, double tm) __attribute__((always_inline)) {
             stats.trianglesTested += count;
             for (uint32_t k = first; k < first + count; ++k) {
                 const TriangleBvh::Tri& tri = v.tris[k];
                 TriangleIntersection x;
                 if (intersectWatertight(sr, tri.p[0], tri.p[1], tri.p[2], tmin, tm, x)) {
                     tm = x.t;
                     hit = {x.t, v.triangleIndex[k], x.u, x.v};
                     found = true;
                 }
             }
             return tm;
         });
    return found;
}

template <class Boxes>
KERF_BVH_INLINE bool anyHit(const View& v, const Ray& ray, double tmin, double tmax,
                            BvhStats& stats) {
    const RayReciprocal rec(ray);
    const Boxes boxes(rec);
    const ShearedRay sr(ray);
    bool found = false;
    walk(v, boxes, rec, tmin, tmax, stats,
         [&](uint32_t first, uint32_t count, double tm) __attribute__((always_inline)) {
             for (uint32_t k = first; k < first + count; ++k) {
                 ++stats.trianglesTested;
                 const TriangleBvh::Tri& tri = v.tris[k];
                 TriangleIntersection x;
                 if (intersectWatertight(sr, tri.p[0], tri.p[1], tri.p[2], tmin, tm, x)) {
                     found = true;
                     return -kInf;
                 }
             }
             return tm;
         });
    return found;
}

/// Appends every crossing in (tmin, tmax) in walk order; the caller sorts and removes the
/// repeats of triangles referenced from several leaves.
template <class Boxes>
KERF_BVH_INLINE void allCrossings(const View& v, const Ray& ray, double tmin, double tmax,
                                  std::vector<TriangleCrossing>& out, BvhStats& stats) {
    const RayReciprocal rec(ray);
    const Boxes boxes(rec);
    const ShearedRay sr(ray);
    walk(v, boxes, rec, tmin, tmax, stats,
         [&](uint32_t first, uint32_t count, double tm) __attribute__((always_inline)) {
             stats.trianglesTested += count;
             for (uint32_t k = first; k < first + count; ++k) {
                 const TriangleBvh::Tri& tri = v.tris[k];
                 TriangleIntersection x;
                 if (intersectWatertight(sr, tri.p[0], tri.p[1], tri.p[2], tmin, tm, x))
                     out.push_back({x.t, v.triangleIndex[k], x.entering});
             }
             return tm;
         });
}

}  // namespace kerf::bvh4

namespace kerf::bvh4::avx2 {
/// Whether the AVX2 walks may run: the CPU has AVX2 and KERF_SIMD is not "scalar".
bool available();
/// The queries with the AVX2 box test (mesh/bvh4_avx2.cpp); call only when available().
bool closestHit(const View& v, const Ray& ray, double tmin, double tmax, TriangleHit& hit,
                BvhStats& stats);
bool anyHit(const View& v, const Ray& ray, double tmin, double tmax, BvhStats& stats);
void allCrossings(const View& v, const Ray& ray, double tmin, double tmax,
                  std::vector<TriangleCrossing>& out, BvhStats& stats);
}  // namespace kerf::bvh4::avx2
