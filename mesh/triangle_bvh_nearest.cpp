// The BVH's nearest-triangle query: a depth-first walk that enters the nearer child box first
// and skips every box farther than the best triangle so far.
#include "mesh/triangle_bvh.h"
#include "mesh/triangle_distance.h"

#include <cmath>

namespace kerf {

namespace {

/// A lower bound on the squared distance from p to a node's box. The float box already holds
/// the triangles (rounded outward); the result is shrunk by a few ulps so rounding in the
/// sum never makes it exceed the exact value.
double boxDistance2(const Vec3& p, const TriangleBvh::Node& n) {
    double s = 0.0;
    for (int a = 0; a < 3; ++a) {
        const double d = std::max({double(n.lo[a]) - p[a], p[a] - double(n.hi[a]), 0.0});
        s += d * d;
    }
    return s * (1.0 - 0x1p-50);
}

}  // namespace

bool TriangleBvh::nearestTriangle(const Vec3& p, double maxDistance, double& distance,
                                  uint32_t& triangle, BvhStats& stats) const {
    if (mNodes.empty()) return false;
    double best2 = maxDistance < kInf ? maxDistance * maxDistance : kInf;
    bool found = false;
    struct Entry {
        uint32_t node;
        double d2;
    };
    Entry stack[kMaxDepth + 4];
    int top = 0;
    stack[top++] = {0, boxDistance2(p, mNodes[0])};
    ++stats.nodesVisited;
    while (top > 0) {
        const Entry e = stack[--top];
        if (e.d2 > best2) continue;
        const Node& node = mNodes[e.node];
        if (node.count > 0) {
            stats.trianglesTested += node.count;
            for (uint32_t k = node.index; k < node.index + node.count; ++k) {
                const Tri& t = mTris[k];
                const Vec3 q = nearestPointOnTriangle(p, Vec3(t.p[0][0], t.p[0][1], t.p[0][2]),
                                                      Vec3(t.p[1][0], t.p[1][1], t.p[1][2]),
                                                      Vec3(t.p[2][0], t.p[2][1], t.p[2][2]));
                const double d2 = glm::dot(q - p, q - p);
                if (d2 < best2 || (!found && d2 <= best2)) {
                    best2 = d2;
                    triangle = mTriangleIndex[k];
                    found = true;
                }
            }
            continue;
        }
        const uint32_t a = e.node + 1, b = node.index;
        const double da = boxDistance2(p, mNodes[a]), db = boxDistance2(p, mNodes[b]);
        stats.nodesVisited += 2;
        // Push the farther first so the nearer is walked first.
        if (da <= db) {
            if (db <= best2) stack[top++] = {b, db};
            if (da <= best2) stack[top++] = {a, da};
        } else {
            if (da <= best2) stack[top++] = {a, da};
            if (db <= best2) stack[top++] = {b, db};
        }
    }
    if (found) distance = std::sqrt(best2);
    return found;
}

}  // namespace kerf
