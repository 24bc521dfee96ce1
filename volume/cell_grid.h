/// @file volume/cell_grid.h
/// @brief The finest cells of an object's octree, stored sparsely in an OpenVDB tree, and the
/// walk of a ray through them.
///
/// The grid covers a cube of n = 2^depth cells of side h from `origin`. Boundary cells (where
/// the surface may pass) are active voxels holding the index of the cell's pruned node; cells
/// classified empty or full are inactive (whole octree cells become OpenVDB tiles where they
/// align with its nodes). OpenVDB stays inside volume/vdb_cell_grid.cpp.
#pragma once

#include "csg/types.h"

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace kerf {

/// Integer cell coordinates, 0 ≤ c < n on each axis.
using CellCoord = std::array<int32_t, 3>;

/// Where the grid sits in space: cell c is the box origin + c·h .. origin + (c + 1)·h, always
/// computed by cellBox so that the classification and the walk see the same boxes.
struct GridFrame {
    Vec3 origin{0.0};
    double h = 1.0;
    int32_t n = 1;  ///< cells per axis (a power of two)

    Bounds3 cellBox(const CellCoord& c, int32_t size) const {
        Bounds3 b;
        for (int a = 0; a < 3; ++a) {
            b.lo[a] = origin[a] + double(c[a]) * h;
            b.hi[a] = origin[a] + double(c[a] + size) * h;
        }
        return b;
    }
};

/// One stretch of a ray inside the grid: [t0, t1] lies in one block of cells; `cell` is the
/// index stored in a boundary cell, or kNoCell where the block holds no boundary cell.
struct GridSegment {
    double t0, t1;
    int32_t cell;
};
constexpr int32_t kNoCell = -1;

/// Called for each segment in increasing t; returns false to stop the walk.
using SegmentVisitor = bool (*)(void* context, const GridSegment& segment);

class CellGrid {
public:
    CellGrid(const GridFrame& frame, const std::vector<std::pair<CellCoord, int32_t>>& boundary,
             const std::vector<std::pair<CellCoord, int32_t>>& fullBlocks);
    ~CellGrid();
    CellGrid(const CellGrid&) = delete;
    CellGrid& operator=(const CellGrid&) = delete;

    const GridFrame& frame() const { return mFrame; }

    /// Visits the segments of the ray over [tmin, tmax] (already clipped to the grid's cube)
    /// in order. Empty and full blocks are skipped a whole OpenVDB node (8 or 128 cells) or
    /// tile at a time. Each segment's ends are computed from its block's planes directly, so
    /// no error accumulates along the walk. Returns false if the walk gave up (a step limit
    /// that only rounding could reach): the caller then searches the rest itself.
    bool walk(const Ray& ray, double tmin, double tmax, SegmentVisitor visit, void* context,
              uint64_t& steps) const;

    /// Whether the cell holding point p is inside a block classified full.
    bool fullAt(const Vec3& p) const;

    /// Bytes of the OpenVDB tree.
    uint64_t memoryBytes() const;

private:
    struct Impl;
    GridFrame mFrame;
    std::unique_ptr<Impl> mImpl;
};

}  // namespace kerf
