/// @file volume/octree/octree.h
/// @brief An object's solid under an octree of interval-classified cells (issue 8 §3): cells
/// where the object is provably all outside or all inside are skipped by rays; each boundary
/// cell keeps the object's tree pruned to that cell (csg/tree/prune.h), so a ray searches only the
/// short stretches where the surface may be, with only the operands that matter there.
#pragma once

#include "csg/tree/node.h"

#include <cstdint>
#include <vector>

namespace kerf {

struct OctreeOptions {
    /// Finest level: 2^depth cells along the longest side of the object's bounds. 0 derives
    /// it from the pixel footprint (below), clamped to [kMinOctreeDepth, kMaxOctreeDepth].
    int depth = 0;
    /// Where the camera is and the world-space size of a pixel per unit of distance: the
    /// finest cell is kCellsPerFootprint pixels wide at the object's nearest distance (at
    /// least kNearestFraction of the object's size).
    Vec3 eye{0.0};
    double footprintPerDistance = 0.0;
};

constexpr int kMinOctreeDepth = 3;  ///< one brick of 8³ cells
constexpr int kMaxOctreeDepth = 10;
constexpr double kCellsPerFootprint = 8.0;
/// The distance the footprint is taken at is at least this fraction of the object's size.
constexpr double kNearestFraction = 0.25;

/// What building the octrees cost and holds, summed over objects (`--stats`).
struct OctreeStats {
    int objects = 0;               ///< objects given an octree
    uint64_t cellsClassified = 0;  ///< interval classifications (pruned() calls)
    uint64_t bricks = 0;           ///< bricks of 8³ finest cells the surface may cross
    uint64_t bricksBuilt = 0;      ///< of those, the ones rays reached (classified lazily)
    uint64_t boundaryCells = 0;    ///< finest cells the surface may cross, in built bricks
    uint64_t fullBlocks = 0;       ///< coarse octree cells classified all inside
    uint64_t distinctNodes = 0;    ///< distinct pruned trees kept by boundary cells
    uint64_t memoryBytes = 0;      ///< OpenVDB trees and cell tables
    /// Implicit tape instructions per boundary cell, summed: pruned against the full tree.
    uint64_t prunedTapeOps = 0, fullTapeOps = 0;
    int maxDepth = 0;
    double finestCell = 0.0;  ///< the smallest finest-cell side over objects

    OctreeStats& operator+=(const OctreeStats& o);
};

/// Whether `node` holds an implicit leaf.
bool hasImplicitLeaf(const NodePtr& node);

/// Whether `node` holds a mesh, a level set (its own DDA skips space better) or an implicit whose
/// tape calls an external field (a profile's outline, csg/tape/scalar_field.h). Neither gets an
/// octree: a field's interval enclosure costs a BVH query per cell and is loose, and one pixel of
/// models/profiles.kerf at tolerance 2e-3 lost its entering crossing under the octree (cause not
/// found; see docs/architecture.md).
bool hasExternalField(const NodePtr& node);

/// An implicit leaf narrower than this many finest cells gains nothing from the octree: its
/// own bound box already confines its search to about as few cells (10,000 small blobs in a
/// union, which the union's BVH finds; measured slower with the octree).
constexpr double kMinImplicitCells = 8.0;

/// The default rule (`--accel auto`): an octree for a bounded object with an implicit leaf
/// at least kMinImplicitCells finest cells wide, where interval root isolation over long
/// ranges is the cost and cells shorten them and prune the tree.
bool octreePays(const NodePtr& object, const OctreeOptions& options);

/// `object` (finite bounds) under an octree; the result answers spans, firstSurface and the
/// values exactly as the object does, within the root finder's tolerance. The coarse levels
/// are built now, in parallel in the calling TBB arena; each brick's cells when a ray first
/// reaches it.
NodePtr withOctree(const NodePtr& object, const OctreeOptions& options);

/// What the octrees among `objects` have built so far, summed.
OctreeStats octreeStats(const std::vector<NodePtr>& objects);

}  // namespace kerf
