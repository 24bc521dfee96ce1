/// @file volume/voxelize_distance.h
/// @brief The exact distance from a point to a triangle mesh, for points near it: triangles
/// listed per block of 8³ voxels (each in every block its box, grown by the reach, meets), so
/// a query scans one block's list, skipping triangles whose box is farther than the best
/// distance so far. OpenVDB's mesh-to-volume finds distances in the outer band from the
/// triangles its neighbours used, which overestimates some by up to half a voxel (measured on
/// a sphere); `kerf voxelize` recomputes every active voxel with this.
#pragma once

#include "csg/types.h"
#include "volume/mesh_export.h"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace kerf {

class MeshDistance {
public:
    /// `mesh` is kept by reference. Queries are exact up to `reach` (model units).
    MeshDistance(const TriangleMesh& mesh, double voxel, double reach);

    /// The distance from `p` to the nearest triangle when it is below `bound` (≤ reach), else
    /// `bound`. Thread-safe.
    double distance(const Vec3& p, double bound) const;

private:
    int64_t blockKey(int64_t i, int64_t j, int64_t k) const;
    int64_t blockOf(double x) const;

    const TriangleMesh& mMesh;
    double mBlock;  ///< a block's side, model units
    std::vector<Bounds3> mBoxes;  ///< per triangle
    std::unordered_map<int64_t, std::vector<uint32_t>> mBlocks;
};

/// The squared distance from p to the triangle abc (its nearest point, by the region of the
/// triangle's plane p projects into: a corner, an edge or the inside).
double squaredDistanceToTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace kerf
