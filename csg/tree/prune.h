/// @file csg/tree/prune.h
/// @brief pruned(node, box): a simpler tree equal to the original inside a box, for the
/// octree, slicing and voxelizing (each cell traces or classifies its own short subtree).
///
/// "Equal inside the box" means: at every point of the box the result is inside exactly where
/// the original is (value() has the same sign, up to rounding where the value is within a few
/// ulps of 0, and only for pruned implicit tapes), and rays give the same spans within the box
/// (the same boundaries, up to the root finder's tolerance for simplified implicit tapes).
/// Outside the box the result may differ arbitrarily.
///
/// Empty and Full are explicit results rather than nodes: a region that is all outside or all
/// inside has no surface to trace, and a caller (an octree) handles it without any node.
#pragma once

#include "csg/tree/node.h"

namespace kerf {

enum class PruneState {
    Empty,    ///< no point of the box is inside (interval value > 0, or outside the bounds)
    Full,     ///< every point of the box is inside (interval value ≤ 0)
    Partial,  ///< the surface may cross the box: `node` says where
};

struct Pruned {
    PruneState state = PruneState::Partial;
    /// Partial: the simpler node (the original itself where nothing could be dropped);
    /// nullptr for Empty and Full.
    NodePtr node;
};

/// The node over the closed box (in the node's own space, that of its parent):
/// - a union child whose bounds miss the box or whose interval value is > 0 there is dropped;
///   one that is ≤ 0 there makes the union Full;
/// - an intersection child that is Full is dropped; an Empty one makes it Empty;
/// - a difference's cutters likewise (Empty dropped, Full makes it Empty); an Empty body
///   makes it Empty;
/// - xor drops Empty children; Full ones flip the parity and are kept;
/// - a transform maps the box into its child's space (the box of the mapped corners, rounded
///   outward); a material passes the result through;
/// - an implicit leaf gets its tape simplified by the min/max choices that interval
///   evaluation decides over the box (csg/tape/tape.h); other primitives stay as they are.
/// A Boolean left with one child becomes that child. Unchanged subtrees are shared.
Pruned pruned(const NodePtr& node, const Bounds3& box);

/// pruned(node, boxes[k]) for every k < count (at most kPrunedManyMax), with the same results.
/// For the octree's common case, materials and transforms over one implicit whose tape has no
/// min, max or abs to decide, the boxes are evaluated together (four at a time by
/// Tape::evalInterval4); anything else box by box.
constexpr int kPrunedManyMax = 8;
void prunedMany(const NodePtr& node, const Bounds3* boxes, int count, Pruned* out);

}  // namespace kerf
