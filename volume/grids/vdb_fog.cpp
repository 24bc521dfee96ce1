/// @file volume/grids/vdb_fog.cpp
/// @brief The fog volume field (see vdb_fog.h).
#include "volume/grids/vdb_fog.h"

#include <openvdb/openvdb.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <vector>

namespace kerf {
namespace {

using Accessor = openvdb::tree::ValueAccessor<const openvdb::FloatTree, false>;

/// Blocks are the grid's 8³ leaves; level k of the pyramid holds blocks of 8·2ᵏ voxels.
constexpr int kBlock = 8;

struct Level {
    int n[3] = {0, 0, 0};
    std::vector<float> lo, hi;
    size_t index(int i, int j, int k) const { return (size_t(k) * n[1] + j) * n[0] + i; }
};

/// Each thread's accessor for the field it used last (an unsafe accessor is not registered
/// with the tree, so dropping it after its tree is gone is harmless).
struct AccessorCache {
    uint64_t owner = 0;
    std::unique_ptr<Accessor> accessor;
};
thread_local AccessorCache tAccessor;
std::atomic<uint64_t> gNextId{1};

class FogField final : public ScalarField {
public:
    explicit FogField(openvdb::FloatGrid::ConstPtr grid) : mGrid(std::move(grid)), mId(gNextId++) {
        mBackground = mGrid->background();
        openvdb::CoordBBox box = mGrid->evalActiveVoxelBoundingBox();
        // Block-aligned origin and size, one voxel of margin for trilinear support.
        for (int a = 0; a < 3; ++a) {
            mOrigin[a] = int(std::floor(double(box.min()[a] - 1) / kBlock)) * kBlock;
            const int last = int(std::floor(double(box.max()[a] + 1) / kBlock));
            mBase.n[a] = last - mOrigin[a] / kBlock + 1;
        }
        const size_t count = size_t(mBase.n[0]) * mBase.n[1] * mBase.n[2];
        mBase.lo.assign(count, std::min(mBackground, 0.0f));
        mBase.hi.assign(count, std::max(mBackground, 0.0f));
        for (auto leaf = mGrid->tree().cbeginLeaf(); leaf; ++leaf) {
            const openvdb::Coord o = leaf->origin();
            int b[3];
            if (!blockOf(o, b)) continue;
            float lo = kInfF, hi = -kInfF;
            for (auto v = leaf->cbeginValueAll(); v; ++v)
                lo = std::min(lo, *v), hi = std::max(hi, *v);
            mBase.lo[mBase.index(b[0], b[1], b[2])] = lo;
            mBase.hi[mBase.index(b[0], b[1], b[2])] = hi;
        }
        // Tiles (constant regions above the leaves) cover whole blocks.
        for (auto t = mGrid->tree().cbeginValueAll(); t; ++t) {
            if (t.isVoxelValue()) continue;
            const openvdb::CoordBBox tb = t.getBoundingBox();
            int b0[3], b1[3];
            for (int a = 0; a < 3; ++a) {
                b0[a] = std::max(0, (tb.min()[a] - mOrigin[a]) / kBlock);
                b1[a] = std::min(mBase.n[a] - 1, (tb.max()[a] - mOrigin[a]) / kBlock);
            }
            for (int k = b0[2]; k <= b1[2]; ++k)
                for (int j = b0[1]; j <= b1[1]; ++j)
                    for (int i = b0[0]; i <= b1[0]; ++i) {
                        const size_t id = mBase.index(i, j, k);
                        mBase.lo[id] = std::min(mBase.lo[id], float(*t));
                        mBase.hi[id] = std::max(mBase.hi[id], float(*t));
                    }
        }
        mLevels.push_back(mBase);
        while (std::max({mLevels.back().n[0], mLevels.back().n[1], mLevels.back().n[2]}) > 1) {
            const Level& f = mLevels.back();
            Level c;
            for (int a = 0; a < 3; ++a) c.n[a] = (f.n[a] + 1) / 2;
            c.lo.assign(size_t(c.n[0]) * c.n[1] * c.n[2], kInfF);
            c.hi.assign(c.lo.size(), -kInfF);
            for (int k = 0; k < f.n[2]; ++k)
                for (int j = 0; j < f.n[1]; ++j)
                    for (int i = 0; i < f.n[0]; ++i) {
                        const size_t from = f.index(i, j, k), to = c.index(i / 2, j / 2, k / 2);
                        c.lo[to] = std::min(c.lo[to], f.lo[from]);
                        c.hi[to] = std::max(c.hi[to], f.hi[from]);
                    }
            mLevels.push_back(std::move(c));
        }
        for (const Level& l : mLevels)
            for (float v : l.lo)
                if (v < 0.0f) mMinValue = std::min(mMinValue, v);
    }

