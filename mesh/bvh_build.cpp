// The triangle BVH's build: the shared builder (csg/bvh/bvh_builder.h) over the triangles'
// references with the triangle rule (binned SAH on box centres, the top levels as TBB tasks),
// its nodes converted to 32-byte nodes with float boxes rounded outward. The tree depends only
// on the mesh, never on the thread count: every split is decided from the range's own
// references.
#include "mesh/triangle_bvh.h"

#include "csg/bvh/bvh_builder.h"
#include "csg/bvh/bvh_nesting.h"
#include "csg/check.h"
#include "mesh/bvh4.h"
#include "mesh/bvh_split.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace kerf {

namespace {

// Past this depth the build splits at the median (which halves), so no walk outgrows the
// stack: SAH depth + log2(2^32) ≤ TriangleBvh::kMaxDepth.
constexpr int kSahDepthLimit = 28;

float roundDown(double x) {
    float f = static_cast<float>(x);
    return double(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}
float roundUp(double x) {
    float f = static_cast<float>(x);
    return double(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

// The triangle rule: SAH with costs in triangle tests (a flat node still compares), a median
// split past kSahDepthLimit or where SAH finds nothing, the top of the tree in TBB tasks.
BvhBuildRule triangleRule(const BvhBuildOptions& opts) {
    BvhBuildRule rule;
    rule.split = BvhBuildRule::Split::Sah;
    rule.cost = BvhBuildRule::SahCost::AreaScaled;
    rule.bins = opts.bins;
    rule.maxLeafSize = opts.maxLeafSize;
    rule.sahDepthLimit = kSahDepthLimit;
    rule.nodeCost = opts.traversalCost;
    rule.parallelAbove = uint32_t(std::max(opts.parallelAbove, 2));
    rule.parallelInvoke = [](const std::function<void()>& a, const std::function<void()>& b) {
        tbb::parallel_invoke(a, b);
    };
    return rule;
}

}  // namespace

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
    std::vector<BvhBuildItem> items(refCount);
    for (size_t i = 0; i < refCount; ++i)  // the box's centre bins as well as the centroid
        items[i] = {refs[i].box, refs[i].box.center(), uint32_t(i)};
    const BinaryBvh tree = buildBinaryBvh(std::move(items), triangleRule(opts));
    mBounds = tree.nodes[0].box;
    mNodes.resize(tree.nodes.size());
    for (size_t k = 0; k < tree.nodes.size(); ++k) {
        const BinaryBvhNode& from = tree.nodes[k];
        Node& to = mNodes[k];
        for (int a = 0; a < 3; ++a) {
            to.lo[a] = roundDown(from.box.lo[a]);
            to.hi[a] = roundUp(from.box.hi[a]);
        }
        to.index = from.first;
        to.count = uint16_t(from.count);  // at most maxLeafSize ≤ 255
        to.axis = uint16_t(from.axis);
    }
    KERF_DCHECK(childBoxesNest(mNodes, [](const Node& n) { return n.index; }));
    mTris.resize(refCount);
    mTriangleIndex.resize(refCount);
    for (size_t k = 0; k < refCount; ++k) {
        mTriangleIndex[k] = refs[tree.order[k]].triangle;
        const auto& t = mesh.triangles[mTriangleIndex[k]];
        for (int j = 0; j < 3; ++j)
            for (int a = 0; a < 3; ++a) mTris[k].p[j][a] = mesh.positions[t[j]][a];
    }
    mWide = bvh4::collapse(mNodes);
    mPacks = bvh4::packLeaves(mWide, mTris.data(), mTriangleIndex.data());
}

}  // namespace kerf
