/// @file volume/grids/vdb_level_set.h
/// @brief Reading a level set from a .vdb file into a LevelSetGrid (volume/grids/level_set_grid.h).
/// The only file that includes OpenVDB for it is volume/grids/vdb_level_set.cpp.
#pragma once

#include "volume/grids/level_set_grid.h"

#include <memory>
#include <stdexcept>
#include <string>

namespace kerf {

/// A .vdb file that cannot be a solid: the message says what is wrong (without the path,
/// which the caller's diagnostic names).
class VdbError : public std::runtime_error {
public:
    explicit VdbError(const std::string& what, bool aboutGrid = false)
        : std::runtime_error(what), mAboutGrid(aboutGrid) {}
    /// The file was read, and the chosen (or named) grid is what is wrong.
    bool aboutGrid() const { return mAboutGrid; }

private:
    bool mAboutGrid;
};

/// The float level-set grid `gridName` of the file at `path`; with an empty name, the first
/// grid of class level set (or the file's only grid). Throws VdbError for: a missing or
/// unreadable file, a missing grid (listing the file's grids), a grid whose values are not
/// float, a fog volume (grid class fog volume), a grid with no value ≤ 0 (no inside), a
/// background ≤ 0 (the outside would be inside), or a transform that is not affine.
std::shared_ptr<const LevelSetGrid> loadLevelSet(const std::string& path,
                                                 const std::string& gridName = "");

}  // namespace kerf
