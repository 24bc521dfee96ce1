/// @file csg/bvh/bvh.h
/// @brief A bounding volume hierarchy over a set of boxes, built by binned SAH with the shared
/// builder (csg/bvh/bvh_builder.h), stored as a flat
/// array of 32-byte nodes with float boxes (rounded outward, so they hold the double boxes),
/// and walked near child first with a fixed stack. Used over the children of wide Boolean
/// nodes and over objects. Unbounded boxes are kept out of the tree and always reported.
#pragma once

#include "csg/bvh/bvh_builder.h"
#include "csg/trace_context.h"
#include "csg/types.h"

#include <cstdint>
#include <vector>

namespace kerf {

class Bvh {
public:
    /// How the build splits a node: by binned SAH, or at the median of the centroids along
    /// their longest axis (two items per leaf), the tree kerf used before SAH. The scene's
    /// objects keep the median tree: the order objects are searched in narrows the range each
    /// later one is searched over, and root-isolated surfaces (torus, implicit) may land on a
    /// different root within the tolerance when that range changes; the stored reference
    /// images pin today's order.
    enum class Split { Sah, Median };

    Bvh() = default;
    explicit Bvh(const std::vector<Bounds3>& items, Split split = Split::Sah);

    /// Calls visit(index, tEnter) for every item whose box the ray meets within [tmin, tmax]
    /// (near boxes first, as far as the tree can tell; tEnter is at most the exact entry).
    /// visit returns the tmax to continue with: smaller to narrow the search, below tmin to
    /// end it. Boxes are tested conservatively: an item may be reported that the ray just
    /// misses, never the other way round.
    template <class Visit>
    void traverse(const Ray& ray, double tmin, double tmax, TraceStats& stats,
                  Visit&& visit) const {
        traverse(RayReciprocal(ray), tmin, tmax, stats, visit);
    }
    /// The same with the ray's reciprocal direction already computed.
    template <class Visit>
    void traverse(const RayReciprocal& rec, double tmin, double tmax, TraceStats& stats,
                  Visit&& visit) const;

    int itemCount() const { return mItemCount; }
    /// Tree depth (a single leaf has depth 1; 0 when no bounded item), for tests.
    int depth() const;

private:
    struct Node {
        float lo[3], hi[3];  ///< rounded outward from the double boxes: never smaller
        int32_t first;       ///< leaf: first index into mOrder; inner: index of the right child
        uint16_t count;      ///< leaf: number of items (> 0); inner: 0 (left child follows)
        uint16_t axis;       ///< inner: the split axis, for the near-first order
    };
    static_assert(sizeof(Node) == 32, "two nodes per cache line");
    /// The traversal stack holds at most one entry per level plus one; the build switches to
    /// median splits (which halve) before a tree could get deeper than this.
    static constexpr int kStackSize = 96;

    /// The builder's rule for a split kind (bin count, leaf sizes and costs of bvh.cpp).
    static BvhBuildRule buildRule(Split split);
    static void setBox(Node& node, const Bounds3& box);

    std::vector<Node> mNodes;
    std::vector<int32_t> mOrder;      ///< item indices, leaves point into ranges of it
    std::vector<int32_t> mUnbounded;  ///< items with infinite boxes, always visited
    int mItemCount = 0;
};

template <class Visit>
void Bvh::traverse(const RayReciprocal& rec, double tmin, double tmax, TraceStats& stats,
                   Visit&& visit) const {
    for (int32_t i : mUnbounded) tmax = visit(i, tmin);
    if (mNodes.empty() || !(tmin <= tmax)) return;
    int32_t stack[kStackSize];
    int top = 0;
    stack[top++] = 0;
    while (top > 0 && tmin <= tmax) {  // a visit may close the range to end the walk
        const int32_t self = stack[--top];
        const Node& n = mNodes[self];
        double t0 = tmin, t1 = tmax;
        ++stats.boundsTests;
        if (!Bounds3::clipRayConservative(rec, n.lo, n.hi, t0, t1)) continue;
        if (n.count > 0) {
            for (int k = 0; k < n.count; ++k) tmax = visit(mOrder[n.first + k], t0);
            continue;
        }
        // Visit the near child first: push the far one below it.
        if (rec.negative[n.axis]) {
            stack[top++] = self + 1;
            stack[top++] = n.first;
        } else {
            stack[top++] = n.first;
            stack[top++] = self + 1;
        }
    }
}

}  // namespace kerf
