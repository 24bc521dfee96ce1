/// @file csg/prism.h
/// @brief A straight extrusion of a polygon (loops of line segments, filled even-odd) along
/// y: POV-Ray's linear prism. Its spans are found in closed form, by crossing the ray's
/// shadow in the (x, z) plane with every edge and the slab y0 ≤ y ≤ y1, where the implicit
/// extrusion (csg/profile.h) would need root isolation. Internal to csg/ (makeExtrude).
#pragma once

#include "csg/node.h"
#include "csg/profile_path.h"

#include <vector>

namespace kerf {

/// The prism of `loops` (each a closed polygon of at least three points in (x, z)) between y0
/// and y1 (y0 < y1). `implicitForm` is the same solid as an implicit (makeImplicit): the prism
/// takes its implicit form, bounds, kind and parameters from it, so everything but ray
/// tracing (slices, pruning, `kerf check`) sees that implicit.
NodePtr makePrism(std::vector<std::vector<Vec2>> loops, double y0, double y1, NodePtr implicitForm);

}  // namespace kerf
