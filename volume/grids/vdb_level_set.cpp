// Reading a level set from a .vdb file (volume/grids/vdb_level_set.h): the grid is chosen and
// checked from the file's metadata, then its tree is copied into a LevelSetGrid's blocks. Blocks
// line up with OpenVDB's 8³ leaves, so a block is constant when none of the leaves its 9³ samples
// touch (its own and its seven upper neighbours) exists and their tile values agree.
#include "volume/grids/vdb_level_set.h"

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
    TreeSource(const FloatTree& tree, const openvdb::CoordBBox& box) : mAcc(tree) {
        background = tree.background();
        for (int a = 0; a < 3; ++a) {
            // A block of background on each side, so the walk starts and ends outside.
            const int first = (box.min()[a] >> 3) * 8 - LevelSetGrid::kBlock;
            const int last = (box.max()[a] >> 3) * 8 + 2 * LevelSetGrid::kBlock;  // exclusive
            lo[a] = first;
            blocks[a] = (last - first) / LevelSetGrid::kBlock;
        }
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

}  // namespace

std::shared_ptr<const LevelSetGrid> loadLevelSet(const std::string& path,
                                                 const std::string& gridName) {
    static std::once_flag once;
    std::call_once(once, [] { openvdb::initialize(); });
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw VdbError("no such file");
    if (std::filesystem::is_directory(path, ec)) throw VdbError("it is a folder, not a .vdb file");
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

        LevelSetInfo info;
        info.file = path;
        info.gridName = name;
        const openvdb::Vec3d vs = grid->transform().voxelSize();
        info.voxelSize = Vec3(vs.x(), vs.y(), vs.z());
        info.activeVoxels = grid->activeVoxelCount();
        info.background = tree.background();
        // OpenVDB's matrices act on row vectors: world = index · M, translation in row 3.
        const openvdb::Mat4d m = grid->transform().baseMap()->getAffineMap()->getMat4();
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) info.worldFromIndex.linear[i][j] = m(i, j);
        info.worldFromIndex.offset = Vec3(m(3, 0), m(3, 1), m(3, 2));

        const openvdb::CoordBBox box = storedBox(tree);
        if (box.empty())
            throw VdbError(what + " is empty: it has no values besides the background", true);
        auto result = std::make_shared<const LevelSetGrid>(TreeSource(tree, box), std::move(info));
        if (result->insideBounds().empty())
            throw VdbError(
                what + " has no value ≤ 0, so no inside (is it a fog volume without its class?)");
        return result;
    } catch (const openvdb::Exception& e) {
        throw VdbError(std::string("cannot read it as a .vdb file: ") + e.what());
    }
}

}  // namespace kerf
