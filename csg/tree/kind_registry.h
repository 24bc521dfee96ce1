/// @file csg/tree/kind_registry.h
/// @brief One row per kind of node: its name and the traits csg/ and volume/ decide by
/// (Booleans, pruning, the octree rule), so that no walker keeps its own list of kinds. The
/// language's side of a kind (keyword, properties, factory) is lang/solid_kinds.h.
#pragma once

#include "csg/tree/node_kind.h"

#include <cstddef>

namespace kerf {

/// What a kind of node is, as the code outside its class needs to know it.
struct KindTraits {
    NodeKind kind;
    const char* name;  ///< the language's keyword ("sphere", "open cone" for the side alone)
    bool leaf;         ///< a primitive: no children
    /// Its spans need root isolation (an implicit, a torus) rather than a closed form; a
    /// Boolean over one guides the search by its closed-form operand (csg/tree/boolean.cpp).
    bool rootFound;
    /// An implicit leaf whose cells the octree classifies (volume/octree/octree.cpp): a tree
    /// with one may pay for an octree.
    bool octreeLeaf;
    /// The leaf walks its own structure (a mesh's BVH, a level set's grid): the octree leaves
    /// a tree holding it alone.
    bool ownWalk;
    bool surface;     ///< makes an open sheet (csg/primitives/surfaces.h), not a solid
    bool csgOperand;  ///< may be an operand of a Boolean (the solids; surfaces are not)
};

/// The row of a kind.
const KindTraits& kindTraits(NodeKind kind);
/// Every row, in the order of NodeKind; `kindCount()` of them.
const KindTraits* allKindTraits();
size_t kindCount();

}  // namespace kerf
