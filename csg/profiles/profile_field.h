/// @file csg/profiles/profile_field.h
/// @brief A PathShape (csg/profiles/profile_path.h) as a signed distance in the plane: the leaf of
/// polygons, `path { … }` and glyph outlines. The field reads x and y of its point and
/// ignores z; negative inside (even-odd fill).
///
/// Distance: lines and arcs in closed form; quadratic and cubic Béziers by subdivision with
/// a certified lower bound from the control polygon (the curve lies within the polygon's
/// largest offset from its chord), refined until the bound and the best curve point agree
/// to 2⁻³⁴ of the segment's size. Sign: crossings of the ray toward +x, each segment cut
/// into y-monotone pieces with the half-open endpoint rule, so joins count once.
#pragma once

#include "csg/profiles/profile_path.h"
#include "csg/tape/scalar_field.h"

#include <memory>

namespace kerf {

/// An axis-aligned box in the plane.
struct Bounds2 {
    Vec2 lo{0.0};
    Vec2 hi{0.0};
};

/// The box holding every segment of the shape (control polygons for Béziers, so it may be a
/// little larger than the outline). Empty shapes give lo = hi = 0.
Bounds2 pathBounds(const PathShape& shape);

/// The signed distance to the shape's outline in the (x, y) plane, z ignored. `range` is the
/// distance at the box's centre ± the box's half-diagonal (as mesh/mesh_shape does), with the
/// sign of the centre when no outline is in reach; `lipschitz` is 1. `rangeGradient` gives
/// ∂/∂z = 0 and, where one straight edge is provably the nearest feature of the whole box
/// (at interior points of it), that edge's outward normal — so root isolation proves roots on
/// polygon sides unique instead of bisecting; elsewhere [−1, 1].
std::shared_ptr<const ScalarField> pathField(PathShape shape);

}  // namespace kerf
