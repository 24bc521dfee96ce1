/// @file volume/grids/level_set_grid.h
/// @brief A narrow-band level set (a .vdb file's float grid, volume/grids/vdb_level_set.h) as the
/// samples of its trilinear interpolant, stored for ray walking: blocks of 8³ cells, each
/// block either a constant (an inactive tile or the background) or a brick of its 9³ corner
/// samples (the ninth layer copied from the neighbours, so every cell is inside one brick),
/// under a coarse level of 16³-block groups. Every block and group keeps its samples' minimum
/// and maximum, so a ray skips any stretch where the interpolant cannot change sign.
///
/// Everything here is in the grid's index space: sample (i, j, k) is voxel (i, j, k)'s value
/// and the interpolant between samples is trilinear. Outside the stored blocks the value is
/// the background, which must be positive (outside). Values are in the file's units (world
/// distances); inside is f ≤ 0 as for every solid.
#pragma once

#include "csg/interval/interval.h"
#include "csg/tape/scalar_field.h"
#include "csg/types.h"

#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace kerf {

/// What `kerf check` says about a grid: read from the file, not recomputed.
struct LevelSetInfo {
    std::string file;       ///< the path it was read from
    std::string gridName;   ///< the grid's name in the file ("" when it has none)
    Vec3 voxelSize{1.0};    ///< world size of a voxel along index x, y and z
    Affine worldFromIndex;  ///< the grid's transform (affine maps only)
    uint64_t activeVoxels = 0;
    double background = 0.0;  ///< the value outside the narrow band (positive)
};

/// One crossing of the interpolant's zero set along a ray (index space).
struct LevelSetCrossing {
    double t;
    bool entering;  ///< f goes from > 0 to ≤ 0 (a zero-width touch counts as entering then leaving)
    Vec3 gradient;  ///< ∇f of the interpolant there, index space (the outward normal's direction)
};

class LevelSetGrid final : public ScalarField {
public:
    static constexpr int kBlock = 8;   ///< cells per block side
    static constexpr int kGroup = 16;  ///< blocks per group side
    static constexpr int kTile = 4;    ///< blocks per tile side: a group has 4³ tiles
    static constexpr int kGroupVoxels = kBlock * kGroup;  ///< 128: one OpenVDB internal node
    /// At most this many groups in the grid's box (a 4-byte index each, 16 MB; a box of about
    /// 20,000 voxels a side): the coarse level is dense over the box, everything finer is
    /// stored only where the source says a group varies.
    static constexpr uint64_t kMaxGroups = uint64_t(1) << 22;
    /// Index coordinates of data are within ±kMaxIndex (2^31 − 512), so a group's margin and
    /// its ninth samples stay in the int range.
    static constexpr int64_t kMaxIndex = (int64_t(1) << 31) - 512;

    /// The samples by block, for the constructor: blocks (bx, by, bz) cover the integer points
    /// of [lo, lo + 8·blocks]; beyond them the value is `background` (> 0), which the samples on
    /// the faces of that box should be too (the loader pads by a block), so walks start and end
    /// outside.
    struct Source {
        std::array<int32_t, 3> lo{};      ///< the first sample, a multiple of kBlock
        std::array<int32_t, 3> blocks{};  ///< blocks along each axis (≥ 1)
        double background = 1.0;
        /// True with the value when every sample of block (bx, by, bz) (its 9³ corners) is
        /// the same; false when the block needs a brick.
        virtual bool isConstant(int bx, int by, int bz, float& value) const = 0;
        /// Fills the block's 9³ samples, x fastest.
        virtual void fillBrick(int bx, int by, int bz, float* samples) const = 0;
        /// Appends the groups (kGroup blocks a side, counted from lo) whose samples may not all
        /// be groupValue(g): every other group is stored as that constant, without asking
        /// about its blocks. Duplicates are allowed. By default every group of the box.
        virtual void listVaryingGroups(std::vector<std::array<int32_t, 3>>& out) const;
        /// The value of every sample of a group not listed (by default the background).
        virtual float groupValue(int gx, int gy, int gz) const;
        /// False when the group's own 128³ voxels are one constant, so only its blocks on the
        /// upper faces (whose ninth samples reach the next group) can vary.
        virtual bool groupHasDetail(int gx, int gy, int gz) const;
        virtual ~Source() = default;
    };

    LevelSetGrid(const Source& source, LevelSetInfo info);

