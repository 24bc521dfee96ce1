/// @file csg/tree/solids.h
/// @brief Factories for every kind of node. Arguments are validated by the caller (lang/):
/// these assume radii > 0, non-degenerate axes and non-empty boxes.
#pragma once

#include "csg/tape/tape.h"
#include "csg/tree/node.h"
#include "csg/tree/span.h"

#include <vector>

namespace kerf {

NodePtr makeSphere(const Vec3& center, double radius);
NodePtr makeBox(const Vec3& lo, const Vec3& hi);
/// Capped cylinder from `a` to `b`.
NodePtr makeCylinder(const Vec3& a, const Vec3& b, double radius);
// The primitives added as rows: makeKind(factory parameters) for each.
#define KERF_PRIMITIVE(Kind, keyword, rootFound, fields, factoryParameters) \
    NodePtr make##Kind factoryParameters;
#include "csg/tree/primitive_rows.def"
#undef KERF_PRIMITIVE
/// Capped cone (frustum) from `a` (radius r1) to `b` (radius r2); one radius may be 0.
NodePtr makeCone(const Vec3& a, const Vec3& b, double r1, double r2);
/// Torus around the y axis, centred at the origin: major radius R, minor radius r.
NodePtr makeTorus(double majorRadius, double minorRadius);
/// All p with dot(normal, p) ≤ offset. `normal` need not be unit length.
NodePtr makeHalfSpace(const Vec3& normal, double offset);
/// {p in bound : f(p) ≤ 0}, f given as a tape over x, y, z.
NodePtr makeImplicit(std::shared_ptr<const Tape> f, const Bounds3& bound);
/// The implicit leaf `original` (its kind must be Implicit) with f in place of its function:
/// same bound and primitive id, so where f equals the old function the two are one surface.
NodePtr withImplicitFunction(const Node& original, std::shared_ptr<const Tape> f);
/// An implicit {f ≤ 0} ∩ bound whose boundaries carry another primitive's id: the stand-in
/// through which csg/primitives/comparison_methods.h traces that primitive's implicit form. Its
/// root isolation runs on csg/tape/tape_ray_program.h (enclosures, point values and slopes of the
/// tape specialised to each ray) instead of Tape::evalIntervalAlongRay.
NodePtr makeImplicitStandIn(std::shared_ptr<const Tape> f, const Bounds3& bound, uint32_t id);

/// The child seen through worldFromLocal (maps the child's space into this node's space).
NodePtr makeTransform(NodePtr child, const Affine& worldFromLocal);
/// Gives boundaries of the child that have no material yet this material.
NodePtr makeMaterial(NodePtr child, int32_t material);
/// The child in motion over scene time s in [0, 1] (csg/tree/motion.h): turned by spin·s degrees
/// about the origin, then moved by velocity·s.
NodePtr makeMotion(NodePtr child, const Vec3& velocity, const Vec3& spin);
/// Union / intersection / xor of all children; difference is the first minus all the rest.
/// Wide nodes get a BVH over their children's bounds.
NodePtr makeBoolean(BoolOp op, std::vector<NodePtr> children);

}  // namespace kerf
