/// @file csg/profiles/prism.h
/// @brief A straight extrusion along y of an outline of lines and quadratic and cubic Béziers
/// (filled even-odd): POV-Ray's prism with linear, quadratic and cubic splines. Its spans are
/// found by crossing the ray's shadow in the (x, z) plane with every segment (a line in
/// closed form, a Bézier by bisection on its monotone pieces) and the slab y0 ≤ y ≤ y1,
/// where the implicit extrusion (csg/profiles/profile.h) needs interval root isolation along the
/// whole ray. Internal to csg/ (makeExtrude).
#pragma once

#include "csg/profiles/profile_path.h"
#include "csg/tree/node.h"

namespace kerf {

/// The prism of `shape` (closed loops of lines and Béziers in (x, z), no arcs) between y0 and
/// y1 (y0 < y1). `implicitForm` is the same solid as an implicit (makeImplicit): the prism
/// takes its implicit form, bounds, kind and parameters from it, so everything but ray
/// tracing (slices, pruning, `kerf check`) sees that implicit.
NodePtr makePrism(const PathShape& shape, double y0, double y1, NodePtr implicitForm);

}  // namespace kerf
