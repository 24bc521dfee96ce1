/// @file mesh/triangle_bvh.h
/// @brief A bounding volume hierarchy over a TriangleMesh's triangles: binned SAH build
/// (parallel with TBB near the root), flat 32-byte nodes with float boxes rounded outward,
/// triangles copied in leaf order for locality, and three walks with the watertight test:
/// closest hit, any hit (shadow rays) and every crossing (for CSG spans).
///
/// Split: the build is in bvh_build.cpp; the ray walks run over the binary tree collapsed into
/// 4-wide nodes (bvh4.h, bvh4_collapse.cpp, bvh4_queries.h, with the AVX2 box test in
/// bvh4_avx2.cpp) and are dispatched in triangle_bvh.cpp; the ray–triangle test is in
/// watertight_triangle.h.
#pragma once

#include "mesh/bvh4_node.h"
#include "mesh/triangle_mesh.h"

#include <cstdint>
#include <vector>

namespace kerf {

/// Work counters of the walks; the caller owns one (per thread) and reads it when it likes.
struct BvhStats {
    /// Nodes whose box was tested (the ray walks: the root and every child of each wide node
    /// entered; nearestTriangle: binary nodes).
    uint64_t nodesVisited = 0;
    /// Ray–triangle tests (a triangle split over several leaves may be tested more than once).
    uint64_t trianglesTested = 0;
};

/// The nearest crossing: t, the mesh's triangle index, and the weights of its vertices 1 and
/// 2 (vertex 0 has 1 − u − v).
struct TriangleHit {
    double t = kInf;
    uint32_t triangle = 0;
    double u = 0.0, v = 0.0;
};

/// One crossing of the all-crossings walk.
struct TriangleCrossing {
    double t;
    uint32_t triangle;
    bool entering;  ///< dot(dir, geometric normal) < 0, the normal (p1 − p0) × (p2 − p0)
    bool operator==(const TriangleCrossing& o) const {
        return t == o.t && triangle == o.triangle && entering == o.entering;
    }
};

/// Build settings; the defaults are what kerf uses.
struct BvhBuildOptions {
    int bins = 32;              ///< SAH bins over the centroids' extent along each axis
    int maxLeafSize = 8;        ///< a leaf never holds more triangles than this
    int parallelAbove = 16384;  ///< subtrees with more triangles are built as TBB tasks
    /// SAH cost of a walk step, in triangle tests: 3, as four triangles are tested at once
    /// (sphere +8% primary rays, city unchanged; bench/bvh_bench.cpp --traversal-cost).
    double traversalCost = 3.0;
    /// Thin triangles are referenced from several leaves with tighter boxes: a reference is
    /// halved while its box's half area exceeds splitRatio × its part's area, at most
    /// splitDepth times (bvh_split.h). 0 turns it off.
    int splitDepth = 3;
    double splitRatio = 16.0;
    /// Ray walks test a wide node's four boxes on AVX2 lanes when the CPU has AVX2 (and
    /// KERF_SIMD is not "scalar"); false forces the scalar test. Same answers and counters.
    bool simd = true;
};

class TriangleBvh {
public:
    TriangleBvh() = default;
    /// Builds over mesh's triangles (positions copied; the mesh need not outlive the BVH).
    /// Any input builds: no triangles, repeated or zero-area triangles. Positions must be
    /// finite (loading rejects NaN and infinities before) and fewer than 2^32 triangles. The
    /// tree does not depend on the thread count.
    explicit TriangleBvh(const TriangleMesh& mesh, const BvhBuildOptions& options = {});

    /// The nearest crossing with t in (tmin, tmax), or false. Ties at equal t go to whichever
    /// triangle the walk meets first. A ray with a zero direction meets nothing.
    bool closestHit(const Ray& ray, double tmin, double tmax, TriangleHit& hit,
                    BvhStats& stats) const;
    /// Whether any triangle crosses the ray with t in (tmin, tmax) (stops at the first).
    bool anyHit(const Ray& ray, double tmin, double tmax, BvhStats& stats) const;
    /// Every crossing with t in (tmin, tmax), sorted by t then triangle index (appended to
    /// out, which is cleared first), each triangle once even where it is split over several
    /// leaves. A ray through an edge or vertex crosses every triangle that shares it, so it may
    /// report one surface crossing more than once at the same t.
    void allCrossings(const Ray& ray, double tmin, double tmax, std::vector<TriangleCrossing>& out,
                      BvhStats& stats) const;

    /// The point of the triangles nearest to p, if one lies within maxDistance: its distance
    /// and its triangle (ties go to the first the walk meets). The walk visits nodes nearest
    /// first and skips those farther than the best so far (mesh/triangle_bvh_nearest.cpp).
    bool nearestTriangle(const Vec3& p, double maxDistance, double& distance, uint32_t& triangle,
                         BvhStats& stats) const;

    size_t triangleCount() const { return mTriangleCount; }
    size_t nodeCount() const { return mNodes.size(); }
    Bounds3 bounds() const { return mBounds; }
    /// Tree depth (a single leaf has depth 1; 0 without triangles), for tests.
    int depth() const;

    struct Node {
        float lo[3], hi[3];  ///< rounded outward from the double boxes: never smaller
        uint32_t index;      ///< leaf: first triangle slot; inner: the second child
        uint16_t count;      ///< leaf: triangles (> 0); inner: 0 (the first child follows)
        uint16_t axis;       ///< inner: the split axis, for the near-first order
    };
    static_assert(sizeof(Node) == 32, "two nodes per cache line");
    /// Deepest walk the fixed stack allows; the build splits at the median below this depth.
    static constexpr int kMaxDepth = 60;
    struct Tri {
        double p[3][3];
    };  ///< vertices as plain arrays (see watertight_triangle.h)

private:
    std::vector<Node> mNodes;
    /// Triangle vertices in leaf order; a split triangle has a slot in each of its leaves.
    std::vector<Tri> mTris;
    std::vector<uint32_t> mTriangleIndex;  ///< the mesh's index of each slot of mTris
    size_t mTriangleCount = 0;
    Bounds3 mBounds;
    std::vector<bvh4::WideNode> mWide;  ///< mNodes collapsed 4-wide: the ray walks' tree
    std::vector<bvh4::TriPack> mPacks;  ///< mTris again, four side by side per wide leaf
    bool mSimd = true;
};

}  // namespace kerf
