/// @file csg/tree/repeated_instances.h
/// @brief One solid placed twice in the same place is one solid: A ∪ A = A ∩ A = A, and
/// A − B − B = A − B. A Boolean keeps one of each repeated instance, so a solid doubled n
/// times in one place is tested once per ray, not 2^n times (issue 24).
#pragma once

#include "csg/tree/node.h"

#include <vector>

namespace kerf {

/// True when `a` and `b` are the same subtree under the same transforms and materials: the
/// same node, or the same chain of transform (equal maps, bit for bit) and material (equal
/// ids) nodes over one same node. Never true for merely equal-looking primitives.
bool sameInstance(const Node& a, const Node& b);

/// `children` without the repeats (by sameInstance) an operation `op` lets go: all but the
/// first of each for union and intersection, the repeats among the subtracted operands of a
/// difference (the first operand stays, even when also subtracted); xor keeps them all
/// (A xor A is empty). The order of what is kept is unchanged. Expected O(n) by hashing.
std::vector<NodePtr> withoutRepeatedInstances(BoolOp op, std::vector<NodePtr> children);

}  // namespace kerf
