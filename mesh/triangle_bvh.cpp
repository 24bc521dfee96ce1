// The triangle BVH's walks: near child first with a fixed stack, boxes tested conservatively
// (csg/types.h: a box is never missed through rounding), triangles with the watertight test.
#include "mesh/triangle_bvh.h"

#include "mesh/watertight_triangle.h"

#include <algorithm>

namespace kerf {

namespace {

constexpr int kStackSize = TriangleBvh::kMaxDepth + 4;

// Walks the tree calling leaf(first, count) for each leaf the ray's box test passes within
// [tmin, tmax]; leaf returns the (possibly smaller) tmax to go on with, or a value below tmin
// to stop.
template <class Leaf>
void walk(const std::vector<TriangleBvh::Node>& nodes, const Ray& ray, double tmin,
          double tmax, BvhStats& stats, Leaf&& leaf) {
    if (nodes.empty() || !(tmin < tmax)) return;
    const RayReciprocal rec(ray);
    uint32_t stack[kStackSize];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const TriangleBvh::Node& node = nodes[stack[--top]];
        ++stats.nodesVisited;
        double t0 = tmin, t1 = tmax;
        if (!Bounds3::clipRayConservative(rec, node.lo, node.hi, t0, t1)) continue;
        if (node.count > 0) {
            tmax = leaf(node.index, node.count, tmax);
            if (!(tmin < tmax)) return;
            continue;
        }
        const uint32_t first = uint32_t(&node - nodes.data()) + 1, second = node.index;
        // Push the far child first so the near one is taken next.
        if (rec.negative[node.axis]) {
            stack[top++] = first;
            stack[top++] = second;
        } else {
            stack[top++] = second;
            stack[top++] = first;
        }
    }
}

}  // namespace

bool TriangleBvh::closestHit(const Ray& ray, double tmin, double tmax, TriangleHit& hit,
                             BvhStats& stats) const {
    const ShearedRay sr(ray);
    bool found = false;
    walk(mNodes, ray, tmin, tmax, stats, [&](uint32_t first, uint32_t count, double tm) {
        stats.trianglesTested += count;
        for (uint32_t k = first; k < first + count; ++k) {
            TriangleIntersection x;
            if (intersectWatertight(sr, mTris[k].p[0], mTris[k].p[1], mTris[k].p[2], tmin, tm,
                                    x)) {
                tm = x.t;
                hit = {x.t, mTriangleIndex[k], x.u, x.v};
                found = true;
            }
        }
        return tm;
    });
    return found;
}

bool TriangleBvh::anyHit(const Ray& ray, double tmin, double tmax, BvhStats& stats) const {
    const ShearedRay sr(ray);
    bool found = false;
    walk(mNodes, ray, tmin, tmax, stats, [&](uint32_t first, uint32_t count, double tm) {
        for (uint32_t k = first; k < first + count; ++k) {
            ++stats.trianglesTested;
            TriangleIntersection x;
            if (intersectWatertight(sr, mTris[k].p[0], mTris[k].p[1], mTris[k].p[2], tmin, tm,
                                    x)) {
                found = true;
                return -kInf;
            }
        }
        return tm;
    });
    return found;
}

void TriangleBvh::allCrossings(const Ray& ray, double tmin, double tmax,
                               std::vector<TriangleCrossing>& out, BvhStats& stats) const {
    out.clear();
    const ShearedRay sr(ray);
    walk(mNodes, ray, tmin, tmax, stats, [&](uint32_t first, uint32_t count, double tm) {
        stats.trianglesTested += count;
        for (uint32_t k = first; k < first + count; ++k) {
            TriangleIntersection x;
            if (intersectWatertight(sr, mTris[k].p[0], mTris[k].p[1], mTris[k].p[2], tmin, tm,
                                    x))
                out.push_back({x.t, mTriangleIndex[k], x.entering});
        }
        return tm;
    });
    std::sort(out.begin(), out.end(), [](const TriangleCrossing& a, const TriangleCrossing& b) {
        return a.t < b.t || (a.t == b.t && a.triangle < b.triangle);
    });
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
