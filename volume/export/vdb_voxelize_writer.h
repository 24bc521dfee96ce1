/// @file volume/export/vdb_voxelize_writer.h
/// @brief The OpenVDB side of `kerf voxelize` (volume/export/voxelize.h): level-set grids from
/// closed meshes, and the .vdb bytes. Only volume/export/vdb_voxelize_writer.cpp includes OpenVDB.
#pragma once

#include "csg/tape/tape.h"
#include "volume/export/mesh_export.h"

#include <memory>
#include <string>

namespace kerf {

/// The grids of one .vdb file, in the order they are added.
class LevelSetFile {
public:
    LevelSetFile();
    ~LevelSetFile();
    LevelSetFile(const LevelSetFile&) = delete;
    LevelSetFile& operator=(const LevelSetFile&) = delete;

    struct Added {
        uint64_t activeVoxels = 0;
        uint64_t distanceQueries = 0;  ///< voxels tested: the band and the layer round it
    };

    /// Adds a GRID_LEVEL_SET FloatGrid `name` with transform "uniform scale `voxel`": the
    /// voxels nearer than band·voxel to the closed `mesh` are active and hold their exact
    /// distance to it (world units) with the sign of `tape` at the voxel (f ≤ 0: inside,
    /// negative); inactive values are ±band·voxel. An empty mesh gives an empty grid.
    Added add(const std::string& name, const WatertightMesh& mesh, double voxel, double band,
              const Tape& tape);

    /// The whole .vdb file.
    std::string bytes() const;

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

}  // namespace kerf
