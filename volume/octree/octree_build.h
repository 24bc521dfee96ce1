/// @file volume/octree/octree_build.h
/// @brief Classifying an object's cells, coarse to fine: empty and full cells stop, cells the
/// surface may cross are split, each child classifying its parent's pruned tree. The coarse
/// levels down to bricks run when the grid is made (in parallel); a brick's cells when a ray
/// first reaches it.
#pragma once

#include "csg/tree/node.h"
#include "volume/octree/cell_grid.h"

#include <vector>

namespace kerf {

struct CoarseCells {
    std::vector<std::pair<CellCoord, NodePtr>> bricks;  ///< bricks the surface may cross
    std::vector<std::pair<CellCoord, int32_t>> full;    ///< (corner, side) of full cells
    uint64_t classified = 0;
};

/// The cells of `frame`'s cube down to bricks (kBrickCells), classified by pruning `object`
/// over them. Parallel (TBB); the result is sorted, so independent of the thread count.
CoarseCells classifyCoarse(const NodePtr& object, const GridFrame& frame);

/// The finest cells of the brick at `corner`, whose tree pruned to the brick is `node`.
void classifyBrick(const GridFrame& frame, const CellCoord& corner, const NodePtr& node,
                   BrickContent& out);

}  // namespace kerf
