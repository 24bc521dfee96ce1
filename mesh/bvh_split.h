/// @file mesh/bvh_split.h
/// @brief Pre-splitting of long thin triangles' references for the BVH build (early split
/// clipping, Ernst & Greiner 2007): a triangle whose box is much larger than the triangle is
/// referenced several times, each reference with the box of the part of the triangle in one
/// half of the box, so rays that pass near it meet fewer of its boxes.
#pragma once

#include "mesh/triangle_mesh.h"

#include <cstdint>
#include <vector>

namespace kerf {

struct TriangleRef {
    Bounds3 box;        ///< holds the part of the triangle this reference stands for
    uint32_t triangle;  ///< the mesh's index
};

/// One reference per triangle with its box, plus the pieces of thin ones: a piece is halved
/// along its box's longest axis while its box's half area exceeds ratio × its part's area
/// and it is fewer than maxDepth halvings deep. Each piece's box is the box of the triangle
/// clipped to the half, widened past the clipping's rounding, and never leaves the half; the
/// union of a triangle's pieces' boxes holds the whole triangle. Deterministic; references of
/// one triangle are consecutive, in triangle order.
std::vector<TriangleRef> triangleReferences(const TriangleMesh& mesh, int maxDepth, double ratio);

}  // namespace kerf
