/// @file volume/grids/vdb_grid_files.h
/// @brief Plain .vdb files written and read back without OpenVDB in the caller: grids given as
/// values at index coordinates, and float grids read for checking (names, class, transform,
/// active voxels, trilinear samples). For tests and tools that make or inspect files; the
/// renderer reads level sets and fog volumes through volume/grids/vdb_level_set.h and vdb_fog.h.
#pragma once

#include "csg/types.h"

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace kerf {

/// A grid to write: world = turnZ(index · voxel) + move.
struct VdbGridToWrite {
    enum class Kind : uint8_t { LevelSet, FogVolume, Unclassed, Vec3 };
    Kind kind = Kind::LevelSet;
    std::string name;
    double voxel = 1.0;
    double turnZ = 0.0;  ///< radians about z, after the scale
    Vec3 move{0.0};
    float background = 0.0f;
    /// Active values at index coordinates (a Vec3 grid stores (v, v, v)).
    std::vector<std::pair<std::array<int, 3>, float>> values;
    /// A level set's inactive voxels take the sign of the band next to them (OpenVDB's signed
    /// flood fill), so its inside is negative beyond the band too.
    bool fillSigns = false;
    /// Stored as 16-bit halves (OpenVDB's "is_saved_as_half_float").
    bool saveAsHalf = false;
};

/// How the trees are stored: OpenVDB's default is Blosc with active-mask compression.
struct VdbCompression {
    enum class Codec : uint8_t { Blosc, Zip, None };
    Codec codec = Codec::Blosc;
    bool activeMask = true;  ///< inactive values left out where the masks can restore them
};

/// Writes the grids to one .vdb file. Throws std::runtime_error when it cannot.
void writeVdbGrids(const std::string& path, const std::vector<VdbGridToWrite>& grids,
                   const VdbCompression& compression = {});

/// A float grid read from a .vdb file (shared, read-only).
class VdbFloatGrid {
public:
    std::string name;
    std::string gridClass;  ///< "level set", "fog volume" or "unknown"
    bool linear = false;    ///< a linear (scale, rotation, translation) transform
    Vec3 voxelSize{0.0};
    Vec3 origin{0.0};  ///< the world position of index (0, 0, 0)
    float background = 0.0f;

    float value(int i, int j, int k) const;
    bool active(int i, int j, int k) const;
    uint64_t activeVoxelCount() const;
    void forEachActive(const std::function<void(int i, int j, int k, float value)>& visit) const;
    /// The trilinear interpolant at a world point (OpenVDB's BoxSampler).
    double sampleWorld(const Vec3& p) const;

    struct Impl;
    std::shared_ptr<const Impl> impl;
};

/// Every float grid of the file, in the file's order. Throws std::runtime_error when it cannot
/// be read.
std::vector<VdbFloatGrid> readVdbFloatGrids(const std::string& path);

}  // namespace kerf
