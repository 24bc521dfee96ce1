/// @file mesh/bvh4.h
/// @brief The triangle BVH's ray walks over 4-wide nodes: the binary tree collapsed so each
/// node holds up to four children's boxes side by side (float, rounded outward like the binary
/// nodes), leaves' triangles packed four at a time, and the walk, written once as a template
/// on a lane policy (box test and pack test) so the scalar and the AVX2 paths
/// (mesh/bvh4_avx2.cpp) run the same code around them.
///
/// Both box tests compute, lane for lane, the same IEEE operations as
/// Bounds3::clipRayConservative (csg/types.h), so they cull the same boxes and give the same
/// entry distances; both pack tests give intersectWatertight's decisions. So the walks visit
/// the same nodes, test the same triangles in the same order and give the same bits whichever
/// runs (tests/mesh/bvh4_test.cpp).
#pragma once

#include "mesh/bvh4_node.h"
#include "mesh/triangle_bvh.h"
#include "mesh/watertight_triangle.h"

#include <cstdint>
#include <limits>
#include <vector>

#define KERF_BVH_INLINE __attribute__((always_inline)) inline

namespace kerf::bvh4 {

/// Collapses the binary tree (TriangleBvh::Node, depth-first with the first child next) into
/// wide nodes, root first: each wide node takes the binary node's children and opens its
/// largest-area inner children until it has four. Leaves keep their triangle ranges.
std::vector<WideNode> collapse(const std::vector<TriangleBvh::Node>& binary);

/// Packs each wide leaf's triangles (the slots [index, index + count) of tris, whose mesh
/// indices are triangleIndex) into TriPacks and points the leaf lanes at their first pack.
std::vector<TriPack> packLeaves(std::vector<WideNode>& nodes, const TriangleBvh::Tri* tris,
                                const uint32_t* triangleIndex);

/// What the walks need of a BVH, without its private parts.
struct View {
    const WideNode* nodes;
    const TriangleBvh::Node* root;  ///< the binary root: its box is tested first
    const TriPack* packs;
};

/// A walk-stack entry: a leaf's first pack and triangle count (count > 0) or a wide node
/// (count 0), and the entry distance of its box.
struct Entry {
    uint32_t index, count;
    double tEnter;
};
/// Three siblings wait per level at most (a wide node's nearest child is entered at once).
constexpr int kStackSize = 3 * TriangleBvh::kMaxDepth + 4;

/// What a lane policy's pack test reports: lanes it decided are crossed somewhere on the line
/// (hit; the caller still checks t against the range), lanes it could not decide (exact: the
/// caller runs intersectWatertight), and the rest, which miss. For a hit lane, t and the
/// weights' numerators and denominator are those intersectWatertight computes, bit for bit.
struct PackResult {
    unsigned hit = 0, exact = 0;
    double t[4], det[4], v[4], w[4];
};

/// The scalar lanes: Bounds3::clipRayConservative on each box, and every triangle left to the
/// reference watertight test (this is the reference the AVX2 lanes must equal).
struct ScalarLanes {
    const RayReciprocal& rec;
    ScalarLanes(const RayReciprocal& r, const ShearedRay&) : rec(r) {}
    /// Bit k of the result: lane k's box meets the ray within [tmin, tmax], entered at t[k].
    KERF_BVH_INLINE unsigned test(const WideNode& n, double tmin, double tmax, double t[4]) const {
        unsigned mask = 0;
        for (int k = 0; k < n.lanes; ++k) {
            const float lo[3] = {n.lo[0][k], n.lo[1][k], n.lo[2][k]};
            const float hi[3] = {n.hi[0][k], n.hi[1][k], n.hi[2][k]};
            double t0 = tmin, t1 = tmax;
            if (Bounds3::clipRayConservative(rec, lo, hi, t0, t1)) {
                mask |= 1u << k;
                t[k] = t0;
            }
        }
        return mask;
    }
    KERF_BVH_INLINE void packTest(const TriPack&, unsigned lanes, PackResult& r) const {
        r.hit = 0;
        r.exact = lanes;
    }
};

/// Walks the wide tree calling leaf(firstPack, count, tmax) for each leaf whose box the ray may
/// meet within [tmin, tmax]; leaf returns the tmax to go on with, or a value below tmin to stop.
/// Children are entered nearest first (shadow rays too: measured no slower than lane order,
/// with fewer boxes and triangles tested); the others wait with their entry distances and are
/// skipped once the range has shrunk past them. Entries are conservative, so no box holding a
/// hit is skipped. BvhStats::nodesVisited counts the boxes tested (the root's and each tested
/// node's children).
template <class Lanes, class Leaf>
KERF_BVH_INLINE void walk(const View& v, const Lanes& boxes, const RayReciprocal& rec, double tmin,
                          double tmax, BvhStats& stats, Leaf&& leaf) {
    if (!(tmin < tmax)) return;
    ++stats.nodesVisited;
    double rootEnter = tmin;
    {
        double t1 = tmax;
        if (!Bounds3::clipRayConservative(rec, v.root->lo, v.root->hi, rootEnter, t1)) return;
    }
    Entry stack[kStackSize];
    int top = 0;
    Entry cur{0, 0, rootEnter};
    for (;;) {
        if (cur.count > 0) {
            tmax = leaf(cur.index, cur.count, tmax);
            if (!(tmin < tmax)) return;
        } else {
            const WideNode& n = v.nodes[cur.index];
            double t[4];
            unsigned mask = boxes.test(n, tmin, tmax, t);
            stats.nodesVisited += n.lanes;
            if (mask) {
                if ((mask & (mask - 1)) == 0) {  // one child: no order to decide
                    const int k = __builtin_ctz(mask);
                    cur = {n.index[k], n.count[k], t[k]};
                } else if (__builtin_popcount(mask) == 2) {  // the common pair: one compare
                    const int k0 = __builtin_ctz(mask), k1 = __builtin_ctz(mask & (mask - 1));
                    const bool firstNear = t[k0] <= t[k1];
                    const int near = firstNear ? k0 : k1, far = firstNear ? k1 : k0;
                    stack[top++] = {n.index[far], n.count[far], t[far]};
                    cur = {n.index[near], n.count[near], t[near]};
                } else {
                    // Sort the hit lanes by entry (insertion sort of at most four), push all
                    // but the nearest, farthest first, and go on with the nearest.
                    Entry hit[4];
                    int h = 0;
                    while (mask) {
                        const int k = __builtin_ctz(mask);
                        mask &= mask - 1;
                        Entry e{n.index[k], n.count[k], t[k]};
                        int j = h++;
                        while (j > 0 && hit[j - 1].tEnter > e.tEnter) {
                            hit[j] = hit[j - 1];
                            --j;
                        }
                        hit[j] = e;
                    }
                    for (int j = h - 1; j > 0; --j) stack[top++] = hit[j];
                    cur = hit[0];
                }
                // The nearest child is read next: start loading it (a wide node is two
                // cache lines, a pack five).
                const char* next = cur.count > 0
                                       ? reinterpret_cast<const char*>(&v.packs[cur.index])
                                       : reinterpret_cast<const char*>(&v.nodes[cur.index]);
                __builtin_prefetch(next);
                __builtin_prefetch(next + 64);
                if (cur.count > 0) {
                    __builtin_prefetch(next + 128);
                    __builtin_prefetch(next + 192);
                    __builtin_prefetch(next + 256);
                }
                continue;
            }
        }
        // Pop the next waiting child the shrunken range still reaches.
        for (;;) {
            if (top == 0) return;
            cur = stack[--top];
            if (cur.tEnter <= tmax) break;
        }
    }
}

}  // namespace kerf::bvh4
