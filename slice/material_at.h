/// @file slice/material_at.h
/// @brief Which material a point inside a solid has: the tree walked down to the primitive that
/// puts the point inside, the innermost material node on the way winning (as the renderer
/// colours a surface by its innermost material).
#pragma once

#include "csg/tree/node.h"

#include <cstdint>

namespace kerf {

/// The material index at `p` (model space) inside `node`, `inherited` where no material node
/// lies on the path. For a point outside, the walk still ends somewhere: the child nearest to
/// containing it (least value) is followed.
int32_t materialAt(const Node& node, const Vec3& p, int32_t inherited = 0);

}  // namespace kerf
