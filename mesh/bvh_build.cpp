// The triangle BVH's build: binned SAH (Wald 2007) over triangle centroids, recursing into the
// two halves as TBB tasks near the root, then flattened depth first into 32-byte nodes. The
// tree depends only on the mesh, never on the thread count: every split is decided from the
// range's own triangles and tasks write disjoint ranges.
#include "mesh/triangle_bvh.h"

#include "csg/bvh/bvh_nesting.h"
#include "csg/check.h"
#include "mesh/bvh4.h"
#include "mesh/bvh_split.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace kerf {

namespace {

// Past this depth the build splits at the median (which halves), so no walk outgrows the
// stack: SAH depth + log2(2^32) ≤ TriangleBvh::kMaxDepth.
constexpr int kSahDepthLimit = 28;
constexpr int kMaxBins = 64;

struct BuildNode {
    Bounds3 box;
    std::unique_ptr<BuildNode> child[2];
    int axis = 0;
    uint32_t begin = 0, count = 0;  // leaf range of the references (count 0: inner)
};

double halfArea(const Bounds3& b) {
    if (b.empty()) return 0.0;
    const Vec3 e = b.extent();
    return e.x * e.y + e.y * e.z + e.z * e.x;
}

float roundDown(double x) {
    float f = static_cast<float>(x);
    return double(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}
float roundUp(double x) {
    float f = static_cast<float>(x);
    return double(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

}  // namespace

// A reference as the build sorts it: its data moves with it, so the binning passes read
// memory in order (an index array into separate boxes would be read at random).
struct BuildRef {
    Bounds3 box;
    Vec3 centroid;
    uint32_t id;  ///< index into the references
};

struct BvhBuilder {
    const BvhBuildOptions& options;
    std::vector<BuildRef> refs;

    std::unique_ptr<BuildNode> build(uint32_t begin, uint32_t end, int depth, size_t& nodes);
    void flatten(const BuildNode& n, std::vector<TriangleBvh::Node>& out);
    bool sahSplit(uint32_t begin, uint32_t end, const Bounds3& box, const Bounds3& cbox,
                  uint32_t& mid, int& axis);
};

// Chooses the cheapest binned SAH split of [begin, end) and partitions the range there.
// False when a leaf is at least as cheap (and allowed) or no bin boundary separates anything.
bool BvhBuilder::sahSplit(uint32_t begin, uint32_t end, const Bounds3& box, const Bounds3& cbox,
                          uint32_t& mid, int& axis) {
    const uint32_t n = end - begin;
    const int bins = std::clamp(options.bins, 2, kMaxBins);
    // Costs are kept multiplied by the parent's half area, so a flat or point box (area 0)
    // still compares.
    const double parentArea = halfArea(box);
    double bestCost = n <= uint32_t(options.maxLeafSize) ? n * parentArea : kInf;
    int bestAxis = -1, bestBin = 0;
    // One pass bins the references along all three axes.
    Bounds3 bins3[3][kMaxBins];
    uint32_t counts3[3][kMaxBins] = {};
    double lo3[3], scale3[3];
    bool active[3];
    for (int a = 0; a < 3; ++a) {
        lo3[a] = cbox.lo[a];
        const double extent = cbox.hi[a] - cbox.lo[a];
        active[a] = extent > 0.0;
        scale3[a] = active[a] ? bins / extent : 0.0;
    }
    for (uint32_t i = begin; i < end; ++i) {
        const BuildRef& r = refs[i];
        for (int a = 0; a < 3; ++a) {
            if (!active[a]) continue;
            const int b = std::min(bins - 1, int((r.centroid[a] - lo3[a]) * scale3[a]));
            bins3[a][b].extend(r.box);
            ++counts3[a][b];
        }
    }
    for (int a = 0; a < 3; ++a) {
        if (!active[a]) continue;
        const Bounds3* binBox = bins3[a];
        const uint32_t* binCount = counts3[a];
        // Right-to-left sweep of the areas and counts right of each boundary.
        double rightArea[kMaxBins];
        Bounds3 acc;
        uint32_t accCount = 0, rightCount[kMaxBins];
        for (int b = bins - 1; b > 0; --b) {
            acc.extend(binBox[b]);
            accCount += binCount[b];
            rightArea[b] = halfArea(acc);
            rightCount[b] = accCount;
        }
        acc = Bounds3();
        accCount = 0;
        for (int b = 1; b < bins; ++b) {  // boundary b: bins [0, b) left, [b, bins) right
            acc.extend(binBox[b - 1]);
            accCount += binCount[b - 1];
            if (accCount == 0 || rightCount[b] == 0) continue;
            const double cost = options.traversalCost * parentArea + halfArea(acc) * accCount +
                                rightArea[b] * rightCount[b];
            if (cost < bestCost) {
                bestCost = cost;
                bestAxis = a;
                bestBin = b;
            }
        }
    }
    if (bestAxis < 0) return false;
    const double lo = cbox.lo[bestAxis];
    const double scale = bins / (cbox.hi[bestAxis] - lo);
    const auto it =
        std::partition(refs.begin() + begin, refs.begin() + end, [&](const BuildRef& r) {
            return std::min(bins - 1, int((r.centroid[bestAxis] - lo) * scale)) < bestBin;
        });
    mid = uint32_t(it - refs.begin());
    axis = bestAxis;
    return true;
}

std::unique_ptr<BuildNode> BvhBuilder::build(uint32_t begin, uint32_t end, int depth,
                                             size_t& nodes) {
    auto node = std::make_unique<BuildNode>();
    Bounds3 cbox;
    for (uint32_t i = begin; i < end; ++i) {
        node->box.extend(refs[i].box);
        cbox.extend(refs[i].centroid);
    }
    ++nodes;
    const uint32_t n = end - begin;
    uint32_t mid = begin;
    int axis = 0;
    bool split = false;
    if (n > 1) {
        if (depth < kSahDepthLimit) split = sahSplit(begin, end, node->box, cbox, mid, axis);
        if (!split && n > uint32_t(options.maxLeafSize)) {
            // Too many for a leaf and no SAH split (coincident centroids, or too deep): halve
            // at the median centroid along the widest axis (by index among equal centroids).
            const Vec3 e = cbox.extent();
            axis = e.x >= e.y ? (e.x >= e.z ? 0 : 2) : (e.y >= e.z ? 1 : 2);
            mid = begin + n / 2;
            std::nth_element(refs.begin() + begin, refs.begin() + mid, refs.begin() + end,
                             [&](const BuildRef& a, const BuildRef& b) {
                                 const double ca = a.centroid[axis], cb = b.centroid[axis];
                                 return ca < cb || (ca == cb && a.id < b.id);
                             });
            split = true;
        }
    }
    if (!split) {
        node->begin = begin;
        node->count = n;
        return node;
    }
    node->axis = axis;
    if (n > uint32_t(std::max(options.parallelAbove, 2))) {
        size_t leftNodes = 0, rightNodes = 0;
        tbb::parallel_invoke([&] { node->child[0] = build(begin, mid, depth + 1, leftNodes); },
                             [&] { node->child[1] = build(mid, end, depth + 1, rightNodes); });
        nodes += leftNodes + rightNodes;
    } else {
        node->child[0] = build(begin, mid, depth + 1, nodes);
        node->child[1] = build(mid, end, depth + 1, nodes);
    }
    return node;
}

void BvhBuilder::flatten(const BuildNode& n, std::vector<TriangleBvh::Node>& out) {
    const size_t self = out.size();
    out.emplace_back();
    TriangleBvh::Node& f = out[self];
    for (int a = 0; a < 3; ++a) {
        f.lo[a] = roundDown(n.box.lo[a]);
        f.hi[a] = roundUp(n.box.hi[a]);
    }
    if (!n.child[0]) {
        f.index = n.begin;
        f.count = uint16_t(n.count);
        f.axis = 0;
        return;
    }
    out[self].count = 0;
    out[self].axis = uint16_t(n.axis);
    flatten(*n.child[0], out);
    out[self].index = uint32_t(out.size());
    flatten(*n.child[1], out);
}

TriangleBvh::TriangleBvh(const TriangleMesh& mesh, const BvhBuildOptions& options) {
    const size_t count = mesh.triangles.size();
    mTriangleCount = count;
    mSimd = options.simd;
    if (count == 0) return;
    BvhBuildOptions opts = options;
    opts.maxLeafSize = std::clamp(opts.maxLeafSize, 1, 255);
    // The build sorts references: one per triangle, several for thin ones (bvh_split.h).
    const std::vector<TriangleRef> refs =
        triangleReferences(mesh, std::clamp(opts.splitDepth, 0, 16), opts.splitRatio);
    const size_t refCount = refs.size();
    BvhBuilder builder{opts, {}};
    builder.refs.resize(refCount);
    for (size_t i = 0; i < refCount; ++i)  // the box's centre bins as well as the centroid
        builder.refs[i] = {refs[i].box, refs[i].box.center(), uint32_t(i)};
    size_t nodes = 0;
    const auto root = builder.build(0, uint32_t(refCount), 0, nodes);
    mBounds = root->box;
    mNodes.reserve(nodes);
    builder.flatten(*root, mNodes);
    KERF_DCHECK(childBoxesNest(mNodes, [](const Node& n) { return n.index; }));
    mTris.resize(refCount);
    mTriangleIndex.resize(refCount);
    for (size_t k = 0; k < refCount; ++k) {
        mTriangleIndex[k] = refs[builder.refs[k].id].triangle;
        const auto& t = mesh.triangles[mTriangleIndex[k]];
        for (int j = 0; j < 3; ++j)
            for (int a = 0; a < 3; ++a) mTris[k].p[j][a] = mesh.positions[t[j]][a];
    }
    mWide = bvh4::collapse(mNodes);
    mPacks = bvh4::packLeaves(mWide, mTris.data(), mTriangleIndex.data());
}

}  // namespace kerf
