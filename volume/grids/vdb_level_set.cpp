// Reading a level set from a .vdb file (volume/grids/vdb_level_set.h): the grid is chosen and
// checked from the file's metadata, then its tree is copied into a LevelSetGrid's blocks. Blocks
// line up with OpenVDB's 8³ leaves, so a block is constant when none of the leaves its 9³ samples
// touch (its own and its seven upper neighbours) exists and their tile values agree.
#include "volume/grids/vdb_level_set.h"

#include "volume/grids/checked_vdb_layout.h"

#include <openvdb/openvdb.h>

#include <algorithm>
#include <filesystem>
#include <mutex>
#include <vector>

namespace kerf {

namespace {

using openvdb::Coord;
using openvdb::FloatGrid;
using FloatTree = FloatGrid::TreeType;

std::string className(openvdb::GridClass c) {
    switch (c) {
        case openvdb::GRID_LEVEL_SET: return "level set";
        case openvdb::GRID_FOG_VOLUME: return "fog volume";
        case openvdb::GRID_STAGGERED: return "staggered";
        default: return "unknown class";
    }
}

/// The file's grids by name: name (value type, class), ….
std::string describeGrids(const openvdb::GridPtrVec& grids) {
    std::vector<std::string> items;
    for (const auto& g : grids)
        items.push_back("'" + g->getName() + "' (" + g->valueType() + ", " +
                        className(g->getGridClass()) + ")");
    std::sort(items.begin(), items.end());
    std::string s;
    for (const std::string& item : items) s += (s.empty() ? "" : ", ") + item;
    return items.empty() ? std::string("no grids") : s;
}

/// The grid's samples for LevelSetGrid, read through an accessor (one per source: the build is
/// single-threaded).
class TreeSource final : public LevelSetGrid::Source {
public:
    /// `box` is within ±LevelSetGrid::kMaxIndex (checked by the caller), so every coordinate
    /// below fits an int with room for a group's margin.
    TreeSource(const FloatTree& tree, const openvdb::CoordBBox& box) : mTree(tree), mAcc(tree) {
        background = tree.background();
        for (int a = 0; a < 3; ++a) {
            // Groups line up with OpenVDB's 128³ internal nodes; a block of background before
            // and after the data, so the walk starts and ends outside.
            const int64_t first =
                floorDivide(int64_t(box.min()[a]) - 8, kGroupVoxels) * kGroupVoxels;
            const int64_t last = floorDivide(box.max()[a], 8) * 8 + 2 * LevelSetGrid::kBlock;
            lo[a] = int32_t(first);
            blocks[a] = int32_t((last - first) / LevelSetGrid::kBlock);
        }
    }

    /// Each 128³ internal node and each tile other than the background makes the groups whose
    /// samples reach it vary: the node's group and its lower neighbours, a tile's shell.
    void listVaryingGroups(std::vector<std::array<int32_t, 3>>& out) const override {
        for (auto node = mTree.cbeginNode(); node; ++node) {
            if (node.getDepth() != kInternal1Depth) continue;
            openvdb::CoordBBox nb;
            node.getBoundingBox(nb);
            const std::array<int32_t, 3> g = groupOf(nb.min());
            for (int c = 0; c < 8; ++c)
                out.push_back({g[0] - (c & 1), g[1] - ((c >> 1) & 1), g[2] - ((c >> 2) & 1)});
        }
        auto tile = mTree.cbeginValueAll();
        tile.setMaxDepth(kInternal1Depth - 1);  // tiles of 128³ voxels and more
        for (; tile; ++tile) {
            if (tile.isVoxelValue() || *tile == mTree.background()) continue;
            openvdb::CoordBBox tb;
            tile.getBoundingBox(tb);
            listTileShell(groupOf(tb.min()), groupOf(tb.max()), out);
        }
    }

    float groupValue(int gx, int gy, int gz) const override {
        return mAcc.getValue(groupOrigin(gx, gy, gz));
    }

    bool groupHasDetail(int gx, int gy, int gz) const override {
        return mAcc.probeConstNode<Internal1>(groupOrigin(gx, gy, gz)) != nullptr;
    }

    bool isConstant(int bx, int by, int bz, float& value) const override {
        const Coord o(lo[0] + 8 * bx, lo[1] + 8 * by, lo[2] + 8 * bz);
        bool first = true;
        for (int c = 0; c < 8; ++c) {
            const Coord n = o.offsetBy((c & 1) ? 8 : 0, (c & 2) ? 8 : 0, (c & 4) ? 8 : 0);
            if (mAcc.probeConstLeaf(n)) return false;
            const float v = mAcc.getValue(n);
            if (first)
                value = v, first = false;
            else if (v != value)
                return false;
        }
        return true;
    }

