/// @file mesh/bvh4_queries.h
/// @brief The three ray queries over the wide tree (closest hit, any hit, every crossing) as
/// templates on the lanes (box and triangle-pack tests), instantiated once for the scalar path
/// (mesh/triangle_bvh.cpp) and once for AVX2 (mesh/bvh4_avx2.cpp). The triangles go through the one
/// watertight test.
#pragma once

#include "mesh/bvh4.h"
#include "mesh/watertight_triangle.h"

namespace kerf::bvh4 {

/// Lane k of a tested pack within (tmin, tmax): the pack test's decision where it made one,
/// else the reference test itself. Either way intersectWatertight's answer, bit for bit.
KERF_BVH_INLINE bool laneHit(const TriPack& p, int k, const PackResult& r, const ShearedRay& sr,
                             double tmin, double tmax, TriangleIntersection& x) {
    if (r.exact >> k & 1u) {
        const double a[3] = {p.p[0][0][k], p.p[0][1][k], p.p[0][2][k]};
        const double b[3] = {p.p[1][0][k], p.p[1][1][k], p.p[1][2][k]};
        const double c[3] = {p.p[2][0][k], p.p[2][1][k], p.p[2][2][k]};
        return intersectWatertight(sr, a, b, c, tmin, tmax, x);
    }
    if (!(r.hit >> k & 1u)) return false;
    const double t = r.t[k];
    if (!(t > tmin && t < tmax)) return false;
    x.t = t;
    x.u = r.v[k] / r.det[k];
    x.v = r.w[k] / r.det[k];
    x.entering = r.det[k] > 0.0;
    return true;
}

/// Calls f(pack, lane) in order for each triangle of a leaf that the pack test did not rule
/// out, until f returns false. Returns how many of the leaf's triangles were reached: all of
/// them, or up to and including the lane where f stopped.
template <class Lanes, class F>
KERF_BVH_INLINE uint32_t forLeaf(const View& v, const Lanes& lanes, uint32_t first, uint32_t count,
                                 PackResult& r, F&& f) {
    for (uint32_t i = 0; i < count; i += 4) {
        const TriPack& p = v.packs[first + i / 4];
        const int n = count - i < 4 ? int(count - i) : 4;
        lanes.packTest(p, (1u << n) - 1u, r);
        for (unsigned open = r.hit | r.exact; open; open &= open - 1) {
            const int k = __builtin_ctz(open);
            if (!f(p, k)) return i + uint32_t(k) + 1;
        }
    }
    return count;
}

template <class Lanes>
KERF_BVH_INLINE bool closestHit(const View& v, const Ray& ray, double tmin, double tmax,
                                TriangleHit& hit, BvhStats& stats) {
    const RayReciprocal rec(ray);
    const ShearedRay sr(ray);
    const Lanes lanes(rec, sr);
    bool found = false;
    PackResult r;
    walk(
        v, lanes, rec, tmin, tmax,
        stats, [&](uint32_t first, uint32_t count, double tm) __attribute__((always_inline)) {
            stats.trianglesTested += count;
            forLeaf(
                v, lanes, first, count,
                r, [&](const TriPack& p, int k) __attribute__((always_inline)) {
                    TriangleIntersection x;
                    if (laneHit(p, k, r, sr, tmin, tm, x)) {
                        tm = x.t;
                        hit = {x.t, p.triangle[k], x.u, x.v};
                        found = true;
                    }
                    return true;
                });
            return tm;
        });
    return found;
}

template <class Lanes>
KERF_BVH_INLINE bool anyHit(const View& v, const Ray& ray, double tmin, double tmax,
                            BvhStats& stats) {
    const RayReciprocal rec(ray);
    const ShearedRay sr(ray);
    const Lanes lanes(rec, sr);
    bool found = false;
    PackResult r;
    walk(
        v, lanes, rec, tmin, tmax,
        stats, [&](uint32_t first, uint32_t count, double tm) __attribute__((always_inline)) {
            stats.trianglesTested += forLeaf(
                v, lanes, first, count,
                r, [&](const TriPack& p, int k) __attribute__((always_inline)) {
                    TriangleIntersection x;
                    found = laneHit(p, k, r, sr, tmin, tm, x);
                    return !found;
                });
            return found ? -kInf : tm;
        });
    return found;
}

/// Appends every crossing in (tmin, tmax) in walk order; the caller sorts and removes the
/// repeats of triangles referenced from several leaves.
template <class Lanes>
KERF_BVH_INLINE void allCrossings(const View& v, const Ray& ray, double tmin, double tmax,
                                  std::vector<TriangleCrossing>& out, BvhStats& stats) {
    const RayReciprocal rec(ray);
    const ShearedRay sr(ray);
    const Lanes lanes(rec, sr);
    PackResult r;
    walk(
        v, lanes, rec, tmin, tmax,
        stats, [&](uint32_t first, uint32_t count, double tm) __attribute__((always_inline)) {
            stats.trianglesTested += count;
            forLeaf(
                v, lanes, first, count,
                r, [&](const TriPack& p, int k) __attribute__((always_inline)) {
                    TriangleIntersection x;
                    if (laneHit(p, k, r, sr, tmin, tm, x))
                        out.push_back({x.t, p.triangle[k], x.entering});
                    return true;
                });
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
