/// @file volume/grids/brick_index.h
/// @brief The addressing of a two-level bricked 3-D array (Shirley et al., Fundamentals of
/// Computer Graphics §12.5): voxels in n³ bricks, bricks in m³ macrobricks, each brick stored
/// x-fastest and each macrobrick's bricks x-fastest. The address of voxel (x, y, z) is
/// Fx(x) + Fy(y) + Fz(z) from three lookup tables, so an access has no multiply or divide.
/// The sum is a key packing two numbers: the macrobrick (high 32 bits) and the offset inside
/// it (low 32 bits); the offsets of one macrobrick stay below 2³², so no carry crosses over.
/// This is the non-template part of volume/grids/brick_grid.h.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace kerf {

/// Brick and macrobrick sizes, as powers of two.
struct BrickLayout {
    int brickLog2 = 3;  ///< n = 2^brickLog2 voxels per brick side (8: a brick of floats is 2 KiB)
    int macroLog2 = 3;  ///< m = 2^macroLog2 bricks per macrobrick side (8: 64³ voxels)
};

class BrickIndex {
public:
    /// Throws std::invalid_argument for a size below 1 or a layout outside brickLog2 ∈ [1, 5],
    /// macroLog2 ∈ [0, 5], brickLog2 + macroLog2 ≤ 10 (a macrobrick holds at most 2³⁰ voxels).
    BrickIndex(glm::ivec3 size, BrickLayout layout);

    /// The key of voxel (x, y, z), 0 ≤ x < size().x etc. (not checked).
    std::uint64_t key(int x, int y, int z) const { return mF[0][x] + mF[1][y] + mF[2][z]; }
    /// The three table entries of one axis, for callers that sum them themselves.
    const std::uint64_t* table(int axis) const { return mF[axis].data(); }
    static std::uint32_t macroOf(std::uint64_t key) { return std::uint32_t(key >> 32); }
    static std::uint32_t offsetOf(std::uint64_t key) { return std::uint32_t(key); }

    glm::ivec3 size() const { return mSize; }          ///< voxels per axis, as asked
    glm::ivec3 brickCount() const { return mBricks; }  ///< bricks per axis (padded up)
    glm::ivec3 macroCount() const { return mMacros; }  ///< macrobricks per axis (padded up)
    BrickLayout layout() const { return mLayout; }
    int brickSide() const { return 1 << mLayout.brickLog2; }
    int macroSide() const { return 1 << (mLayout.brickLog2 + mLayout.macroLog2); }  ///< in voxels
    std::size_t macroVoxels() const {
        return std::size_t(1) << 3 * (mLayout.brickLog2 + mLayout.macroLog2);
    }
    std::size_t macroTotal() const { return std::size_t(mMacros.x) * mMacros.y * mMacros.z; }
    std::size_t brickTotal() const { return std::size_t(mBricks.x) * mBricks.y * mBricks.z; }
    /// The number of brick (bx, by, bz) in a dense x-fastest brick array (per-brick data).
    std::size_t brickNumber(int bx, int by, int bz) const {
        return std::size_t(bx) +
               std::size_t(mBricks.x) * (std::size_t(by) + std::size_t(mBricks.y) * bz);
    }
    std::size_t macroNumber(int mx, int my, int mz) const {
        return std::size_t(mx) +
               std::size_t(mMacros.x) * (std::size_t(my) + std::size_t(mMacros.y) * mz);
    }

private:
    glm::ivec3 mSize, mBricks, mMacros;
    BrickLayout mLayout;
    std::vector<std::uint64_t> mF[3];
};

}  // namespace kerf