    const LevelSetInfo& info() const { return mInfo; }
    /// The cells where f can be ≤ 0, in index space (empty when the grid has no inside).
    const Bounds3& insideBounds() const { return mInsideBounds; }
    /// Blocks that hold a brick, and the bytes this grid uses.
    uint64_t brickCount() const { return mBrickCount; }
    /// Blocks whose samples were asked of the source while building: the build's work, which
    /// follows the groups the source lists, not the box.
    uint64_t blocksExamined() const { return mBlocksExamined; }
    /// Groups that store their blocks.
    uint64_t storedGroups() const { return mBlockList.size() / (kGroup * kGroup * kGroup); }
    uint64_t memoryBytes() const;

    /// Appends to `out` (cleared first) the crossings of the interpolant's zero set along
    /// origin + t·dir with tmin < t ≤ tmax (index space), in order; only the first when
    /// `firstOnly`. Returns whether f(tmin) ≤ 0 (inside at the start). A double root (a ray
    /// that touches the surface from outside) gives an entering and a leaving crossing at the
    /// same t. Crossings alternate: entering, leaving, entering, …, starting from the state
    /// returned.
    bool walk(const Ray& ray, double tmin, double tmax, bool firstOnly,
              std::vector<LevelSetCrossing>& out) const;

    // ScalarField, in index space: the trilinear interpolant.
    double value(const Vec3& p) const override;
    long double valueExtended(const glm::tvec3<long double>& p) const override;
    double valueGradient(const Vec3& p, Vec3& gradient) const override;
    Interval range(const Interval& x, const Interval& y, const Interval& z) const override;
    /// The largest difference of neighbouring samples: a bound on every partial derivative.
    double lipschitz() const override { return mLipschitz; }

private:
    struct Block {
        float lo, hi;   ///< the minimum and maximum of its samples
        int32_t brick;  ///< index into mBricks (in units of a brick), or −1: constant lo
    };
    struct Group {
        float lo, hi;
        int32_t firstBlock;  ///< index of its 16³ blocks in mBlocks, or −1: constant lo
    };
    friend class LevelSetWalker;

    /// The 8 corner samples of cell (i, j, k) (grid-relative), x fastest; false outside.
    bool cellCorners(int i, int j, int k, float c[8]) const;
    const Block* blockAt(int bx, int by, int bz) const;
    /// The sample range over grid-relative cells [lo, hi] (inclusive, clamped to the grid).
    void sampleRange(const int lo[3], const int hi[3], float& mn, float& mx) const;
    /// The constructor's steps: block (bx, by, bz), constant or a brick stored in mBricks
    /// (`brick` is scratch), with mLipschitz and mInsideBounds widened to hold it; and a
    /// group's blocks stored, with the ranges of their tiles.
    Block buildBlock(const Source& source, int bx, int by, int bz, std::vector<float>& brick);
    void buildGroup(const Source& source, const std::array<int32_t, 3>& gc,
                    std::vector<Block>& blocks, std::vector<float>& brick);
    void storeGroupBlocks(const std::vector<Block>& blocks, Group& g);
    /// mInsideBounds widened by the samples [lo, hi] (block units from block b's corner).
    void widenInside(int bx, int by, int bz, const Vec3& lo, const Vec3& hi);
    /// The index in mGroupList of a constant group of value v (one entry per value).
    int32_t constantGroup(float v);
    const Group& groupAt(int gx, int gy, int gz) const {
        return mGroupList[mGroupIndex[(size_t(gz) * mGroups[1] + gy) * mGroups[0] + gx]];
    }

    LevelSetInfo mInfo;
    int32_t mLo[3];      ///< index of sample (0, 0, 0)
    int32_t mBlocks[3];  ///< blocks per axis
    int32_t mGroups[3];  ///< groups per axis
    float mBackground;
    /// Per group of the box, x fastest: its entry in mGroupList (groups that store blocks
    /// have one each; constant groups share one per value).
    std::vector<int32_t> mGroupIndex;
    std::vector<Group> mGroupList;
    std::unordered_map<uint32_t, int32_t> mConstantGroups;  ///< while building: value bits → group
    std::vector<Block> mBlockList;  ///< kGroup³ per group that has any non-constant block
    /// The min and max of each tile of 4³ blocks, (kGroup / kTile)³ per group in mBlockList
    /// (in the same order), so a walk crosses empty space inside a group 32 cells at a step.
    std::vector<std::pair<float, float>> mTiles;
    std::vector<float> mBricks;  ///< 9³ floats per brick
    Bounds3 mInsideBounds;
    uint64_t mBrickCount = 0;
    uint64_t mBlocksExamined = 0;
    double mLipschitz = 0.0;
};

}  // namespace kerf
