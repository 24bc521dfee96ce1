/// @file mesh/bvh4_node.h
/// @brief The triangle BVH's 4-wide node and its leaves' triangles packed four at a time
/// (the walks over them are in mesh/bvh4.h).
#pragma once

#include <cstdint>

namespace kerf::bvh4 {

/// A lane's box is empty (lo = +inf > hi = −inf) when the node has fewer than four children:
/// every slab test then fails, in both paths, without a branch.
struct alignas(64) WideNode {
    float lo[3][4], hi[3][4];  ///< [axis][lane]
    uint32_t index[4];         ///< leaf lane: first triangle slot; inner lane: the wide node
    uint16_t count[4];         ///< leaf lane: triangles (> 0); inner lane or empty: 0
    uint8_t lanes;             ///< children in use (lanes 0 .. lanes − 1)
    uint8_t pad[7];
};
static_assert(sizeof(WideNode) == 128, "two cache lines");

/// Up to four of a leaf's triangles, coordinates side by side so four watertight tests run on
/// AVX2 lanes. A leaf of n triangles takes ceil(n / 4) consecutive packs; unused lanes repeat
/// lane 0 (and are never tested).
struct alignas(32) TriPack {
    double p[3][3][4];     ///< [vertex][axis][lane]
    uint32_t triangle[4];  ///< the mesh's index of each lane's triangle
    uint32_t pad[4];
};
static_assert(sizeof(TriPack) == 320, "five cache lines");

}  // namespace kerf::bvh4
