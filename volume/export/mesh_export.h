/// @file volume/export/mesh_export.h
/// @brief `kerf mesh`'s pipeline, the front door: the solid (the union of a scene's bounded
/// objects) → interval-classified lattice blocks, sampled only near the surface
/// (volume/export/mesh_field.h) → OpenVDB's volume-to-mesh (volume/export/vdb_mesh.h) → vertices
/// placed on the true surface (volume/export/mesh_placement.h) → optionally its error
/// (volume/export/mesh_measure.h).
#pragma once

#include "csg/tree/node.h"
#include "volume/export/mesh_measure.h"
#include "volume/export/mesh_placement.h"

#include <array>
#include <vector>

namespace kerf {

struct MeshExportOptions {
    double voxel = 0.0;       ///< lattice spacing, model units; > 0
    double adaptivity = 0.0;  ///< OpenVDB's adaptivity in [0, 1]: 0 uniform, 1 fewest triangles
    bool measure = false;     ///< also measure the error and volumes (stats)
};

/// What `kerf mesh` writes: its own type, not mesh/triangle_mesh.h's imported TriangleMesh (no
/// normals, UVs or source file; closed by construction).
struct WatertightMesh {
    std::vector<Vec3> vertices;
    /// Counter-clockwise seen from outside; every edge shared by exactly two triangles.
    std::vector<std::array<uint32_t, 3>> triangles;
};

struct MeshExportStats {
    size_t objects = 0;           ///< objects meshed
    size_t unboundedSkipped = 0;  ///< unbounded objects (half-spaces) left out
    std::array<int64_t, 3> lattice{0, 0, 0};
    uint64_t intervalEvaluations = 0;
    uint64_t boundaryBlocks = 0;  ///< 8³ blocks sampled
    uint64_t fullRegions = 0;
    uint64_t leaves = 0;  ///< OpenVDB leaves (boundary blocks and the ring round them)
    PlacementStats placement;
    uint64_t crowdedEdges = 0;  ///< edges of more than two faces left (mesh_unpinch.h)
    double secondsClassify = 0.0, secondsPolygonize = 0.0, secondsPlace = 0.0, secondsMeasure = 0.0;
    // With `measure`:
    SurfaceDistance distance;
    double meshVolume = 0.0;
    VolumeBounds modelVolume;
};

/// The mesh of the union of the bounded objects; `stats` is reset, then filled. Throws
/// MeshInputError for a bad voxel or adaptivity, a voxel too fine for the caps
/// (volume/export/mesh_field.h), or no bounded object.
WatertightMesh exportMesh(const std::vector<NodePtr>& objects, const MeshExportOptions& options,
                          MeshExportStats& stats);

}  // namespace kerf
