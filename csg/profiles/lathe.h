/// @file csg/profiles/lathe.h
/// @brief A full turn about the y axis of an outline of lines and quadratic and cubic Béziers
/// in the (r, y) plane (filled even-odd): POV-Ray's lathe with linear, quadratic and Bézier
/// splines. A line turns into a cone frustum, a cylinder or an annulus. A ray's spans come from
/// crossing the ray's image in the plane, the curve r = |ray at height y|, with every segment:
/// a quadratic per line, a polynomial of degree 4 or 6 per Bézier (its class changes isolated
/// in Bernstein form, csg/profiles/bernstein.h), where the implicit revolution
/// (csg/profiles/profile.h) needs interval root isolation along the whole ray. Internal to
/// csg/ (makeRevolve).
#pragma once

#include "csg/profiles/profile_path.h"
#include "csg/tree/node.h"

#include <array>
#include <vector>

namespace kerf {

/// One segment of the outline: a line p[0] → p[1] (degree 1) or a Bézier of degree 2 or 3 with
/// control points p[0 … degree], all at r ≥ 0.
struct LatheSegment {
    std::array<Vec2, 4> p{};
    int degree = 1;
};

/// The solid of one full turn of the closed loops made of `segments` (in any order; lines may
/// reach r < 0, which does not count) about the y axis. `implicitForm` is the same solid as an
/// implicit (makeImplicit): the lathe takes its implicit form, bounds, kind and parameters from it,
/// so everything but ray tracing sees that implicit.
NodePtr makeLathe(const std::vector<LatheSegment>& segments, NodePtr implicitForm);

}  // namespace kerf
