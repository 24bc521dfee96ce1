/// @file volume/grids/vdb_fog.cpp
/// @brief The fog volume field (see vdb_fog.h).
#include "volume/grids/vdb_fog.h"

#include "volume/grids/block_pyramid.h"
#include "volume/grids/checked_vdb_layout.h"

#include <openvdb/openvdb.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <vector>

namespace kerf {
namespace {

using FogAccessor = openvdb::tree::ValueAccessor<const openvdb::FloatTree, false>;

/// Blocks are the grid's 8³ leaves; level k of the pyramid holds blocks of 8·2ᵏ voxels.
constexpr int kBlock = 8;

constexpr float kInfF = std::numeric_limits<float>::infinity();

/// The grid's leaves and tiles as a min/max pyramid over its 8³ blocks: work and memory
/// follow the leaves and tiles the file holds, not its bounding box.
BlockPyramid makePyramid(const openvdb::FloatGrid& grid) {
    const openvdb::CoordBBox box = grid.evalActiveVoxelBoundingBox();
    BlockCoord lo, hi;
    for (int a = 0; a < 3; ++a) {  // one voxel of margin for trilinear support
        lo[a] = int(std::floor((double(box.min()[a]) - 1) / kBlock));
        hi[a] = int(std::floor((double(box.max()[a]) + 1) / kBlock));
    }
    BlockPyramid pyramid(grid.background(), lo, hi);
    for (auto leaf = grid.tree().cbeginLeaf(); leaf; ++leaf) {
        float vlo = kInfF, vhi = -kInfF;
        for (auto v = leaf->cbeginValueAll(); v; ++v)
            vlo = std::min(vlo, *v), vhi = std::max(vhi, *v);
        const openvdb::Coord o = leaf->origin();  // a multiple of 8: the division is exact
        pyramid.addBlock({o.x() / kBlock, o.y() / kBlock, o.z() / kBlock}, vlo, vhi);
    }
    // Tiles (constant regions above the leaves) are aligned cubes of 2^k blocks a side.
    for (auto t = grid.tree().cbeginValueAll(); t; ++t) {
        if (t.isVoxelValue()) continue;
        const openvdb::CoordBBox tb = t.getBoundingBox();
        // In 64 bits: a tile at the end of the int range ends at INT_MAX, and dim() overflows.
        const int side = int((int64_t(tb.max().x()) - tb.min().x() + 1) / kBlock);
        int level = 0;
        while ((1 << level) < side) ++level;
        const openvdb::Coord o = tb.min();
        const int cube = kBlock * side;
        pyramid.addTile(level, {o.x() / cube, o.y() / cube, o.z() / cube}, float(*t));
    }
    pyramid.finish();
    return pyramid;
}

/// Each thread's accessor for the field it used last (an unsafe accessor is not registered
/// with the tree, so dropping it after its tree is gone is harmless).
struct AccessorCache {
    uint64_t owner = 0;
    std::unique_ptr<FogAccessor> accessor;
};
thread_local AccessorCache tAccessor;
std::atomic<uint64_t> gNextId{1};

class FogField final : public ScalarField {
public:
    explicit FogField(openvdb::FloatGrid::ConstPtr grid)
        : mGrid(std::move(grid)), mId(gNextId++), mPyramid(makePyramid(*mGrid)) {}

    /// The least value held anywhere, or 0 (negative density is refused on reading).
    float minValue() const { return float(std::min(mPyramid.whole().lo, 0.0)); }

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
        const FogAccessor& acc = accessor();
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
        BlockCoord b0, b1;
        for (int a = 0; a < 3; ++a) {
            // Beyond 2^34 voxels a block number would not fit an int (index coordinates are ints).
            if (!(std::fabs(lo[a]) < 1.6e10 && std::fabs(hi[a]) < 1.6e10))
                return Interval::entire();
            // Trilinear support: voxels floor(lo) … floor(hi) + 1 (a hair wider for rounding).
            b0[a] = int(std::floor((std::floor(lo[a] - 1e-6)) / kBlock));
            b1[a] = int(std::floor((std::floor(hi[a] + 1e-6) + 1) / kBlock));
        }
        return mPyramid.range(b0, b1);
    }
    double lipschitz() const override { return kInf; }

private:
    const FogAccessor& accessor() const {
        if (tAccessor.owner != mId) {
            tAccessor.accessor = std::make_unique<FogAccessor>(mGrid->tree());
            tAccessor.owner = mId;
        }
        return *tAccessor.accessor;
    }

    openvdb::FloatGrid::ConstPtr mGrid;
    uint64_t mId;
    BlockPyramid mPyramid;
};

}  // namespace

VdbFog loadVdbFog(const std::string& path, const std::string& gridName) {
    openvdb::initialize();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) throw VdbFogError("no such file");
    if (const std::string bad = checkVdbLayout(path); !bad.empty()) throw VdbFogError(bad);
    openvdb::io::File file(path);
    openvdb::GridPtrVecPtr grids;
    try {
        file.open(false);
        grids = file.readAllGridMetadata();  // the trees of the chosen grid only, below
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
    if (!chosen->transform().isLinear())
        throw VdbFogError("grid '" + chosen->getName() + "' has a non-linear transform");
    openvdb::FloatGrid::ConstPtr grid;
    try {
        grid = openvdb::gridConstPtrCast<openvdb::FloatGrid>(file.readGrid(chosen->getName()));
        file.close();
    } catch (const std::exception& e) {
        throw VdbFogError(std::string("not a readable .vdb file (") + e.what() + ")");
    }
    if (grid->activeVoxelCount() == 0)
        throw VdbFogError("grid '" + chosen->getName() + "' has no active voxels");
    std::shared_ptr<FogField> field;
    try {
        field = std::make_shared<FogField>(grid);
    } catch (const std::bad_alloc&) {  // its min/max pyramid over the leaves
        throw VdbFogError("grid '" + chosen->getName() +
                          "' needs more memory than there is to sample as fog");
    }
    if (field->minValue() < 0.0f)
        throw VdbFogError("grid '" + chosen->getName() + "' holds negative density (down to " +
                          std::to_string(field->minValue()) + ")");
    return {field, field->worldBounds(), chosen->getName()};
}

}  // namespace kerf
