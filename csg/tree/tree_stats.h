/// @file csg/tree/tree_stats.h
/// @brief Counts over solid trees that share subtrees (an instance is the same subtree under
/// another transform): one walk over the DAG, each node visited once and memoised on its
/// identity, so a subtree used twice at each of 60 levels costs 60 visits, not 2^60.
#pragma once

#include "csg/tree/node.h"

#include <cstdint>
#include <vector>

namespace kerf {

struct TreeStats {
    int64_t nodes = 0;       ///< distinct nodes
    int64_t primitives = 0;  ///< distinct primitive leaves (a shared leaf counts once)
    /// Primitive leaves counted once per use, as a ray sees them: the tree written out.
    /// Saturates at INT64_MAX (`instancesSaturated`), which 63 doublings reach.
    int64_t instances = 0;
    bool instancesSaturated = false;
    int depth = 0;  ///< the height of the highest tree; a leaf is 1
};

/// The counts over all `roots` together (a subtree shared by two roots counts once in the
/// distinct counts, once per use in `instances`). Iterative: no depth overflows the stack.
TreeStats treeStats(const std::vector<NodePtr>& roots);
TreeStats treeStats(const Node& root);

}  // namespace kerf
