/// @file volume/export/mesh_field.h
/// @brief The sampled field that `kerf mesh` polygonizes: a lattice of voxel-corner points
/// over the solid's bounds, cut into blocks of 8³ points (one OpenVDB leaf each). Blocks are
/// classified coarse to fine by interval arithmetic on the solid's tape, so empty and full
/// space cost one interval evaluation per region; only blocks the surface may cross get point
/// values (a first-order distance f/|∇f|, in voxels). This file knows nothing of OpenVDB.
#pragma once

#include "csg/tape/tape.h"
#include "csg/tree/node.h"

#include <array>
#include <memory>
#include <stdexcept>
#include <vector>

namespace kerf {

/// Points per block side: one OpenVDB leaf (checked in volume/export/vdb_mesh.cpp).
constexpr int kMeshBlock = 8;
/// The most voxels kerf samples for one mesh (in boundary blocks): 2^26. Measured on the cup,
/// a run takes about 17 bytes per sampled voxel (samples, the ring of constant leaves, OpenVDB's
/// meshing, the mesh), so about 1.2 GB at the cap.
constexpr uint64_t kMeshMaxVoxels = uint64_t(1) << 26;
/// The most lattice points along one axis of the bounds (OpenVDB's coordinates are int32).
constexpr int64_t kMeshMaxAxisPoints = int64_t(1) << 24;
/// Stored values are clamped to ±this many voxels (the narrow band's half-width).
constexpr float kMeshBand = 3.0f;

/// A mistake in what was asked of the mesher (a voxel size that is not a positive number,
/// too fine for the memory cap, nothing bounded to mesh); what() says which and why.
struct MeshInputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// The lattice: point i (per axis) is at origin + i·voxel, computed exactly so everywhere.
struct MeshLattice {
    Vec3 origin{0.0};
    double voxel = 1.0;
    std::array<int64_t, 3> points{0, 0, 0};  ///< lattice points per axis
    Vec3 at(int64_t i, int64_t j, int64_t k) const {
        return {origin.x + double(i) * voxel, origin.y + double(j) * voxel,
                origin.z + double(k) * voxel};
    }
};

/// A block the surface may cross: its corner in blocks, its 8³ values in voxels (at
/// valueIndex(x, y, z), z fastest as in an OpenVDB leaf), negative inside, and the solid's tape
/// simplified over the block's points widened by kMeshTapeMargin voxels (for placing and measuring
/// vertices near it).
struct BoundaryBlock {
    std::array<int32_t, 3> block{0, 0, 0};
    std::vector<float> values;  ///< kMeshBlock³, index valueIndex(x, y, z)
    std::shared_ptr<const Tape> tape;
};
constexpr int kMeshTapeMargin = 3;
inline int valueIndex(int x, int y, int z) { return (x * kMeshBlock + y) * kMeshBlock + z; }

/// A cube of whole blocks inside the solid: corner and side in blocks.
struct FullRegion {
    std::array<int32_t, 3> block{0, 0, 0};
    int32_t size = 1;
};

struct SampledField {
    MeshLattice lattice;
    std::shared_ptr<const Tape> tape;     ///< the whole solid
    std::vector<BoundaryBlock> boundary;  ///< sorted by block
    std::vector<FullRegion> full;
    uint64_t intervalEvaluations = 0;
};

/// The lattice for the solid within `bounds` at `voxel`, with two voxels of margin. Throws
/// MeshInputError when voxel is not a finite positive number or the lattice would have more
/// than kMeshMaxAxisPoints points along an axis.
MeshLattice meshLattice(const Bounds3& bounds, double voxel);

/// Classifies the lattice's blocks for the solid whose implicit is `tape` and samples the
/// boundary blocks (TBB; the result does not depend on the thread count). Throws
/// MeshInputError when more than kMeshMaxVoxels voxels would be sampled.
SampledField sampleField(const MeshLattice& lattice, std::shared_ptr<const Tape> tape);

}  // namespace kerf
