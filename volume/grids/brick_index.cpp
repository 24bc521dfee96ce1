#include "volume/grids/brick_index.h"

#include <stdexcept>
#include <string>

namespace kerf {

BrickIndex::BrickIndex(glm::ivec3 size, BrickLayout layout) : mSize(size), mLayout(layout) {
    const int bn = layout.brickLog2, mn = layout.macroLog2;
    if (bn < 1 || bn > 5 || mn < 0 || mn > 5 || bn + mn > 10)
        throw std::invalid_argument("brick layout: brick side 2^" + std::to_string(bn) +
                                    " and macrobrick side 2^" + std::to_string(mn) +
                                    " bricks are outside 2^1..2^5 each, 2^10 voxels together");
    for (int a = 0; a < 3; ++a) {
        // A macrobrick number must fit 32 bits: at most 2³¹ voxels per axis is far beyond that
        // already, so the count of macrobricks is checked as a whole below.
        if (size[a] < 1)
            throw std::invalid_argument("bricked grid: size " + std::to_string(size[a]) +
                                        " along an axis (at least 1 voxel needed)");
        mBricks[a] = int((std::int64_t(size[a]) + (1 << bn) - 1) >> bn);
        mMacros[a] = int((std::int64_t(mBricks[a]) + (1 << mn) - 1) >> mn);
    }
    if (macroTotal() >= (std::size_t(1) << 32))
        throw std::invalid_argument("bricked grid: more than 2^32 macrobricks");

    // Within a macrobrick: brick (x, y, z) of its m³ starts at n³·(bx + m·by + m²·bz), voxel
    // (x, y, z) of a brick sits at x + n·y + n²·z. Across macrobricks: x-fastest numbering.
    const std::uint64_t n = std::uint64_t(1) << bn, m = std::uint64_t(1) << mn, n3 = n * n * n;
    const std::uint64_t voxelStride[3] = {1, n, n * n};
    const std::uint64_t brickStride[3] = {n3, n3 * m, n3 * m * m};
    const std::uint64_t macroStride[3] = {1, std::uint64_t(mMacros.x),
                                          std::uint64_t(mMacros.x) * std::uint64_t(mMacros.y)};
    for (int a = 0; a < 3; ++a) {
        mF[a].resize(std::size_t(size[a]));
        for (std::uint64_t v = 0; v < std::uint64_t(size[a]); ++v) {
            const std::uint64_t inBrick = v & (n - 1), brick = (v >> bn) & (m - 1),
                                macro = v >> (bn + mn);
            mF[a][v] =
                (macro * macroStride[a] << 32) + brick * brickStride[a] + inBrick * voxelStride[a];
        }
    }
}

}  // namespace kerf
