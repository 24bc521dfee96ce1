// The triangle BVH's walks: near child first with a fixed stack, boxes tested conservatively
// (csg/types.h: a box is never missed through rounding), triangles with the watertight test.
#include "mesh/triangle_bvh.h"

#include "mesh/watertight_triangle.h"

#include <algorithm>

namespace kerf {

namespace {

constexpr int kStackSize = TriangleBvh::kMaxDepth + 4;

// Walks the tree calling leaf(first, count, tmax) for each leaf whose box the ray may meet
// within [tmin, tmax]; leaf returns the (possibly smaller) tmax to go on with, or a value below
// tmin to stop. Both children's boxes are tested together and the nearer entered first; the
// other waits on the stack with its entry, skipped if the range has shrunk past it. The entries
// are conservative (never later than exact), so no box that holds a hit is skipped.
template <class Leaf>
void walk(const std::vector<TriangleBvh::Node>& nodes, const Ray& ray, double tmin,
          double tmax, BvhStats& stats, Leaf&& leaf) {
    if (nodes.empty() || !(tmin < tmax)) return;
    const RayReciprocal rec(ray);
    struct Entry {
        uint32_t node;
        double tEnter;
    };
    Entry stack[kStackSize];
    int top = 0;
    ++stats.nodesVisited;
    {
        double t0 = tmin, t1 = tmax;
        if (!Bounds3::clipRayConservative(rec, nodes[0].lo, nodes[0].hi, t0, t1)) return;
    }
    uint32_t current = 0;
    for (;;) {
        const TriangleBvh::Node& node = nodes[current];
        bool descend = false;
        if (node.count > 0) {
            tmax = leaf(node.index, node.count, tmax);
            if (!(tmin < tmax)) return;
        } else {
            const uint32_t a = current + 1, b = node.index;
            double a0 = tmin, a1 = tmax, b0 = tmin, b1 = tmax;
            const bool hitA = Bounds3::clipRayConservative(rec, nodes[a].lo, nodes[a].hi, a0, a1);
            const bool hitB = Bounds3::clipRayConservative(rec, nodes[b].lo, nodes[b].hi, b0, b1);
            stats.nodesVisited += 2;
            if (hitA && hitB) {
                const bool aFirst = a0 <= b0;
                stack[top++] = aFirst ? Entry{b, b0} : Entry{a, a0};
                current = aFirst ? a : b;
                descend = true;
            } else if (hitA || hitB) {
                current = hitA ? a : b;
                descend = true;
            }
        }
        if (descend) continue;
        // Pop the next waiting node the shrunken range still reaches.
        for (;;) {
            if (top == 0) return;
            const Entry e = stack[--top];
            if (e.tEnter <= tmax) {
                current = e.node;
                break;
            }
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
