// The octree's finest cells in an OpenVDB Int32 tree, and the ray walk over it. The walk uses
// OpenVDB's node hierarchy for its skips (a 128³ or 8³ node without boundary cells is crossed
// in one step) but computes every segment end from the block's own planes, so the segments a
// ray is given are exact up to one rounded division each.
#include "volume/cell_grid.h"

#include <openvdb/openvdb.h>
#include <openvdb/tree/ValueAccessor.h>

#include <algorithm>
#include <cmath>

namespace kerf {

namespace {

constexpr int32_t kEmptyValue = -1;  // the background: no solid here
constexpr int32_t kFullValue = -2;   // inactive, inside the solid

using Tree = openvdb::Int32Tree;
using Accessor = openvdb::tree::ValueAccessor<const Tree, /*IsSafe=*/false>;

/// Side, in cells, of the region a value found at OpenVDB tree depth `depth` stands for
/// (getValueDepth: −1 background, 0 root tile, 1 and 2 internal-node tiles, 3 a voxel).
int32_t regionSize(int depth) {
    switch (depth) {
        case 3: return 1;
        case 2: return Tree::LeafNodeType::DIM;                                  // 8
        case 1: return Tree::RootNodeType::ChildNodeType::ChildNodeType::DIM;  // 128
        default: return Tree::RootNodeType::ChildNodeType::DIM;                 // 4096
    }
}

}  // namespace

struct CellGrid::Impl {
    Tree tree{kEmptyValue};
};

CellGrid::CellGrid(const GridFrame& frame,
                   const std::vector<std::pair<CellCoord, int32_t>>& boundary,
                   const std::vector<std::pair<CellCoord, int32_t>>& fullBlocks)
    : mFrame(frame), mImpl(std::make_unique<Impl>()) {
    for (const auto& [c, size] : fullBlocks) {
        const openvdb::Coord lo(c[0], c[1], c[2]);
        mImpl->tree.fill(openvdb::CoordBBox(lo, lo.offsetBy(size - 1)), kFullValue, false);
    }
    openvdb::tree::ValueAccessor<Tree> acc(mImpl->tree);
    for (const auto& [c, index] : boundary) acc.setValueOn(openvdb::Coord(c[0], c[1], c[2]), index);
}

CellGrid::~CellGrid() = default;

uint64_t CellGrid::memoryBytes() const { return mImpl->tree.memUsage(); }

bool CellGrid::fullAt(const Vec3& p) const {
    openvdb::Coord ijk;
    for (int a = 0; a < 3; ++a) {
        const double c = std::floor((p[a] - mFrame.origin[a]) / mFrame.h);
        if (!(c >= 0.0 && c < double(mFrame.n))) return false;
        ijk[a] = int32_t(c);
    }
    return mImpl->tree.getValue(ijk) == kFullValue;
}

bool CellGrid::walk(const Ray& ray, double tmin, double tmax, SegmentVisitor visit,
                    void* context, uint64_t& steps) const {
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
    // A walk crosses at most 3n cells; more steps can only come from rounding at corners.
    const int64_t limit = 3 * int64_t(f.n) + 16;
    double t = tmin;
    for (int64_t step = 0; step < limit; ++step) {
        ++steps;
        int32_t value = kEmptyValue;
        const bool boundary = acc.probeValue(ijk, value);
        const int32_t size = boundary ? 1 : regionSize(acc.getValueDepth(ijk));
        openvdb::Coord block;
        for (int a = 0; a < 3; ++a) block[a] = ijk[a] & ~(size - 1);
        double tExit = tmax;
        int axis = -1;
        for (int a = 0; a < 3; ++a) {
            const double d = ray.dir[a];
            double plane;
            if (d > 0.0)
                plane = f.origin[a] + double(block[a] + size) * f.h;
            else if (d < 0.0)
                plane = f.origin[a] + double(block[a]) * f.h;
            else
                continue;
            const double te = (plane - ray.origin[a]) / d;
            if (te < tExit) tExit = te, axis = a;
        }
        tExit = std::max(tExit, t);
        if (!visit(context, {t, tExit, boundary ? value : kNoCell})) return true;
        if (axis < 0) return true;  // tmax reached inside this block
        const int32_t next = ray.dir[axis] > 0.0 ? block[axis] + size : block[axis] - 1;
        if (next < 0 || next >= f.n) return true;  // left the cube
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
