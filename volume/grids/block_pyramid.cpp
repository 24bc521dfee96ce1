/// @file volume/grids/block_pyramid.cpp
/// @brief The sparse min/max pyramid (see block_pyramid.h).
#include "volume/grids/block_pyramid.h"

#include <algorithm>

namespace kerf {
namespace {

/// floor(v / 2^k) for any int v (an arithmetic shift, written so it does not rely on one).
int shiftDown(int v, int k) {
    return v >= 0 ? v >> k : -int((uint32_t(-(int64_t(v) + 1)) >> k) + 1);
}

BlockCoord parentOf(const BlockCoord& c, int k) {
    return {shiftDown(c[0], k), shiftDown(c[1], k), shiftDown(c[2], k)};
}

}  // namespace

size_t BlockPyramid::CoordHash::operator()(const BlockCoord& c) const {
    uint64_t h = uint32_t(c[0]);
    h = h * 0x9E3779B97F4A7C15ull ^ uint32_t(c[1]);
    h = h * 0x9E3779B97F4A7C15ull ^ uint32_t(c[2]);
    return size_t(h ^ (h >> 29));
}

BlockPyramid::BlockPyramid(float background, const BlockCoord& lo, const BlockCoord& hi,
                           Layout layout)
    : mBackground(background),
      mEmptyLo(std::min(background, 0.0f)),
      mEmptyHi(std::max(background, 0.0f)),
      mLo(lo),
      mHi(hi),
      mLayout(layout) {
    // The top level is the first at which the whole box is one cell (31 at most: ints).
    int top = 0;
    while (top < 31 && parentOf(mLo, top) != parentOf(mHi, top)) ++top;
    mLevels.resize(size_t(top) + 1);
}

void BlockPyramid::addBlock(const BlockCoord& block, float lo, float hi) {
    for (int a = 0; a < 3; ++a)
        if (block[a] < mLo[a] || block[a] > mHi[a]) return;  // only inactive voxels out there
    Cell& c = mLevels[0][block];
    c.lo = lo, c.hi = hi, c.complete = true;
}

void BlockPyramid::addTile(int level, const BlockCoord& cell, float value) {
    // Tiles that miss the data's box change nothing a query sees (outside it: background).
    for (int a = 0; a < 3; ++a) {
        const int64_t first = int64_t(cell[a]) * (int64_t(1) << level),
                      last = first + (int64_t(1) << level) - 1;
        if (last < mLo[a] || first > mHi[a]) return;
    }
    // Cells are aligned, so a tile coarser than the top level that meets the box holds the
    // whole top cell.
    const int at = std::min(level, levels() - 1);
    const BlockCoord c = level > at ? parentOf(mLo, at) : cell;
    Cell& t = mLevels[size_t(at)][c];
    t.lo = value, t.hi = value, t.complete = true, t.tile = true;
}

void BlockPyramid::finish() {
    for (size_t k = 0; k + 1 < mLevels.size(); ++k) {
        Level& up = mLevels[k + 1];
        for (const auto& [coord, cell] : mLevels[k]) {
            auto [it, fresh] = up.try_emplace(parentOf(coord, 1));
            Cell& p = it->second;
            if (p.tile) continue;  // tiles and leaves never overlap; keep the tile as it is
            if (fresh) p.lo = cell.lo, p.hi = cell.hi, p.complete = true;
            p.lo = std::min(p.lo, cell.lo);
            p.hi = std::max(p.hi, cell.hi);
            p.complete = p.complete && cell.complete;
            ++p.children;
        }
        for (auto& [coord, cell] : up)
            if (!cell.tile && cell.children < 8) cell.complete = false;
    }
    double blocks = 1.0;  // the box's cell count at level 0, in double: it can pass 2^64
    for (int a = 0; a < 3; ++a) blocks *= double(mHi[a]) - double(mLo[a]) + 1.0;
    if (mLayout == Layout::Auto && blocks <= 64.0 * double(cells()) + 32768.0) buildDense();
}

void BlockPyramid::buildDense() {
    mDense.resize(mLevels.size());
    for (int k = 0; k < levels(); ++k) {
        DenseLevel& d = mDense[size_t(k)];
        d.origin = parentOf(mLo, k);
        const BlockCoord end = parentOf(mHi, k);
        for (int a = 0; a < 3; ++a) d.dims[a] = end[a] - d.origin[a] + 1;
        const size_t n = size_t(d.dims[0]) * size_t(d.dims[1]) * size_t(d.dims[2]);
        d.lo.assign(n, float(kInf));
        d.hi.assign(n, float(-kInf));
        for (int z = d.origin[2]; z <= end[2]; ++z)
            for (int y = d.origin[1]; y <= end[1]; ++y)
                for (int x = d.origin[0]; x <= end[0]; ++x) {
                    const size_t i = d.index({x, y, z});
                    cellRange(k, {x, y, z}, d.lo[i], d.hi[i]);
                }
    }
}

void BlockPyramid::cellRange(int level, const BlockCoord& c, float& lo, float& hi) const {
    const auto own = mLevels[size_t(level)].find(c);
    if (own != mLevels[size_t(level)].end()) {
        lo = std::min(lo, own->second.lo), hi = std::max(hi, own->second.hi);
        if (!own->second.complete) lo = std::min(lo, mEmptyLo), hi = std::max(hi, mEmptyHi);
        return;
    }
    // Absent: inside a coarser tile, or holding no data at all.
    for (int k = level + 1; k < levels(); ++k) {
        const auto up = mLevels[size_t(k)].find(parentOf(c, k - level));
        if (up == mLevels[size_t(k)].end()) continue;
        if (up->second.tile) {
            lo = std::min(lo, up->second.lo), hi = std::max(hi, up->second.hi);
            return;
        }
        break;  // a non-tile ancestor exists, so this cell's absence means no data
    }
    lo = std::min(lo, mEmptyLo), hi = std::max(hi, mEmptyHi);
}

Interval BlockPyramid::range(BlockCoord lo, BlockCoord hi) const {
    float rlo = float(kInf), rhi = float(-kInf);
    for (int a = 0; a < 3; ++a) {
        if (lo[a] < mLo[a] || hi[a] > mHi[a]) rlo = rhi = mBackground;  // reaches outside
        lo[a] = std::max(lo[a], mLo[a]);
        hi[a] = std::min(hi[a], mHi[a]);
        if (lo[a] > hi[a]) return Interval(mBackground, mBackground);
    }
    int level = 0;
    auto span = [&](int a) { return int64_t(shiftDown(hi[a], level)) - shiftDown(lo[a], level); };
    while (level + 1 < levels() && (span(0) > 3 || span(1) > 3 || span(2) > 3)) ++level;
    const BlockCoord c0 = parentOf(lo, level), c1 = parentOf(hi, level);
    if (!mDense.empty()) {
        const DenseLevel& d = mDense[size_t(level)];
        for (int k = c0[2]; k <= c1[2]; ++k)
            for (int j = c0[1]; j <= c1[1]; ++j)
                for (int i = c0[0]; i <= c1[0]; ++i) {
                    const size_t at = d.index({i, j, k});
                    rlo = std::min(rlo, d.lo[at]), rhi = std::max(rhi, d.hi[at]);
                }
        return Interval(rlo, rhi);
    }
    for (int k = c0[2]; k <= c1[2]; ++k)
        for (int j = c0[1]; j <= c1[1]; ++j)
            for (int i = c0[0]; i <= c1[0]; ++i) cellRange(level, {i, j, k}, rlo, rhi);
    return Interval(rlo, rhi);
}

size_t BlockPyramid::cells() const {
    size_t n = 0;
    for (const Level& l : mLevels) n += l.size();
    return n;
}

}  // namespace kerf
