/// @file csg/bvh.h
/// @brief A bounding volume hierarchy over a set of boxes, stored as a flat node array and
/// walked with a fixed stack. Used over the children of wide Boolean nodes and over objects.
/// Unbounded boxes are kept out of the tree and always reported.
#pragma once

#include "csg/trace_context.h"
#include "csg/types.h"

#include <cstdint>
#include <vector>

namespace kerf {

class Bvh {
public:
    Bvh() = default;
    explicit Bvh(const std::vector<Bounds3>& items);

    /// Calls visit(index, tEnter) for every item whose box the ray meets within [tmin, tmax]
    /// (near boxes first, as far as the tree can tell). visit returns the tmax to continue
    /// with: smaller to narrow the search, below tmin to end it.
    template <class Visit>
    void traverse(const Ray& ray, double tmin, double tmax, TraceStats& stats, Visit&& visit) const;

    int itemCount() const { return mItemCount; }

private:
    struct Node {
        Bounds3 box;
        int32_t first;  ///< leaf: first index into mOrder; inner: index of the right child
        int32_t count;  ///< leaf: number of items (> 0); inner: 0 (left child follows)
        int32_t axis;
    };
    int build(const std::vector<Bounds3>& items, int begin, int end);

    std::vector<Node> mNodes;
    std::vector<int32_t> mOrder;      ///< item indices, leaves point into ranges of it
    std::vector<int32_t> mUnbounded;  ///< items with infinite boxes, always visited
    int mItemCount = 0;
};

template <class Visit>
void Bvh::traverse(const Ray& ray, double tmin, double tmax, TraceStats& stats,
                   Visit&& visit) const {
    for (int32_t i : mUnbounded) tmax = visit(i, tmin);
    if (mNodes.empty() || !(tmin <= tmax)) return;
    int32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    const bool dirNeg[3] = {ray.dir.x < 0, ray.dir.y < 0, ray.dir.z < 0};
    while (top > 0 && tmin <= tmax) {  // a visit may close the range to end the walk
        const Node& n = mNodes[stack[--top]];
        double t0 = tmin, t1 = tmax;
        ++stats.boundsTests;
        if (!n.box.clipRay(ray, t0, t1)) continue;
        if (n.count > 0) {
            for (int k = 0; k < n.count; ++k) tmax = visit(mOrder[n.first + k], t0);
            continue;
        }
        const int32_t self = static_cast<int32_t>(&n - mNodes.data());
        // Visit the near child first: push the far one below it.
        if (dirNeg[n.axis]) {
            stack[top++] = self + 1;
            stack[top++] = n.first;
        } else {
            stack[top++] = n.first;
            stack[top++] = self + 1;
        }
    }
}

}  // namespace kerf
