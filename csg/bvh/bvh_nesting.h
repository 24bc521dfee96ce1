/// @file csg/bvh/bvh_nesting.h
/// @brief The invariant of a flat BVH that near-first traversal relies on, for KERF_DCHECK
/// after a build (csg/bvh/bvh.cpp, mesh/bvh_build.cpp).
#pragma once

#include <cstddef>
#include <vector>

namespace kerf {

/// @brief Whether every inner node's box holds both of its children's boxes, so a ray that
/// misses a node misses everything below it. Node: float lo[3], hi[3]; count 0 marks an inner
/// node, whose first child follows it and whose second is at index secondChild(node).
template <class Node, class SecondChild>
bool childBoxesNest(const std::vector<Node>& nodes, SecondChild secondChild) {
    const auto holds = [](const Node& outer, const Node& inner) {
        for (int a = 0; a < 3; ++a) {
            if (!(outer.lo[a] <= inner.lo[a] && inner.hi[a] <= outer.hi[a])) return false;
        }
        return true;
    };
    for (size_t i = 0; i < nodes.size(); ++i) {
        if (nodes[i].count != 0) continue;
        const size_t second = size_t(secondChild(nodes[i]));
        if (i + 1 >= nodes.size() || second >= nodes.size()) return false;
        if (!holds(nodes[i], nodes[i + 1]) || !holds(nodes[i], nodes[second])) return false;
    }
    return true;
}

}  // namespace kerf
