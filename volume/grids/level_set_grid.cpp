// The level set's storage and its implicit form: building the groups, blocks and bricks from
// a Source, and the trilinear interpolant's value, gradient and range over a box. The ray
// walk is in volume/grids/level_set_walk.cpp.
#include "volume/grids/level_set_grid.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <tuple>

namespace kerf {

namespace {

constexpr int kSide = LevelSetGrid::kBlock + 1;  // samples per brick side
constexpr int kBrickSize = kSide * kSide * kSide;

/// Trilinear interpolation of corners c (x fastest) at (u, v, w) in [0, 1]³.
template <typename T>
T trilinear(const float c[8], T u, T v, T w) {
    const T x00 = c[0] + u * (T(c[1]) - c[0]), x10 = c[2] + u * (T(c[3]) - c[2]);
    const T x01 = c[4] + u * (T(c[5]) - c[4]), x11 = c[6] + u * (T(c[7]) - c[6]);
    const T y0 = x00 + v * (x10 - x00), y1 = x01 + v * (x11 - x01);
    return y0 + w * (y1 - y0);
}

int floorToInt(double x, int lo, int hi) {
    if (!(x >= lo)) return lo;  // also NaN
    if (x >= hi) return hi;
    return static_cast<int>(std::floor(x));
}

/// The largest difference of neighbouring samples of a brick: it bounds the interpolant's
/// partial derivatives.
double neighbourDifference(const float* s) {
    double most = 0.0;
    for (int k = 0; k < kSide; ++k)
        for (int j = 0; j < kSide; ++j)
            for (int i = 0; i < kSide; ++i) {
                const float c = s[(k * kSide + j) * kSide + i];
                if (i + 1 < kSide)
                    most =
                        std::max(most, std::fabs(double(s[(k * kSide + j) * kSide + i + 1]) - c));
                if (j + 1 < kSide)
                    most =
                        std::max(most, std::fabs(double(s[(k * kSide + j + 1) * kSide + i]) - c));
                if (k + 1 < kSide)
                    most =
                        std::max(most, std::fabs(double(s[((k + 1) * kSide + j) * kSide + i]) - c));
            }
    return most;
}

/// The bounds of a brick's samples ≤ 0, in sample units from its corner.
Bounds3 insideSamples(const float* brick) {
    Bounds3 samples;
    for (int k = 0; k < kSide; ++k)
        for (int j = 0; j < kSide; ++j)
            for (int i = 0; i < kSide; ++i)
                if (brick[(k * kSide + j) * kSide + i] <= 0.f) samples.extend(Vec3(i, j, k));
    return samples;
}

}  // namespace

void LevelSetGrid::Source::listVaryingGroups(std::vector<std::array<int32_t, 3>>& out) const {
    const int32_t n[3] = {(blocks[0] + kGroup - 1) / kGroup, (blocks[1] + kGroup - 1) / kGroup,
                          (blocks[2] + kGroup - 1) / kGroup};
    for (int32_t z = 0; z < n[2]; ++z)
        for (int32_t y = 0; y < n[1]; ++y)
            for (int32_t x = 0; x < n[0]; ++x) out.push_back({x, y, z});
}

float LevelSetGrid::Source::groupValue(int, int, int) const { return float(background); }

bool LevelSetGrid::Source::groupHasDetail(int, int, int) const { return true; }

LevelSetGrid::LevelSetGrid(const Source& source, LevelSetInfo info) : mInfo(std::move(info)) {
    mBackground = static_cast<float>(source.background);
    for (int a = 0; a < 3; ++a) {
        mLo[a] = source.lo[a];
        mBlocks[a] = source.blocks[a];
        mGroups[a] = (mBlocks[a] + kGroup - 1) / kGroup;
    }
    mInsideBounds = Bounds3{};
    // Every group starts as the constant the source gives it; the listed ones are built.
    mGroupIndex.resize(size_t(mGroups[0]) * mGroups[1] * mGroups[2]);
    size_t gi = 0;
    for (int gz = 0; gz < mGroups[2]; ++gz)
        for (int gy = 0; gy < mGroups[1]; ++gy)
            for (int gx = 0; gx < mGroups[0]; ++gx, ++gi)
                mGroupIndex[gi] = constantGroup(source.groupValue(gx, gy, gz));
    std::vector<std::array<int32_t, 3>> varying;
    source.listVaryingGroups(varying);
    // In the box's order (z, y, x), each once, so the build is the same whatever the list's.
    std::sort(varying.begin(), varying.end(), [](const auto& a, const auto& b) {
        return std::tie(a[2], a[1], a[0]) < std::tie(b[2], b[1], b[0]);
    });
    varying.erase(std::unique(varying.begin(), varying.end()), varying.end());
    std::vector<Block> blocks(kGroup * kGroup * kGroup);
    std::vector<float> brick(kBrickSize);
    for (const auto& gc : varying) {
        if (gc[0] < 0 || gc[1] < 0 || gc[2] < 0 || gc[0] >= mGroups[0] || gc[1] >= mGroups[1] ||
            gc[2] >= mGroups[2])
            continue;
        buildGroup(source, gc, blocks, brick);
    }
    mConstantGroups.clear();
}

int32_t LevelSetGrid::constantGroup(float v) {
    uint32_t bits;
    std::memcpy(&bits, &v, sizeof bits);  // by bits: NaN and -0 are values of their own
    const auto [it, made] = mConstantGroups.try_emplace(bits, int32_t(mGroupList.size()));
    if (made) mGroupList.push_back(Group{v, v, -1});
    return it->second;
}

void LevelSetGrid::buildGroup(const Source& source, const std::array<int32_t, 3>& gc,
                              std::vector<Block>& blocks, std::vector<float>& brick) {
    Group g;
    g.lo = std::numeric_limits<float>::infinity();
    g.hi = -g.lo;
    const bool detail = source.groupHasDetail(gc[0], gc[1], gc[2]);
    const float own = source.groupValue(gc[0], gc[1], gc[2]);
    bool anyBrick = false;
    size_t bi = 0;
    for (int z = 0; z < kGroup; ++z)
        for (int y = 0; y < kGroup; ++y)
            for (int x = 0; x < kGroup; ++x, ++bi) {
                Block& b = blocks[bi];
                const bool upperFace = x == kGroup - 1 || y == kGroup - 1 || z == kGroup - 1;
                if (detail || upperFace) {
                    b = buildBlock(source, gc[0] * kGroup + x, gc[1] * kGroup + y,
                                   gc[2] * kGroup + z, brick);
                } else {  // inside a constant group: its samples are the group's own value
                    b = Block{own, own, -1};
                    if (own <= 0.f)
                        widenInside(gc[0] * kGroup + x, gc[1] * kGroup + y, gc[2] * kGroup + z,
                                    Vec3(0.0), Vec3(kBlock));
                }
                anyBrick = anyBrick || b.brick >= 0;
                g.lo = std::min(g.lo, b.lo);
                g.hi = std::max(g.hi, b.hi);
            }
    const size_t at = (size_t(gc[2]) * mGroups[1] + gc[1]) * mGroups[0] + gc[0];
    if (anyBrick || g.lo != g.hi) {  // a group of one constant stores no blocks
        storeGroupBlocks(blocks, g);
        mGroupIndex[at] = int32_t(mGroupList.size());
        mGroupList.push_back(g);
    } else {
        mGroupIndex[at] = constantGroup(g.lo);
    }
}

void LevelSetGrid::widenInside(int bx, int by, int bz, const Vec3& lo, const Vec3& hi) {
    // f ≤ 0 only in cells with a corner ≤ 0: within a cell of those samples.
    const Vec3 origin(double(mLo[0]) + double(bx) * kBlock, double(mLo[1]) + double(by) * kBlock,
                      double(mLo[2]) + double(bz) * kBlock);
    mInsideBounds.extend(Bounds3{origin + lo - Vec3(1.0), origin + hi + Vec3(1.0)});
}

LevelSetGrid::Block LevelSetGrid::buildBlock(const Source& source, int bx, int by, int bz,
                                             std::vector<float>& brick) {
    Block b;
    b.brick = -1;
    ++mBlocksExamined;
    float v = mBackground;
    if (bx >= mBlocks[0] || by >= mBlocks[1] || bz >= mBlocks[2] ||
        source.isConstant(bx, by, bz, v)) {
        b.lo = b.hi = v;
    } else {
        source.fillBrick(bx, by, bz, brick.data());
        const auto [mn, mx] = std::minmax_element(brick.begin(), brick.end());
        b.lo = *mn;
        b.hi = *mx;
        b.brick = static_cast<int32_t>(mBrickCount++);
        mBricks.insert(mBricks.end(), brick.begin(), brick.end());
        mLipschitz = std::max(mLipschitz, neighbourDifference(brick.data()));
    }
    if (b.lo <= 0.f) {
        const Bounds3 samples =
            b.brick < 0 ? Bounds3{Vec3(0.0), Vec3(kBlock)} : insideSamples(brick.data());
        widenInside(bx, by, bz, samples.lo, samples.hi);
    }
    return b;
}

void LevelSetGrid::storeGroupBlocks(const std::vector<Block>& blocks, Group& g) {
    g.firstBlock = static_cast<int32_t>(mBlockList.size());
    mBlockList.insert(mBlockList.end(), blocks.begin(), blocks.end());
    constexpr int n = kGroup / kTile;
    for (int tz = 0; tz < n; ++tz)
        for (int ty = 0; ty < n; ++ty)
            for (int tx = 0; tx < n; ++tx) {
                std::pair<float, float> t(g.hi, g.lo);
                for (int z = tz * kTile; z < (tz + 1) * kTile; ++z)
                    for (int y = ty * kTile; y < (ty + 1) * kTile; ++y)
                        for (int x = tx * kTile; x < (tx + 1) * kTile; ++x) {
                            const Block& b = blocks[(z * kGroup + y) * kGroup + x];
                            t.first = std::min(t.first, b.lo);
                            t.second = std::max(t.second, b.hi);
                        }
                mTiles.push_back(t);
            }
}

uint64_t LevelSetGrid::memoryBytes() const {
    return mGroupIndex.size() * sizeof(int32_t) + mGroupList.size() * sizeof(Group) +
           mBlockList.size() * sizeof(Block) + mTiles.size() * sizeof(mTiles[0]) +
           mBricks.size() * sizeof(float);
}

const LevelSetGrid::Block* LevelSetGrid::blockAt(int bx, int by, int bz) const {
    const Group& g = groupAt(bx / kGroup, by / kGroup, bz / kGroup);
    if (g.firstBlock < 0) return nullptr;
    return &mBlockList[g.firstBlock + ((bz % kGroup) * kGroup + by % kGroup) * kGroup +
                       bx % kGroup];
}

bool LevelSetGrid::cellCorners(int i, int j, int k, float c[8]) const {
    const int n[3] = {mGroups[0] * kGroup * kBlock, mGroups[1] * kGroup * kBlock,
                      mGroups[2] * kGroup * kBlock};
    if (i < 0 || j < 0 || k < 0 || i >= n[0] || j >= n[1] || k >= n[2]) return false;
    const int bx = i / kBlock, by = j / kBlock, bz = k / kBlock;
    const Block* b = blockAt(bx, by, bz);
    if (!b || b->brick < 0) {
        const float v = b ? b->lo : groupAt(bx / kGroup, by / kGroup, bz / kGroup).lo;
        std::fill(c, c + 8, v);
        return true;
    }
    const float* s = &mBricks[size_t(b->brick) * kBrickSize] +
                     ((k % kBlock) * kSide + j % kBlock) * kSide + i % kBlock;
    c[0] = s[0], c[1] = s[1], c[2] = s[kSide], c[3] = s[kSide + 1];
    c[4] = s[kSide * kSide], c[5] = s[kSide * kSide + 1], c[6] = s[kSide * kSide + kSide],
    c[7] = s[kSide * kSide + kSide + 1];
    return true;
}

double LevelSetGrid::value(const Vec3& p) const {
    const Vec3 r(p.x - mLo[0], p.y - mLo[1], p.z - mLo[2]);
    const Vec3 f = glm::floor(r);
    float c[8];
    if (!(f.x >= 0 && f.y >= 0 && f.z >= 0 && f.x < 1e9 && f.y < 1e9 && f.z < 1e9) ||
        !cellCorners(int(f.x), int(f.y), int(f.z), c))
        return mBackground;
    return trilinear<double>(c, r.x - f.x, r.y - f.y, r.z - f.z);
}

long double LevelSetGrid::valueExtended(const glm::tvec3<long double>& p) const {
    using L = long double;
    const L x = p.x - mLo[0], y = p.y - mLo[1], z = p.z - mLo[2];
    const L fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
    float c[8];
    if (!(fx >= 0 && fy >= 0 && fz >= 0 && fx < 1e9L && fy < 1e9L && fz < 1e9L) ||
        !cellCorners(int(fx), int(fy), int(fz), c))
        return mBackground;
    return trilinear<L>(c, x - fx, y - fy, z - fz);
}

double LevelSetGrid::valueGradient(const Vec3& p, Vec3& gradient) const {
    const Vec3 r(p.x - mLo[0], p.y - mLo[1], p.z - mLo[2]);
    const Vec3 f = glm::floor(r);
    float c[8];
    if (!(f.x >= 0 && f.y >= 0 && f.z >= 0 && f.x < 1e9 && f.y < 1e9 && f.z < 1e9) ||
        !cellCorners(int(f.x), int(f.y), int(f.z), c)) {
        gradient = Vec3(0.0);
        return mBackground;
    }
    const double u = r.x - f.x, v = r.y - f.y, w = r.z - f.z;
    // Differences along x at the four (y, z) edges, then interpolated in y and z; likewise.
    const double dx00 = double(c[1]) - c[0], dx10 = double(c[3]) - c[2];
    const double dx01 = double(c[5]) - c[4], dx11 = double(c[7]) - c[6];
    const double dy00 = double(c[2]) - c[0], dy10 = double(c[3]) - c[1];
    const double dy01 = double(c[6]) - c[4], dy11 = double(c[7]) - c[5];
    const double dz00 = double(c[4]) - c[0], dz10 = double(c[5]) - c[1];
    const double dz01 = double(c[6]) - c[2], dz11 = double(c[7]) - c[3];
    gradient.x = (1 - w) * ((1 - v) * dx00 + v * dx10) + w * ((1 - v) * dx01 + v * dx11);
    gradient.y = (1 - w) * ((1 - u) * dy00 + u * dy10) + w * ((1 - u) * dy01 + u * dy11);
    gradient.z = (1 - v) * ((1 - u) * dz00 + u * dz10) + v * ((1 - u) * dz01 + u * dz11);
    return trilinear<double>(c, u, v, w);
}

void LevelSetGrid::sampleRange(const int lo[3], const int hi[3], float& mn, float& mx) const {
    // Cells [lo, hi] use samples [lo, hi + 1]; a block holds the samples of its cells.
    const int blo[3] = {lo[0] / kBlock, lo[1] / kBlock, lo[2] / kBlock};
    const int bhi[3] = {hi[0] / kBlock, hi[1] / kBlock, hi[2] / kBlock};
    for (int gz = blo[2] / kGroup; gz <= bhi[2] / kGroup; ++gz)
        for (int gy = blo[1] / kGroup; gy <= bhi[1] / kGroup; ++gy)
            for (int gx = blo[0] / kGroup; gx <= bhi[0] / kGroup; ++gx) {
                const Group& g = groupAt(gx, gy, gz);
                const int g0[3] = {gx * kGroup, gy * kGroup, gz * kGroup};
                const bool covered = blo[0] <= g0[0] && blo[1] <= g0[1] && blo[2] <= g0[2] &&
                                     bhi[0] >= g0[0] + kGroup - 1 && bhi[1] >= g0[1] + kGroup - 1 &&
                                     bhi[2] >= g0[2] + kGroup - 1;
                if (g.firstBlock < 0 || covered) {
                    mn = std::min(mn, g.lo);
                    mx = std::max(mx, g.hi);
                    continue;
                }
                for (int bz = std::max(blo[2], g0[2]); bz <= std::min(bhi[2], g0[2] + kGroup - 1);
                     ++bz)
                    for (int by = std::max(blo[1], g0[1]);
                         by <= std::min(bhi[1], g0[1] + kGroup - 1); ++by)
                        for (int bx = std::max(blo[0], g0[0]);
                             bx <= std::min(bhi[0], g0[0] + kGroup - 1); ++bx) {
                            const Block& b = *blockAt(bx, by, bz);
                            if (b.brick < 0 || (b.lo >= mn && b.hi <= mx)) {
                                mn = std::min(mn, b.lo);
                                mx = std::max(mx, b.hi);
                                continue;
                            }
                            // The samples of this block's cells that are in [lo, hi].
                            int s0[3], s1[3];
                            const int b0[3] = {bx * kBlock, by * kBlock, bz * kBlock};
                            for (int a = 0; a < 3; ++a) {
                                s0[a] = std::max(lo[a], b0[a]) - b0[a];
                                s1[a] = std::min(hi[a], b0[a] + kBlock - 1) - b0[a] + 1;
                            }
                            const float* s = &mBricks[size_t(b.brick) * kBrickSize];
                            for (int k = s0[2]; k <= s1[2]; ++k)
                                for (int j = s0[1]; j <= s1[1]; ++j)
                                    for (int i = s0[0]; i <= s1[0]; ++i) {
                                        const float v = s[(k * kSide + j) * kSide + i];
                                        mn = std::min(mn, v);
                                        mx = std::max(mx, v);
                                    }
                        }
            }
}

Interval LevelSetGrid::range(const Interval& x, const Interval& y, const Interval& z) const {
    if (x.maybeNan || y.maybeNan || z.maybeNan) return Interval::entire();
    const Interval box[3] = {x, y, z};
    int lo[3], hi[3];
    bool outside = false;  // part of the box is outside the stored groups: the background
    bool none = false;     // the box misses the stored groups altogether
    for (int a = 0; a < 3; ++a) {
        const int n = mGroups[a] * kGroup * kBlock;  // cells along the axis
        const double l = box[a].lo - mLo[a], h = box[a].hi - mLo[a];
        if (!(l >= 0) || !(h < n)) outside = true;
        if (h < 0 || l >= n) none = true;
        lo[a] = floorToInt(l, 0, n - 1);
        hi[a] = floorToInt(h, 0, n - 1);
    }
    float mn = std::numeric_limits<float>::infinity(), mx = -mn;
    if (outside || none) mn = mx = mBackground;
    if (!none) sampleRange(lo, hi, mn, mx);
    // The interpolant is a convex combination of its corners; widen for its rounding.
    const double slack = (std::fabs(double(mn)) + std::fabs(double(mx))) * 1e-15 + 1e-300;
    return Interval(double(mn) - slack, double(mx) + slack);
}

}  // namespace kerf
