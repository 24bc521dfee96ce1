// The triangle BVH's ray queries: each runs the wide walk of mesh/bvh4_queries.h with the
// AVX2 box test when the CPU has it, else the scalar one (the same bits either way).
#include "mesh/triangle_bvh.h"

#include "mesh/bvh4_queries.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

namespace kerf {

bool bvh4::avx2::available() {
    static const bool use = [] {
        const char* v = std::getenv("KERF_SIMD");
        return __builtin_cpu_supports("avx2") && !(v && std::strcmp(v, "scalar") == 0);
    }();
    return use;
}

namespace {
bool useAvx2(bool simd) { return simd && bvh4::avx2::available(); }
}  // namespace

bool TriangleBvh::closestHit(const Ray& ray, double tmin, double tmax, TriangleHit& hit,
                             BvhStats& stats) const {
    if (mWide.empty()) return false;
    const bvh4::View v{mWide.data(), mNodes.data(), mPacks.data()};
    if (useAvx2(mSimd)) return bvh4::avx2::closestHit(v, ray, tmin, tmax, hit, stats);
    return bvh4::closestHit<bvh4::ScalarLanes>(v, ray, tmin, tmax, hit, stats);
}

bool TriangleBvh::anyHit(const Ray& ray, double tmin, double tmax, BvhStats& stats) const {
    if (mWide.empty()) return false;
    const bvh4::View v{mWide.data(), mNodes.data(), mPacks.data()};
    if (useAvx2(mSimd)) return bvh4::avx2::anyHit(v, ray, tmin, tmax, stats);
    return bvh4::anyHit<bvh4::ScalarLanes>(v, ray, tmin, tmax, stats);
}

void TriangleBvh::allCrossings(const Ray& ray, double tmin, double tmax,
                               std::vector<TriangleCrossing>& out, BvhStats& stats) const {
    out.clear();
    if (mWide.empty()) return;
    const bvh4::View v{mWide.data(), mNodes.data(), mPacks.data()};
    if (useAvx2(mSimd))
        bvh4::avx2::allCrossings(v, ray, tmin, tmax, out, stats);
    else
        bvh4::allCrossings<bvh4::ScalarLanes>(v, ray, tmin, tmax, out, stats);
    std::sort(out.begin(), out.end(), [](const TriangleCrossing& a, const TriangleCrossing& b) {
        return a.t < b.t || (a.t == b.t && a.triangle < b.triangle);
    });
    // A triangle referenced from several leaves is crossed once: its repeats are equal.
    out.erase(std::unique(out.begin(), out.end()), out.end());
}

int TriangleBvh::depth() const {
    if (mNodes.empty()) return 0;
    // Depth of each node in walk order: a first child follows its parent, so one pass with a
    // stack of (node, depth) suffices.
    int deepest = 0;
    std::vector<std::pair<uint32_t, int>> stack{{0u, 1}};
    while (!stack.empty()) {
        const auto [i, d] = stack.back();
        stack.pop_back();
        deepest = std::max(deepest, d);
        if (mNodes[i].count == 0) {
            stack.push_back({i + 1, d + 1});
            stack.push_back({mNodes[i].index, d + 1});
        }
    }
    return deepest;
}

}  // namespace kerf