    float minValue() const { return mMinValue; }

    Bounds3 worldBounds() const {
        const openvdb::CoordBBox box = mGrid->evalActiveVoxelBoundingBox();
        Bounds3 b;
        for (int c = 0; c < 8; ++c) {
            const openvdb::Vec3d idx(c & 1 ? box.max().x() + 1 : box.min().x() - 1,
                                     c & 2 ? box.max().y() + 1 : box.min().y() - 1,
                                     c & 4 ? box.max().z() + 1 : box.min().z() - 1);
            const openvdb::Vec3d w = mGrid->transform().indexToWorld(idx);
            b.extend(Vec3(w.x(), w.y(), w.z()));
        }
        return b;
    }

    double value(const Vec3& p) const override {
        const openvdb::Vec3d q = mGrid->transform().worldToIndex(openvdb::Vec3d(p.x, p.y, p.z));
        const Accessor& acc = accessor();
        const openvdb::Coord c(int(std::floor(q.x())), int(std::floor(q.y())),
                               int(std::floor(q.z())));
        const double fx = q.x() - c.x(), fy = q.y() - c.y(), fz = q.z() - c.z();
        double v = 0.0;
        for (int n = 0; n < 8; ++n) {
            const double w = (n & 1 ? fx : 1 - fx) * (n & 2 ? fy : 1 - fy) * (n & 4 ? fz : 1 - fz);
            if (w != 0.0) v += w * acc.getValue(c.offsetBy(n & 1, (n >> 1) & 1, (n >> 2) & 1));
        }
        return v;
    }
    long double valueExtended(const glm::tvec3<long double>& p) const override {
        return value(Vec3(double(p.x), double(p.y), double(p.z)));
    }
    double valueGradient(const Vec3& p, Vec3& gradient) const override {
        gradient = Vec3(0.0);  // media never ask for it
        return value(p);
    }

    /// The trilinear value over a world box lies within the voxel values that support it:
    /// the min and max of the blocks (at a level where the box spans at most 4 of them).
    Interval range(const Interval& x, const Interval& y, const Interval& z) const override {
        const Interval w[3] = {x, y, z};
        double lo[3] = {kInf, kInf, kInf}, hi[3] = {-kInf, -kInf, -kInf};
        for (int c = 0; c < 8; ++c) {
            const openvdb::Vec3d q = mGrid->transform().worldToIndex(openvdb::Vec3d(
                c & 1 ? w[0].hi : w[0].lo, c & 2 ? w[1].hi : w[1].lo, c & 4 ? w[2].hi : w[2].lo));
            for (int a = 0; a < 3; ++a)
                lo[a] = std::min(lo[a], q[a]), hi[a] = std::max(hi[a], q[a]);
        }
        int b0[3], b1[3];
        bool outside = false;
        for (int a = 0; a < 3; ++a) {
            if (!(std::fabs(lo[a]) < 1e9 && std::fabs(hi[a]) < 1e9)) return Interval::entire();
            // Trilinear support: voxels floor(lo) … floor(hi) + 1 (a hair wider for rounding).
            const int v0 = int(std::floor(lo[a] - 1e-6)), v1 = int(std::floor(hi[a] + 1e-6)) + 1;
            b0[a] = int(std::floor(double(v0 - mOrigin[a]) / kBlock));
            b1[a] = int(std::floor(double(v1 - mOrigin[a]) / kBlock));
            if (b0[a] < 0 || b1[a] >= mBase.n[a]) outside = true;
            b0[a] = std::max(b0[a], 0);
            b1[a] = std::min(b1[a], mBase.n[a] - 1);
            if (b0[a] > b1[a]) return Interval(mBackground, mBackground);
        }
        size_t level = 0;
        while (level + 1 < mLevels.size() &&
               (b1[0] - b0[0] > 3 || b1[1] - b0[1] > 3 || b1[2] - b0[2] > 3)) {
            ++level;
            for (int a = 0; a < 3; ++a) b0[a] >>= 1, b1[a] >>= 1;
        }
        const Level& l = mLevels[level];
        double rlo = outside ? mBackground : kInf, rhi = outside ? mBackground : -kInf;
        for (int k = b0[2]; k <= b1[2]; ++k)
            for (int j = b0[1]; j <= b1[1]; ++j)
                for (int i = b0[0]; i <= b1[0]; ++i) {
                    const size_t id = l.index(i, j, k);
                    rlo = std::min(rlo, double(l.lo[id]));
                    rhi = std::max(rhi, double(l.hi[id]));
                }
        return Interval(rlo, rhi);
    }
    double lipschitz() const override { return kInf; }

private:
    static constexpr float kInfF = std::numeric_limits<float>::infinity();

