/// @file csg/bvh/bvh_builder.h
/// @brief The one BVH builder: a binary tree over item boxes by binned SAH (Wald 2007) or
/// median splits, as a flat depth-first node array with double boxes plus the item order.
/// The object BVH (csg/bvh/bvh.h), the triangle BVH (mesh/triangle_bvh.h, collapsed 4-wide
/// afterwards) and the profile fields' segment tree (csg/profiles/profile_field.cpp) build
/// with it and convert the nodes to their own layouts. Each keeps its own split rule through
/// BvhBuildRule, so their trees are bit for bit the ones they had.
#pragma once

#include "csg/types.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace kerf {

/// An item to build over: its box, the point it is binned and sorted by, and its caller's id
/// (the builder reorders items; BinaryBvh::order gives the ids back in leaf order).
struct BvhBuildItem {
    Bounds3 box;
    Vec3 centroid;
    uint32_t id;
};

/// A node of the built tree. Nodes are in depth-first order: an inner node's first child
/// follows it directly.
struct BinaryBvhNode {
    Bounds3 box;     ///< the hull of its items' boxes (so it holds its children's boxes)
    uint32_t first;  ///< leaf: first position in BinaryBvh::order; inner: the second child
    uint32_t count;  ///< leaf: number of items (> 0); inner: 0
    int axis;        ///< inner: the split axis; leaf: 0
};

/// The built tree: nodes[0] is the root (no nodes when there were no items).
struct BinaryBvh {
    std::vector<BinaryBvhNode> nodes;
    std::vector<uint32_t> order;  ///< item ids in leaf order
};

/// How the builder splits. Each user's rule is spelled out here, not approximated: the
/// object BVH's search order decides ties in the stored reference images.
struct BvhBuildRule {
    /// Sah: binned SAH down to sahDepthLimit, median splits past it (and where no bin boundary
    /// separates anything); Median: always the median split.
    enum class Split { Sah, Median };
    /// The SAH comparison. AreaScaled (triangle BVH): nodeCost·A + Σ A_child·n_child against
    /// n·A, costs in item tests, so a flat box (A = 0) still compares. PerArea (object BVH):
    /// nodeCost + itemCost·Σ A_child·n_child / A against itemCost·n (no split of a flat node
    /// that may be a leaf).
    enum class SahCost { AreaScaled, PerArea };
    /// Which extent picks the median split's axis (the widest one).
    enum class MedianAxis { Centroids, NodeBox };

    Split split = Split::Sah;
    SahCost cost = SahCost::AreaScaled;
    int bins = 16;                ///< SAH bins along each axis (2 .. 64)
    int maxLeafSize = 4;          ///< a leaf holds at most this many, but see below
    uint32_t coincidentLeaf = 0;  ///< items with one centroid share a leaf, up to this many
    int sahDepthLimit = 48;       ///< deeper nodes split at the median (which halves)
    double nodeCost = 1.0;
    double itemCost = 1.0;  ///< PerArea only
    MedianAxis medianAxis = MedianAxis::Centroids;
    /// Equal centroids in a median split are ordered by id (false: as std::nth_element
    /// leaves them, the profile tree's historic order; still deterministic).
    bool medianTieById = true;
    /// Subtrees with more items than this are built as two parallel tasks through
    /// parallelInvoke (when set), which runs both and returns when both are done. The tree
    /// does not depend on it.
    uint32_t parallelAbove = 0;
    std::function<void(const std::function<void()>&, const std::function<void()>&)> parallelInvoke;
};

/// Builds over items (any number; boxes should be non-empty and finite). Deterministic: the
/// same items and rule give the same nodes and order, whatever the thread count.
BinaryBvh buildBinaryBvh(std::vector<BvhBuildItem> items, const BvhBuildRule& rule);

/// Surface-area heuristic half area of a box (0 for an empty box), for SAH costs.
double bvhHalfArea(const Bounds3& b);

}  // namespace kerf
