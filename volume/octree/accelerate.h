/// @file volume/octree/accelerate.h
/// @brief Which acceleration structure each object of a scene gets (`--accel`).
#pragma once

#include "volume/octree/octree.h"

#include <optional>
#include <string>
#include <vector>

namespace kerf {

enum class Accel {
    /// The default rule: an octree for every bounded object with an implicit leaf wide
    /// enough for cells to shorten its search (octreePays), a BVH over the objects.
    Auto,
    /// Objects tested one after the other; no object BVH, no octree (Booleans keep theirs).
    None,
    /// A BVH over the objects; no octree.
    Bvh,
    /// An octree for every object with finite bounds, a BVH over the objects.
    Octree,
};

/// "auto", "none", "bvh", "octree": the names the command line uses.
const char* accelName(Accel accel);
std::optional<Accel> parseAccel(const std::string& name);

struct AcceleratedObjects {
    std::vector<NodePtr> objects;  ///< the scene's objects, some under an octree
    bool objectBvh = true;         ///< whether SceneGeometry puts a BVH over them
};

/// The objects as `accel` says, built in parallel in the calling TBB arena.
AcceleratedObjects accelerate(const std::vector<NodePtr>& objects, Accel accel,
                              const OctreeOptions& options);

}  // namespace kerf