    bool blockOf(const openvdb::Coord& o, int b[3]) const {
        for (int a = 0; a < 3; ++a) {
            b[a] = (o[a] - mOrigin[a]) / kBlock;
            if (o[a] < mOrigin[a] || b[a] >= mBase.n[a]) return false;
        }
        return true;
    }
    const Accessor& accessor() const {
        if (tAccessor.owner != mId) {
            tAccessor.accessor = std::make_unique<Accessor>(mGrid->tree());
            tAccessor.owner = mId;
        }
        return *tAccessor.accessor;
    }

    openvdb::FloatGrid::ConstPtr mGrid;
    uint64_t mId;
    float mBackground = 0.0f;
    float mMinValue = 0.0f;
    int mOrigin[3] = {0, 0, 0};
    Level mBase;
    std::vector<Level> mLevels;
};

}  // namespace

VdbFog loadVdbFog(const std::string& path, const std::string& gridName) {
    openvdb::initialize();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) throw VdbFogError("no such file");
    openvdb::io::File file(path);
    openvdb::GridPtrVecPtr grids;
    try {
        file.open(false);
        grids = file.getGrids();
        file.close();
    } catch (const std::exception& e) {
        throw VdbFogError(std::string("not a readable .vdb file (") + e.what() + ")");
    }
    openvdb::GridBase::Ptr chosen;
    std::string names;
    for (const auto& g : *grids) {
        names += (names.empty() ? "" : ", ") + ("'" + g->getName() + "'");
        if (!gridName.empty()
                ? g->getName() == gridName
                : (g->getName() == "density" || (!chosen && g->isType<openvdb::FloatGrid>())))
            chosen = g;
    }
    if (!chosen)
        throw VdbFogError(gridName.empty()
                              ? "the file has no float grid (grids: " + names + ")"
                              : "the file has no grid '" + gridName + "' (grids: " +
                                    (names.empty() ? std::string("none") : names) + ")");
    if (!chosen->isType<openvdb::FloatGrid>())
        throw VdbFogError("grid '" + chosen->getName() + "' holds " + chosen->valueType() +
                          " values; a fog volume is a float grid");
    if (chosen->getGridClass() == openvdb::GRID_LEVEL_SET)
        throw VdbFogError("grid '" + chosen->getName() +
                          "' is a level set (a surface), not a fog volume of density");
    auto grid = openvdb::gridConstPtrCast<openvdb::FloatGrid>(chosen);
    if (grid->activeVoxelCount() == 0)
        throw VdbFogError("grid '" + chosen->getName() + "' has no active voxels");
    if (!grid->transform().isLinear())
        throw VdbFogError("grid '" + chosen->getName() + "' has a non-linear transform");
    auto field = std::make_shared<FogField>(grid);
    if (field->minValue() < 0.0f)
        throw VdbFogError("grid '" + chosen->getName() + "' holds negative density (down to " +
                          std::to_string(field->minValue()) + ")");
    return {field, field->worldBounds(), chosen->getName()};
}

}  // namespace kerf
