/// @file csg/primitives/surfaces.h
/// @brief Open surfaces: sheets that a ray meets but never enters (a disc, a triangle, the
/// side of a cylinder or cone without caps, the boundary of a solid, a surface clipped by a
/// solid), and the `interior` modifier that gives a back side its own material.
///
/// A surface's spans are zero-width (in == out) at each crossing, and its firstSurface
/// returns the nearest crossing with `entering` true and the normal turned to face the ray
/// (two-sided, as an open mesh). A crossing met from the back (against the geometric normal;
/// for `surface SOLID`, where the ray leaves the solid) carries Boundary::kNoMaterialBack
/// until a modifier gives it a material. A surface has no inside: its implicit form is +1
/// everywhere, and it is never a CSG operand (lang/ refuses it); the slicer skips it.
#pragma once

#include "csg/tree/node.h"

namespace kerf {

/// The ring inner ≤ |p − center| ≤ radius of the plane through center with normal `normal`
/// (any length > 0; its direction is the front). inner = 0: a full disc.
NodePtr makeDisc(const Vec3& center, const Vec3& normal, double radius, double inner = 0.0);
/// The triangle a, b, c; its front faces (b − a) × (c − a). Assumes a non-zero area.
NodePtr makeTriangle(const Vec3& a, const Vec3& b, const Vec3& c);
/// The side of the cone from `a` (radius r1) to `b` (radius r2) without its caps; r1 = r2
/// gives an open cylinder. The front faces out, away from the axis.
NodePtr makeOpenCone(const Vec3& a, const Vec3& b, double r1, double r2);
/// The boundary of a solid as a surface: every surface boundary of its spans is a crossing.
/// Its front is the solid's outside.
NodePtr makeSurfaceOf(NodePtr solid);
/// The crossings of `surface` that lie inside `solid` (where a span of the solid holds t),
/// as POV-Ray's clipped_by.
NodePtr makeClip(NodePtr surface, NodePtr solid);
/// Gives `material` to the child's crossings seen from the back that have no material yet:
/// a surface's back side, or the boundaries where a ray leaves a solid.
NodePtr makeInterior(NodePtr child, int32_t material);

/// Whether a tree is a surface: a surface kind, possibly under transforms, materials,
/// motions and interior modifiers.
bool isSurfaceTree(const Node& node);

}  // namespace kerf