    void fillBrick(int bx, int by, int bz, float* samples) const override {
        const Coord o(lo[0] + 8 * bx, lo[1] + 8 * by, lo[2] + 8 * bz);
        const auto* leaf = mAcc.probeConstLeaf(o);
        for (int k = 0; k <= 8; ++k)
            for (int j = 0; j <= 8; ++j)
                for (int i = 0; i <= 8; ++i) {
                    float& s = samples[(k * 9 + j) * 9 + i];
                    if (leaf && i < 8 && j < 8 && k < 8) {
                        s = leaf->getValue(
                            FloatTree::LeafNodeType::coordToOffset(o.offsetBy(i, j, k)));
                    } else {
                        s = mAcc.getValue(o.offsetBy(i, j, k));
                    }
                }
    }

private:
    using Internal1 = FloatTree::RootNodeType::ChildNodeType::ChildNodeType;
    static constexpr int kInternal1Depth = 2;  // root 0, 4096³ nodes 1, 128³ nodes 2, leaves 3
    static constexpr int64_t kGroupVoxels = LevelSetGrid::kGroupVoxels;

    static int64_t floorDivide(int64_t a, int64_t b) {
        return a >= 0 ? a / b : -((-a + b - 1) / b);
    }

    std::array<int32_t, 3> groupOf(const Coord& c) const {
        std::array<int32_t, 3> g;
        for (int a = 0; a < 3; ++a)
            g[a] = int32_t(floorDivide(int64_t(c[a]) - lo[a], kGroupVoxels));
        return g;
    }
    Coord groupOrigin(int gx, int gy, int gz) const {
        return Coord(int32_t(lo[0] + int64_t(gx) * kGroupVoxels),
                     int32_t(lo[1] + int64_t(gy) * kGroupVoxels),
                     int32_t(lo[2] + int64_t(gz) * kGroupVoxels));
    }

    /// The groups whose samples reach both the tile of groups [a, b] and beyond it: those of
    /// [a − 1, b] outside [a, b − 1].
    static void listTileShell(const std::array<int32_t, 3>& a, const std::array<int32_t, 3>& b,
                              std::vector<std::array<int32_t, 3>>& out) {
        const auto inner = [&](int axis, int32_t v) { return v >= a[axis] && v < b[axis]; };
        for (int32_t z = a[2] - 1; z <= b[2]; ++z)
            for (int32_t y = a[1] - 1; y <= b[1]; ++y) {
                if (inner(1, y) && inner(2, z)) {  // only the two ends of the row are in the shell
                    out.push_back({a[0] - 1, y, z});
                    out.push_back({b[0], y, z});
                    continue;
                }
                for (int32_t x = a[0] - 1; x <= b[0]; ++x) out.push_back({x, y, z});
            }
    }

    const FloatTree& mTree;
    mutable openvdb::tree::ValueAccessor<const FloatTree> mAcc;
};

/// The box of every leaf and every tile that is not the background.
openvdb::CoordBBox storedBox(const FloatTree& tree) {
    openvdb::CoordBBox box;
    tree.evalLeafBoundingBox(box);
    auto it = tree.cbeginValueAll();
    it.setMaxDepth(FloatTree::ValueAllCIter::LEAF_DEPTH - 1);  // tiles only
    for (; it; ++it) {
        if (*it == tree.background()) continue;
        openvdb::CoordBBox tile;
        it.getBoundingBox(tile);
        box.expand(tile);
    }
    return box;
}

/// The grid's box against LevelSetGrid's limits, in 64 bits (its corners may be near the int
/// range, where OpenVDB's own dim() overflows).
void checkLevelSetExtent(const std::string& what, const openvdb::CoordBBox& box) {
    for (int a = 0; a < 3; ++a)
        for (const int64_t c : {int64_t(box.min()[a]), int64_t(box.max()[a])})
            if (c < -LevelSetGrid::kMaxIndex || c > LevelSetGrid::kMaxIndex)
                throw VdbError(what + " has data at index " + std::to_string(c) + " along " +
                                   "xyz"[a] + ", beyond ±" +
                                   std::to_string(LevelSetGrid::kMaxIndex) +
                                   " (kerf's range for a level set's index coordinates)",
                               true);
    uint64_t groups = 1;  // each factor ≤ 2^25 + 3, and the product stops at the limit
    std::string sides;
    for (int a = 0; a < 3; ++a) {
        const int64_t side = int64_t(box.max()[a]) - box.min()[a] + 1;
        sides += (a ? " x " : "") + std::to_string(side);
        groups = std::min<uint64_t>(groups * uint64_t(side / LevelSetGrid::kGroupVoxels + 3),
                                    LevelSetGrid::kMaxGroups + 1);
    }
    if (groups > LevelSetGrid::kMaxGroups)
        throw VdbError(what + "'s data spans a box of " + sides +
                           " voxels (its leaves and tiles); a level set's box may hold at most " +
                           std::to_string(LevelSetGrid::kMaxGroups) +
                           " blocks of 128³ voxels (about 20,000 voxels a side)",
                       true);
}

/// What `kerf check` says about the grid, from the file.
LevelSetInfo levelSetInfo(const FloatGrid& grid, const std::string& path) {
    LevelSetInfo info;
    info.file = path;
    info.gridName = grid.getName();
    const openvdb::Vec3d vs = grid.transform().voxelSize();
    info.voxelSize = Vec3(vs.x(), vs.y(), vs.z());
    info.activeVoxels = grid.activeVoxelCount();
    info.background = grid.tree().background();
    // OpenVDB's matrices act on row vectors: world = index · M, translation in row 3.
    const openvdb::Mat4d m = grid.transform().baseMap()->getAffineMap()->getMat4();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) info.worldFromIndex.linear[i][j] = m(i, j);
    info.worldFromIndex.offset = Vec3(m(3, 0), m(3, 1), m(3, 2));
    return info;
}

}  // namespace

