/// @file volume/octree_build.h
/// @brief Classifying an object's cells, coarse to fine: empty and full cells stop, boundary
/// cells are split down to the finest level, each child classifying its parent's pruned tree.
#pragma once

#include "csg/node.h"
#include "volume/cell_grid.h"

#include <vector>

namespace kerf {

struct OctreeCells {
    std::vector<std::pair<CellCoord, NodePtr>> boundary;  ///< finest cells and their trees
    std::vector<std::pair<CellCoord, int32_t>> full;      ///< (corner, side) of full cells
    uint64_t classified = 0;
};

/// Every cell of `frame`'s cube, classified by pruning `object` over it. Parallel (TBB) below
/// the first levels; the result is independent of the thread count (sorted).
OctreeCells classifyCells(const NodePtr& object, const GridFrame& frame);

}  // namespace kerf
