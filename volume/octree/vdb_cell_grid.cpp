// The octree's coarse levels in an OpenVDB Int32 tree of tiles, bricks refined on first use,
// and the ray walk over both. The walk uses OpenVDB's node hierarchy for its skips (a 128³ or
// 8³ tile without surface is crossed in one step) but computes every segment end from the
// block's own planes, so the segments are exact up to one rounded division each.
#include "volume/octree/cell_grid.h"

#include <openvdb/openvdb.h>
#include <openvdb/tree/ValueAccessor.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>

namespace kerf {

// Named, not anonymous: CellGrid::Impl holds these types, and GCC warns (-Wsubobject-linkage)
// when an included file's class uses an anonymous namespace, as a unity build includes it.
namespace cell_grid_detail {

constexpr int32_t kEmptyValue = -1;  // the background: no solid here
constexpr int32_t kFullValue = -2;   // inactive, inside the solid

using Tree = openvdb::Int32Tree;
using Accessor = openvdb::tree::ValueAccessor<const Tree, /*IsSafe=*/false>;
static_assert(Tree::LeafNodeType::DIM == kBrickCells, "a brick is one OpenVDB leaf's extent");

/// Side, in cells, of the region a value found at OpenVDB tree depth `depth` stands for
/// (getValueDepth: −1 background, 0 root tile, 1 and 2 internal-node tiles, 3 a voxel).
int32_t regionSize(int depth) {
    switch (depth) {
        case 3: return 1;
        case 2: return Tree::LeafNodeType::DIM;                                // 8
        case 1: return Tree::RootNodeType::ChildNodeType::ChildNodeType::DIM;  // 128
        default: return Tree::RootNodeType::ChildNodeType::DIM;                // 4096
    }
}

struct Brick {
    CellCoord corner;
    NodePtr node;
    std::once_flag once;
    std::atomic<bool> built{false};  ///< content is complete (checked before call_once's cost)
    std::unique_ptr<BrickContent> content;  ///< made when a ray first reaches the brick
};

/// One ray's walk through the grid: where it crosses the cells' and blocks' planes, and its
/// steps through a brick's cells or across a block without surface. The steps return true
/// when the walk is over (tmax reached, the cube left, or the visitor stopped it).
class CellWalk {
public:
    CellWalk(const GridFrame& frame, const Ray& ray, double tmax, SegmentVisitor visit,
             void* context)
        : mFrame(frame), mRay(ray), mTmax(tmax), mVisit(visit), mContext(context) {
        // Plane crossings by one multiplication (one rounding more than a division, well
        // inside the caller's slack); a reciprocal that overflows (subnormal direction)
        // divides instead.
        for (int a = 0; a < 3; ++a) {
            mInv[a] = 1.0 / ray.dir[a];
            mDivide[a] = !std::isfinite(mInv[a]);
        }
    }

    /// The cell holding `p` (clamped: an entry point lies on the cube within rounding).
    openvdb::Coord cellAt(const Vec3& p) const {
        openvdb::Coord ijk;
        for (int a = 0; a < 3; ++a) {
            const double c = std::floor((p[a] - mFrame.origin[a]) / mFrame.h);
            ijk[a] = int32_t(std::clamp(c, 0.0, double(mFrame.n - 1)));
        }
        return ijk;
    }

