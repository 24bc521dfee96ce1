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

namespace {

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

}  // namespace

struct CellGrid::Impl {
    Tree tree{kEmptyValue};
    std::vector<std::unique_ptr<Brick>> bricks;
    BrickBuilder builder;
    std::atomic<uint64_t> built{0}, boundaryCells{0}, classified{0}, distinctNodes{0};

    /// The brick's content, classified now if no ray has reached it before.
    const BrickContent& content(int32_t index) {
        Brick& b = *bricks[size_t(index)];
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
        mImpl->tree.fill(openvdb::CoordBBox(lo, lo.offsetBy(size - 1)), kFullValue, false);
    }
    mImpl->bricks.reserve(bricks.size());
    for (auto& [c, node] : bricks) {
        const int32_t index = int32_t(mImpl->bricks.size());
        auto b = std::make_unique<Brick>();
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
    c.memoryBytes = mImpl->tree.memUsage() + c.bricks * sizeof(Brick);
    return c;
}

bool CellGrid::fullAt(const Vec3& p) const {
    openvdb::Coord ijk;
    for (int a = 0; a < 3; ++a) {
        const double c = std::floor((p[a] - mFrame.origin[a]) / mFrame.h);
        if (!(c >= 0.0 && c < double(mFrame.n))) return false;
        ijk[a] = int32_t(c);
    }
    int32_t value = kEmptyValue;
    if (!mImpl->tree.probeValue(ijk, value)) return value == kFullValue;
    const BrickContent& b = mImpl->content(value);
    return b.full[BrickContent::index(ijk[0] & 7, ijk[1] & 7, ijk[2] & 7)];
}

bool CellGrid::walk(const Ray& ray, double tmin, double tmax, SegmentVisitor visit, void* context,
                    uint64_t& steps) const {
    if (!(tmin <= tmax)) return true;
    const GridFrame& f = mFrame;
    Accessor acc(mImpl->tree);
    // The cell holding the entry point (clamped: the entry lies on the cube within rounding).
    openvdb::Coord ijk;
    const Vec3 start = ray.at(tmin);
    for (int a = 0; a < 3; ++a) {
        const double c = std::floor((start[a] - f.origin[a]) / f.h);
        ijk[a] = int32_t(std::clamp(c, 0.0, double(f.n - 1)));
    }
    // Plane crossings by one multiplication (one rounding more than a division, well inside
    // the caller's slack); a reciprocal that overflows (subnormal direction) divides instead.
    double inv[3];
    bool divide[3];
    for (int a = 0; a < 3; ++a) {
        inv[a] = 1.0 / ray.dir[a];
        divide[a] = !std::isfinite(inv[a]);
    }
    // Where the ray leaves the block of `size` cells at `block` (its far planes), and across
    // which axis (−1: not before tmax).
    // Where the ray crosses the far plane of coordinate c (a block of `size` from c) on axis
    // a: +inf where it never does.
    auto planeExit = [&](int a, int32_t c, int32_t size) {
        const double d = ray.dir[a];
        double plane;
        if (d > 0.0)
            plane = f.origin[a] + double(c + size) * f.h;
        else if (d < 0.0)
            plane = f.origin[a] + double(c) * f.h;
        else
            return kInf;
        return divide[a] ? (plane - ray.origin[a]) / d : (plane - ray.origin[a]) * inv[a];
    };
    // Where the ray leaves the block of `size` cells at `block`, and across which axis (−1:
    // not before tmax).
    auto exitOf = [&](const openvdb::Coord& block, int32_t size, double t, int& axis) {
        double tExit = tmax;
        axis = -1;
        for (int a = 0; a < 3; ++a) {
            const double te = planeExit(a, block[a], size);
            if (te < tExit) tExit = te, axis = a;
        }
        return std::max(tExit, t);
    };
    // A walk crosses at most 3n cells; more steps can only come from rounding at corners.
    const int64_t limit = 3 * int64_t(f.n) + 16;
    int64_t step = 0;
    double t = tmin;
    while (step < limit) {
        int32_t value = kEmptyValue;
        int axis;
        if (acc.probeValue(ijk, value)) {
            // A brick the surface may cross: its cells one by one, from its own table, until
            // the ray leaves it. A step to a neighbouring cell changes one coordinate only.
            const BrickContent& b = mImpl->content(value);
            const openvdb::Coord brick(ijk[0] & ~7, ijk[1] & ~7, ijk[2] & ~7);
            // Each cell's exit planes, computed from the planes themselves; a step changes
            // one coordinate, so only that axis's exit is computed anew.
            double exits[3];
            for (int a = 0; a < 3; ++a) exits[a] = planeExit(a, ijk[a], 1);
            while (step++ < limit) {
                ++steps;
                const Node* node =
                    b.nodeAt(BrickContent::index(ijk[0] & 7, ijk[1] & 7, ijk[2] & 7));
                double tExit = tmax;
                axis = -1;
                for (int a = 0; a < 3; ++a)
                    if (exits[a] < tExit) tExit = exits[a], axis = a;
                tExit = std::max(tExit, t);
                if (!visit(context, {t, tExit, node})) return true;
                if (axis < 0) return true;  // tmax reached inside this cell
                t = tExit;
                ijk[axis] += ray.dir[axis] > 0.0 ? 1 : -1;
                if (ijk[axis] < 0 || ijk[axis] >= f.n) return true;  // left the cube
                if ((ijk[axis] & ~7) != brick[axis]) break;          // left the brick
                exits[axis] = planeExit(axis, ijk[axis], 1);
            }
            continue;
        }
        // A block without surface: skipped whole, as large as OpenVDB's tile or node is.
        ++step;
        ++steps;
        const int32_t size = regionSize(acc.getValueDepth(ijk));
        openvdb::Coord block;
        for (int a = 0; a < 3; ++a) block[a] = ijk[a] & ~(size - 1);
        const double tExit = exitOf(block, size, t, axis);
        if (!visit(context, {t, tExit, nullptr})) return true;
        if (axis < 0) return true;  // tmax reached inside this block
        const int32_t next = ray.dir[axis] > 0.0 ? block[axis] + size : block[axis] - 1;
        if (next < 0 || next >= f.n) return true;  // left the cube
        // The ray has moved across the block on the other axes too: found from the exit point.
        const Vec3 p = ray.at(tExit);
        for (int a = 0; a < 3; ++a) {
            if (a == axis) continue;
            const double c = std::floor((p[a] - f.origin[a]) / f.h);
            ijk[a] = int32_t(std::clamp(c, 0.0, double(f.n - 1)));
        }
        ijk[axis] = next;
        t = tExit;
    }
    return false;
}

}  // namespace kerf
