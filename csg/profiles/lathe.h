/// @file csg/profiles/lathe.h
/// @brief A full turn about the y axis of an outline of line segments in the (r, y) plane
/// (filled even-odd): POV-Ray's lathe with a linear spline. Each segment turns into a cone
/// frustum, a cylinder or an annulus; a ray's spans come from crossing the ray's image in the
/// plane, the curve r = |ray at height y|, with every segment (a quadratic per segment),
/// where the implicit revolution (csg/profiles/profile.h) needs interval root isolation along
/// the whole ray. Internal to csg/ (makeRevolve).
#pragma once

#include "csg/profiles/profile_path.h"
#include "csg/tree/node.h"

#include <vector>

namespace kerf {

/// The solid of one full turn of `loops` (closed polygons of (r, y) points; the part at r < 0
/// does not count) about the y axis. `implicitForm` is the same solid as an implicit
/// (makeImplicit): the lathe takes its implicit form, bounds, kind and parameters from it, so
/// everything but ray tracing sees that implicit.
NodePtr makeLathe(const std::vector<std::vector<Vec2>>& loops, NodePtr implicitForm);

}  // namespace kerf