    /// A brick the surface may cross: its cells one by one, from its own table, until the
    /// ray leaves it. A step to a neighbouring cell changes one coordinate only.
    bool throughBrick(const BrickContent& b, openvdb::Coord& ijk, double& t, int64_t& step,
                      int64_t limit, uint64_t& steps) const {
        const openvdb::Coord brick(ijk[0] & ~7, ijk[1] & ~7, ijk[2] & ~7);
        // Each cell's exit planes, computed from the planes themselves; a step changes
        // one coordinate, so only that axis's exit is computed anew.
        double exits[3];
        for (int a = 0; a < 3; ++a) exits[a] = planeExit(a, ijk[a], 1);
        while (step++ < limit) {
            ++steps;
            const Node* node = b.nodeAt(BrickContent::index(ijk[0] & 7, ijk[1] & 7, ijk[2] & 7));
            double tExit = mTmax;
            int axis = -1;
            for (int a = 0; a < 3; ++a)
                if (exits[a] < tExit) tExit = exits[a], axis = a;
            tExit = std::max(tExit, t);
            if (!mVisit(mContext, {t, tExit, node})) return true;
            if (axis < 0) return true;  // tmax reached inside this cell
            t = tExit;
            ijk[axis] += mRay.dir[axis] > 0.0 ? 1 : -1;
            if (ijk[axis] < 0 || ijk[axis] >= mFrame.n) return true;  // left the cube
            if ((ijk[axis] & ~7) != brick[axis]) break;               // left the brick
            exits[axis] = planeExit(axis, ijk[axis], 1);
        }
        return false;
    }

    /// A block without surface, `size` cells wide: skipped whole, as large as OpenVDB's tile
    /// or node is.
    bool acrossBlock(int32_t size, openvdb::Coord& ijk, double& t, int64_t& step,
                     uint64_t& steps) const {
        ++step;
        ++steps;
        openvdb::Coord block;
        for (int a = 0; a < 3; ++a) block[a] = ijk[a] & ~(size - 1);
        int axis;
        const double tExit = exitOf(block, size, t, axis);
        if (!mVisit(mContext, {t, tExit, nullptr})) return true;
        if (axis < 0) return true;  // tmax reached inside this block
        const int32_t next = mRay.dir[axis] > 0.0 ? block[axis] + size : block[axis] - 1;
        if (next < 0 || next >= mFrame.n) return true;  // left the cube
        // The ray has moved across the block on the other axes too: found from the exit point.
        const Vec3 p = mRay.at(tExit);
        for (int a = 0; a < 3; ++a) {
            if (a == axis) continue;
            const double c = std::floor((p[a] - mFrame.origin[a]) / mFrame.h);
            ijk[a] = int32_t(std::clamp(c, 0.0, double(mFrame.n - 1)));
        }
        ijk[axis] = next;
        t = tExit;
        return false;
    }

private:
    /// Where the ray crosses the far plane of coordinate c (a block of `size` from c) on axis
    /// a: +inf where it never does.
    double planeExit(int a, int32_t c, int32_t size) const {
        const double d = mRay.dir[a];
        double plane;
        if (d > 0.0)
            plane = mFrame.origin[a] + double(c + size) * mFrame.h;
        else if (d < 0.0)
            plane = mFrame.origin[a] + double(c) * mFrame.h;
        else
            return kInf;
        return mDivide[a] ? (plane - mRay.origin[a]) / d : (plane - mRay.origin[a]) * mInv[a];
    }

    /// Where the ray leaves the block of `size` cells at `block`, and across which axis (−1:
    /// not before tmax).
    double exitOf(const openvdb::Coord& block, int32_t size, double t, int& axis) const {
        double tExit = mTmax;
        axis = -1;
        for (int a = 0; a < 3; ++a) {
            const double te = planeExit(a, block[a], size);
            if (te < tExit) tExit = te, axis = a;
        }
        return std::max(tExit, t);
    }

    const GridFrame& mFrame;
    const Ray& mRay;
    const double mTmax;
    const SegmentVisitor mVisit;
    void* const mContext;
    double mInv[3];
    bool mDivide[3];
};

}  // namespace cell_grid_detail

// Qualified rather than `using namespace`: in the unity build it would reach later files.
namespace cgd = cell_grid_detail;

struct CellGrid::Impl {
    cgd::Tree tree{cgd::kEmptyValue};
    std::vector<std::unique_ptr<cgd::Brick>> bricks;
    BrickBuilder builder;
    std::atomic<uint64_t> built{0}, boundaryCells{0}, classified{0}, distinctNodes{0};

