/// @file volume/octree/cell_grid.h
/// @brief The cells of an object's octree, stored sparsely in an OpenVDB tree and refined
/// lazily, and the walk of a ray through them.
///
/// The grid covers a cube of n = 2^depth finest cells of side h from `origin`, in bricks of
/// 8³ cells (one OpenVDB leaf node's extent). The coarse levels are classified when the grid is
/// made: empty regions are the tree's background, full ones inactive tiles, and bricks the
/// surface may cross active tiles holding the brick's index. A brick's own cells are
/// classified the first time a ray reaches it (thread-safe, once), so the work and the memory
/// follow the surface that rays actually meet. OpenVDB stays inside
/// volume/octree/vdb_cell_grid.cpp.
#pragma once

#include "csg/tree/node.h"

#include <array>
#include <bitset>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace kerf {

/// Integer cell coordinates, 0 ≤ c < n on each axis.
using CellCoord = std::array<int32_t, 3>;

/// Finest cells per brick side: an OpenVDB leaf node's.
constexpr int32_t kBrickCells = 8;
constexpr int kBrickCellCount = kBrickCells * kBrickCells * kBrickCells;

/// Where the grid sits in space: cell c is the box origin + c·h .. origin + (c + size)·h, always
/// computed by cellBox so that the classification and the walk see the same boxes.
struct GridFrame {
    Vec3 origin{0.0};
    double h = 1.0;
    int32_t n = kBrickCells;  ///< cells per axis (a power of two, at least one brick)

    Bounds3 cellBox(const CellCoord& c, int32_t size) const {
        Bounds3 b;
        for (int a = 0; a < 3; ++a) {
            b.lo[a] = origin[a] + double(c[a]) * h;
            b.hi[a] = origin[a] + double(c[a] + size) * h;
        }
        return b;
    }
};

/// The classified cells of one brick: for each, the pruned tree where the surface may cross
/// it (nullptr where it cannot), and whether it is all inside.
struct BrickContent {
    /// 0 where no surface can be, else 1 + the index of the cell's tree in `nodes`.
    std::array<uint16_t, kBrickCellCount> cell{};
    std::bitset<kBrickCellCount> full;
    std::vector<NodePtr> nodes;  ///< the distinct trees of the brick's cells
    uint64_t classified = 0;
    uint64_t boundaryCells = 0;

    static int index(int x, int y, int z) { return (x * kBrickCells + y) * kBrickCells + z; }
    const Node* nodeAt(int i) const {
        return cell[size_t(i)] ? nodes[cell[size_t(i)] - 1u].get() : nullptr;
    }
};

/// Classifies the cells of the brick at `corner` whose tree (pruned to the brick) is `node`.
using BrickBuilder =
    std::function<void(const CellCoord& corner, const NodePtr& node, BrickContent& out)>;

/// One stretch of a ray inside the grid: [t0, t1] lies in one cell or one block of cells
/// without surface; `node` is the cell's pruned tree, or nullptr where no surface can be.
struct GridSegment {
    double t0, t1;
    const Node* node;
};

/// Called for each segment in increasing t; returns false to stop the walk.
using SegmentVisitor = bool (*)(void* context, const GridSegment& segment);

class CellGrid {
public:
    /// bricks: the corners of the bricks the surface may cross, with their pruned trees;
    /// fullBlocks: (corner, side) of coarse cells classified all inside.
    CellGrid(const GridFrame& frame, std::vector<std::pair<CellCoord, NodePtr>> bricks,
             const std::vector<std::pair<CellCoord, int32_t>>& fullBlocks, BrickBuilder builder);
    ~CellGrid();
    CellGrid(const CellGrid&) = delete;
    CellGrid& operator=(const CellGrid&) = delete;

    const GridFrame& frame() const { return mFrame; }

    /// Visits the segments of the ray over [tmin, tmax] (within the grid's cube) in order,
    /// classifying the bricks it reaches for the first time. Blocks without surface are
    /// skipped a whole OpenVDB tile (8³ or 128³ cells) at a time. Each segment's ends are
    /// computed from its block's planes directly, so no error accumulates along the walk.
    /// Returns false if the walk gave up (a step limit only rounding could reach): the caller
    /// then searches the rest itself.
    bool walk(const Ray& ray, double tmin, double tmax, SegmentVisitor visit, void* context,
              uint64_t& steps) const;

    /// Whether the cell holding point p is classified all inside.
    bool fullAt(const Vec3& p) const;

    struct Counts {
        uint64_t bricks = 0, bricksBuilt = 0, boundaryCells = 0, classified = 0, distinctNodes = 0,
                 memoryBytes = 0;
    };
    /// What has been built so far (bricks are built as rays reach them).
    Counts counts() const;

private:
    struct Impl;
    GridFrame mFrame;
    std::unique_ptr<Impl> mImpl;
};

}  // namespace kerf
