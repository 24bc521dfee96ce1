/// @file volume/export/voxelize.h
/// @brief `kerf voxelize`: each solid object of a scene as an OpenVDB narrow-band level set
/// (signed distance, negative inside, world units), one grid per object, in one .vdb file.
///
/// How the distance is found, and why it is a distance. The implicit value f is not a distance
/// in general, and |f|/|∇f| or a root found along ∇f only bound it from above. So the surface
/// is first sampled only near itself: interval classification of the object's tape over a
/// lattice of 8³-voxel blocks, coarse to fine (empty and full regions stop, the rest split),
/// then crossings on the lattice edges of the boundary blocks, with vertices moved onto the
/// true surface and its creases (`kerf mesh`, volume/export/mesh_export.h). The voxel values are
/// then the exact distances to that closed mesh, computed in the narrow band only by OpenVDB's
/// mesh-to-volume (volume/export/vdb_voxelize_writer.cpp). Distance functions are 1-Lipschitz in
/// the set, so each value is within the two-sided Hausdorff distance between the mesh and the
/// surface of the true signed distance (measured: docs/BENCHMARKS.md, tests/volume). The sign
/// of every active voxel is the implicit's own (f ≤ 0 inside). No dense grid is allocated.
/// This header knows nothing of OpenVDB.
#pragma once

#include "csg/tree/node.h"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace kerf {

/// The default cap on the estimated active voxels of all grids: 2^24. Measured at the peak,
/// about 140 bytes per active voxel of one object (the sampled lattice near its surface, the
/// mesh and its triangle lists, the grid: 192 MB for a sphere of 1.23 M voxels) and 30 per
/// voxel of the grids kept for the file, so about 2.4 GB at the cap.
constexpr uint64_t kVoxelizeDefaultMaxVoxels = uint64_t(1) << 24;
/// OpenVDB refuses a scale map whose determinant is below 3·1e-15 (openvdb/math/Maps.h), so a
/// voxel must be at least ∛(3e-15) ≈ 1.44e-5 model units: a limit of the file format, not of
/// kerf (a model that small is voxelized scaled up).
constexpr double kVoxelizeMinVoxelCube = 3e-15;
/// Narrow-band half-widths accepted, in voxels. The band holds about 2·W voxels per voxel face
/// of the surface and each distance query scans the triangles within W voxels, so the time
/// grows as W³: at 16 it is about 150 times the default's.
constexpr double kVoxelizeMinBand = 1.0;
constexpr double kVoxelizeMaxBand = 16.0;

struct VoxelizeOptions {
    double voxel = 0.0;  ///< H: the voxel size in model units; > 0
    double band = 3.0;   ///< half-width of the narrow band in voxels (OpenVDB's default, 3)
    uint64_t maxVoxels = kVoxelizeDefaultMaxVoxels;  ///< refuse past this many estimated voxels
};

/// A mistake in what was asked (a bad voxel or band, too many voxels, nothing to voxelize);
/// what() says which and why.
struct VoxelizeInputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// One grid written.
struct VoxelizedGrid {
    size_t object = 0;  ///< index in the scene's objects
    std::string name;   ///< objectGridName(object)
    uint64_t activeVoxels = 0;
    uint64_t estimatedVoxels = 0;  ///< the estimate checked against maxVoxels
    double denseVoxels = 0.0;      ///< the dense alternative: the object's bounds / H³
    uint64_t cellsClassified = 0;  ///< interval evaluations (estimate and lattice)
    uint64_t boundaryBlocks = 0;   ///< 8³ blocks sampled near the surface
    uint64_t triangles = 0;        ///< of the surface mesh the distances are measured to
    uint64_t distanceQueries = 0;  ///< voxels whose distance was computed
    double seconds = 0.0;          ///< all of it: estimate, mesh, band
    double secondsMesh = 0.0;      ///< classifying, sampling and meshing the surface
    double secondsBand = 0.0;      ///< the band's distances and the flood fill
};

/// An object left out, and why (an open surface, an unbounded solid).
struct VoxelizeSkip {
    size_t object = 0;
    std::string reason;
};

struct VoxelizeStats {
    std::vector<VoxelizedGrid> grids;
    std::vector<VoxelizeSkip> skipped;
    double secondsWrite = 0.0;
};

/// The grid name of objects[index]: objects have no names in the language, so `object_0`,
/// `object_1`, … by their order in the model (skipped objects keep their numbers).
std::string objectGridName(size_t index);

/// Every solid object as a level set at options.voxel, written to `path` at once
/// (io/atomic_file.h). Throws VoxelizeInputError before writing anything for bad options, an
/// estimate past options.maxVoxels, or no solid object; FileWriteError if the file cannot be
/// written. Deterministic; parallel (TBB).
VoxelizeStats voxelizeToFile(const std::vector<NodePtr>& objects, const VoxelizeOptions& options,
                             const std::string& path);

}  // namespace kerf