    /// The brick's content, classified now if no ray has reached it before.
    const BrickContent& content(int32_t index) {
        cgd::Brick& b = *bricks[size_t(index)];
        if (b.built.load(std::memory_order_acquire)) return *b.content;
        std::call_once(b.once, [&] {
            b.content = std::make_unique<BrickContent>();
            builder(b.corner, b.node, *b.content);
            built.fetch_add(1, std::memory_order_relaxed);
            boundaryCells.fetch_add(b.content->boundaryCells, std::memory_order_relaxed);
            classified.fetch_add(b.content->classified, std::memory_order_relaxed);
            distinctNodes.fetch_add(b.content->nodes.size(), std::memory_order_relaxed);
            b.built.store(true, std::memory_order_release);
        });
        return *b.content;
    }
};

CellGrid::CellGrid(const GridFrame& frame, std::vector<std::pair<CellCoord, NodePtr>> bricks,
                   const std::vector<std::pair<CellCoord, int32_t>>& fullBlocks,
                   BrickBuilder builder)
    : mFrame(frame), mImpl(std::make_unique<Impl>()) {
    mImpl->builder = std::move(builder);
    for (const auto& [c, size] : fullBlocks) {
        const openvdb::Coord lo(c[0], c[1], c[2]);
        mImpl->tree.fill(openvdb::CoordBBox(lo, lo.offsetBy(size - 1)), cgd::kFullValue, false);
    }
    mImpl->bricks.reserve(bricks.size());
    for (auto& [c, node] : bricks) {
        const int32_t index = int32_t(mImpl->bricks.size());
        auto b = std::make_unique<cgd::Brick>();
        b->corner = c;
        b->node = std::move(node);
        mImpl->bricks.push_back(std::move(b));
        // An active tile one leaf node wide: the walk finds the brick without a leaf node.
        const openvdb::Coord lo(c[0], c[1], c[2]);
        mImpl->tree.addTile(/*level=*/1, lo, index, /*active=*/true);
    }
}

CellGrid::~CellGrid() = default;

CellGrid::Counts CellGrid::counts() const {
    Counts c;
    c.bricks = mImpl->bricks.size();
    c.bricksBuilt = mImpl->built.load();
    c.boundaryCells = mImpl->boundaryCells.load();
    c.classified = mImpl->classified.load();
    c.distinctNodes = mImpl->distinctNodes.load();
    c.memoryBytes = mImpl->tree.memUsage() + c.bricks * sizeof(cgd::Brick);
    return c;
}

bool CellGrid::fullAt(const Vec3& p) const {
    openvdb::Coord ijk;
    for (int a = 0; a < 3; ++a) {
        const double c = std::floor((p[a] - mFrame.origin[a]) / mFrame.h);
        if (!(c >= 0.0 && c < double(mFrame.n))) return false;
        ijk[a] = int32_t(c);
    }
    int32_t value = cgd::kEmptyValue;
    if (!mImpl->tree.probeValue(ijk, value)) return value == cgd::kFullValue;
    const BrickContent& b = mImpl->content(value);
    return b.full[BrickContent::index(ijk[0] & 7, ijk[1] & 7, ijk[2] & 7)];
}

bool CellGrid::walk(const Ray& ray, double tmin, double tmax, SegmentVisitor visit, void* context,
                    uint64_t& steps) const {
    if (!(tmin <= tmax)) return true;
    const cgd::CellWalk w{mFrame, ray, tmax, visit, context};
    cgd::Accessor acc(mImpl->tree);
    openvdb::Coord ijk = w.cellAt(ray.at(tmin));
    // A walk crosses at most 3n cells; more steps can only come from rounding at corners.
    const int64_t limit = 3 * int64_t(mFrame.n) + 16;
    int64_t step = 0;
    double t = tmin;
    while (step < limit) {
        int32_t value = cgd::kEmptyValue;
        const bool done =
            acc.probeValue(ijk, value)
                ? w.throughBrick(mImpl->content(value), ijk, t, step, limit, steps)
                : w.acrossBlock(cgd::regionSize(acc.getValueDepth(ijk)), ijk, t, step, steps);
        if (done) return true;
    }
    return false;
}

}  // namespace kerf