std::shared_ptr<const LevelSetGrid> loadLevelSet(const std::string& path,
                                                 const std::string& gridName) {
    static std::once_flag once;
    std::call_once(once, [] { openvdb::initialize(); });
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw VdbError("no such file");
    if (std::filesystem::is_directory(path, ec)) throw VdbError("it is a folder, not a .vdb file");
    if (const std::string bad = checkVdbLayout(path); !bad.empty()) throw VdbError(bad);
    try {
        openvdb::io::File file(path);
        file.open(false);  // no delayed loading: the file may change after this returns
        const openvdb::GridPtrVecPtr grids = file.readAllGridMetadata();
        openvdb::GridBase::ConstPtr chosen;
        for (const auto& g : *grids) {
            if (gridName.empty() ? g->getGridClass() == openvdb::GRID_LEVEL_SET
                                 : g->getName() == gridName) {
                chosen = g;
                break;
            }
        }
        if (!chosen && gridName.empty() && grids->size() == 1) chosen = grids->front();
        if (!chosen) {
            file.close();
            if (!gridName.empty())
                throw VdbError(
                    "it has no grid named '" + gridName + "'; its grids: " + describeGrids(*grids),
                    true);
            throw VdbError("it has no level-set grid; its grids: " + describeGrids(*grids) +
                           "; name one with grid \"name\"");
        }
        const std::string name = chosen->getName();
        const std::string what = "grid '" + name + "'";
        if (chosen->getGridClass() == openvdb::GRID_FOG_VOLUME) {
            file.close();
            throw VdbError(what +
                               " is a fog volume (grid class fog volume), not a level set: it has "
                               "densities, not an inside and an outside",
                           true);
        }
        if (!chosen->isType<FloatGrid>()) {
            file.close();
            throw VdbError(
                what + " holds " + chosen->valueType() + " values; a solid needs a float level set",
                true);
        }
        if (!chosen->transform().isLinear()) {
            file.close();
            throw VdbError(
                what + " has a frustum (non-affine) transform; only affine grids are supported",
                true);
        }
        const FloatGrid::ConstPtr grid = openvdb::gridConstPtrCast<FloatGrid>(file.readGrid(name));
        file.close();
        const FloatTree& tree = grid->tree();
        if (!(tree.background() > 0.f))
            throw VdbError(what + " has background " + std::to_string(tree.background()) +
                               ": a level set's outside must be positive",
                           true);

        LevelSetInfo info = levelSetInfo(*grid, path);
        const openvdb::CoordBBox box = storedBox(tree);
        if (box.empty())
            throw VdbError(what + " is empty: it has no values besides the background", true);
        checkLevelSetExtent(what, box);
        auto result = std::make_shared<const LevelSetGrid>(TreeSource(tree, box), std::move(info));
        if (result->insideBounds().empty())
            throw VdbError(
                what + " has no value ≤ 0, so no inside (is it a fog volume without its class?)");
        return result;
    } catch (const openvdb::Exception& e) {
        throw VdbError(std::string("cannot read it as a .vdb file: ") + e.what());
    } catch (const std::bad_alloc&) {  // a length inside the grids' nodes kerf does not check
        throw VdbError(
            "cannot read it as a .vdb file: its grids ask for more memory than there is");
    }
}

}  // namespace kerf
