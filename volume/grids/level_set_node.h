/// @file volume/grids/level_set_node.h
/// @brief A level set (volume/grids/level_set_grid.h) as a solid: a leaf (NodeKind::Volume) in the
/// grid's index space under a transform to world space, so ray parameters, CSG, materials and
/// the user's transforms work as for any solid. Spans come from the walk's crossings; normals
/// are the interpolant's gradient.
#pragma once

#include "csg/tree/node.h"
#include "volume/grids/level_set_grid.h"

#include <memory>

namespace kerf {

/// The grid as a solid in world space: the index-space leaf under grid->info().worldFromIndex.
NodePtr levelSetSolid(std::shared_ptr<const LevelSetGrid> grid);
/// The index-space leaf alone (tests, and the benchmark, which traces in index space).
NodePtr levelSetLeaf(std::shared_ptr<const LevelSetGrid> grid);

}  // namespace kerf
