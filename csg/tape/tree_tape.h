/// @file csg/tape/tree_tape.h
/// @brief A whole tree as one expression, libfive's view of a model: the primitives'
/// implicit forms (Primitive::implicitExpr) under the transforms' coordinate maps, combined
/// by min and max as the Boolean nodes combine values. Its value is the tree's value() up to
/// rounding (the same operations in the same order, bounds terms included), so
/// Tape::simplified over a box measures how much of the model matters there.
#pragma once

#include "csg/tape/tape.h"
#include "csg/tree/node.h"

namespace kerf {

/// The tree's implicit form over the coordinates x, y, z (of the tree's own space) in g.
ExprId treeExpr(const Node& node, ExprGraph& g, ExprId x, ExprId y, ExprId z);

/// treeExpr compiled.
std::shared_ptr<const Tape> treeTape(const Node& node);

}  // namespace kerf
