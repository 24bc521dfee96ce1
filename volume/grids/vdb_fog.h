/// @file volume/grids/vdb_fog.h
/// @brief A fog volume (an OpenVDB float grid of density) read as a ScalarField for
/// heterogeneous media (scene/medium.h): trilinear values, and a range over any box from the
/// maxima and minima of the grid's 8³ leaf blocks and of coarser blocks above them, so a
/// majorant is tight near the smoke and empty space is proved empty. Only vdb_fog.cpp
/// includes OpenVDB.
#pragma once

#include "csg/tape/scalar_field.h"
#include "csg/types.h"

#include <memory>
#include <stdexcept>
#include <string>

namespace kerf {

/// Why a fog volume could not be read: the message says what is wrong (without the path).
struct VdbFogError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct VdbFog {
    std::shared_ptr<const ScalarField> density;
    Bounds3 bounds;        ///< world box of the grid's active voxels, one voxel wider each side
    std::string gridName;  ///< the grid read
};

/// Reads the float fog grid `gridName` (empty: "density" if the file has one, else its only
/// float grid) from the .vdb at `path`. Throws VdbFogError for a missing or unreadable file,
/// a missing grid, a grid that does not hold floats, a level set, or negative values.
VdbFog loadVdbFog(const std::string& path, const std::string& gridName);

}  // namespace kerf
