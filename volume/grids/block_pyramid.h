/// @file volume/grids/block_pyramid.h
/// @brief The minima and maxima of a sparse voxel field over blocks of 8³ voxels and over
/// coarser blocks above them (level k: cells of 2ᵏ blocks a side, aligned to multiples of 2ᵏ
/// in absolute block coordinates), stored only where the field holds data: a hash map per
/// level, so memory follows the leaves and tiles present, never the bounding box (a fog of
/// two voxels 2²⁵ apart once sized a dense pyramid by the product of its extents). Cells no
/// leaf or tile reaches take the background. No OpenVDB here: volume/grids/vdb_fog.cpp feeds
/// it the grid's leaves and tiles.
#pragma once

#include "csg/interval/interval.h"
#include "csg/types.h"

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace kerf {

/// Block (or cell) coordinates: any int, negative included.
using BlockCoord = std::array<int, 3>;

class BlockPyramid {
public:
    /// `background`: the value of voxels no leaf or tile holds; `lo`…`hi`: the inclusive
    /// box of blocks that hold data (outside it a query sees exactly the background).
    /// `Layout::Sparse` keeps queries on the hash maps even where the dense layout would be
    /// chosen (for the test that both give the same ranges).
    enum class Layout { Auto, Sparse };
    BlockPyramid(float background, const BlockCoord& lo, const BlockCoord& hi,
                 Layout layout = Layout::Auto);

    /// The minimum and maximum of every voxel of one 8³ block (a leaf's values).
    void addBlock(const BlockCoord& block, float lo, float hi);
    /// A constant tile covering exactly the level-`level` cell `cell` (2^level blocks a side).
    void addTile(int level, const BlockCoord& cell, float value);
    /// Builds the coarser levels from what was added; call once, before range().
    void finish();

    /// An interval holding every voxel value of the blocks lo…hi (inclusive): the union of the
    /// cells, at the finest level where the box spans at most 4 cells a side, that cover it.
    Interval range(BlockCoord lo, BlockCoord hi) const;
    /// The range over the whole box of data.
    Interval whole() const { return range(mLo, mHi); }

    /// Levels built (1 for a single block) and cells stored over all levels, for tests and
    /// statistics: cells grow with the data, not the box.
    int levels() const { return int(mLevels.size()); }
    size_t cells() const;

private:
    struct Cell {
        float lo = 0.0f, hi = 0.0f;
        uint8_t children = 0;   ///< direct children present (coarse levels)
        bool complete = false;  ///< every voxel below is held by a leaf or a tile
        bool tile = false;      ///< a constant tile: nothing is stored below it
    };
    struct CoordHash {
        size_t operator()(const BlockCoord& c) const;
    };
    using Level = std::unordered_map<BlockCoord, Cell, CoordHash>;

    /// The range a query sees for one cell of `level`: its own, or an enclosing tile's, plus
    /// the background's share where it is not complete.
    void cellRange(int level, const BlockCoord& c, float& lo, float& hi) const;

    /// Where the box holds few cells more than the data (a fog filling its box, the common
    /// case), each level is also laid out densely with every cell's range resolved, so a query
    /// is array reads, as fast as the dense pyramid this replaced; the hash maps stay the
    /// truth. Memory stays proportional to the data: at most 64 dense cells per stored one.
    struct DenseLevel {
        BlockCoord origin{}, dims{};
        std::vector<float> lo, hi;
        size_t index(const BlockCoord& c) const {
            return (size_t(c[2] - origin[2]) * size_t(dims[1]) + size_t(c[1] - origin[1])) *
                       size_t(dims[0]) +
                   size_t(c[0] - origin[0]);
        }
    };
    void buildDense();

    float mBackground;
    float mEmptyLo, mEmptyHi;  ///< the range of a cell holding no data: [min(bg, 0), max(bg, 0)]
    BlockCoord mLo, mHi;
    Layout mLayout;
    std::vector<Level> mLevels;
    std::vector<DenseLevel> mDense;  ///< empty: queries use the hash maps
};

}  // namespace kerf
