/// @file volume/export/voxelize_distance.h
/// @brief The exact distance from a point to a triangle mesh, for points near it: triangles
/// listed per block (8 voxels or twice the reach on a side, whichever is larger, so a
/// triangle is listed in at most 27 blocks; each in every block its box, grown by the reach,
/// meets), in
/// clusters of 8 near ones (Morton order of their centres) with a box each, so a query scans
/// one block's clusters, skipping those whose box is farther than the best distance so far;
/// a hint (the triangle nearest the previous voxel) gives a close first bound. OpenVDB's
/// mesh-to-volume finds distances in the outer band from the triangles its neighbours used, which
/// overestimates some by up to half a voxel (measured on a sphere); `kerf voxelize` recomputes
/// every active voxel with this.
#pragma once

#include "csg/types.h"
#include "volume/export/mesh_export.h"

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace kerf {

class MeshDistance {
public:
    /// `mesh` is kept by reference. Queries are exact up to `reach` (model units).
    MeshDistance(const WatertightMesh& mesh, double voxel, double reach);

    /// The distance from `p` to the nearest triangle when it is below `bound` (≤ reach), else
    /// `bound`. `hint` is a triangle to try first (or kNoHint); it becomes the nearest found.
    /// Thread-safe. The result does not depend on the hint.
    double distance(const Vec3& p, double bound, uint32_t& hint) const;

    static constexpr uint32_t kNoHint = ~uint32_t(0);

private:
    using BlockKey = std::array<int64_t, 3>;
    struct KeyHash {
        size_t operator()(const BlockKey& k) const;
    };
    int64_t blockOf(double x) const;

    const WatertightMesh& mMesh;
    double mBlock;                ///< a block's side, model units
    std::vector<Bounds3> mBoxes;  ///< per triangle
    struct Block {
        std::vector<uint32_t> triangles;  ///< cluster c holds [8c, 8c + 8)
        std::vector<Bounds3> clusters;
    };
    std::unordered_map<BlockKey, Block, KeyHash> mBlocks;
};

/// The squared distance from p to the triangle abc (its nearest point, by the region of the
/// triangle's plane p projects into: a corner, an edge or the inside).
double squaredDistanceToTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace kerf
