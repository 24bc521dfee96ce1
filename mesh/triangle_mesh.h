/// @file mesh/triangle_mesh.h
/// @brief An indexed triangle mesh as kerf keeps it: shared vertices, one index triple per
/// triangle (counter-clockwise seen from outside for a solid), optional per-vertex normals and
/// UVs. Loading (Assimp), validation (half-edges) and the BVH all work on this one type.
#pragma once

#include "csg/types.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace kerf {

struct TriangleMesh {
    std::vector<Vec3> positions;
    std::vector<std::array<uint32_t, 3>> triangles;
    std::vector<Vec3> normals;               ///< per vertex, or empty
    std::vector<std::array<double, 2>> uvs;  ///< per vertex, or empty
    std::string source;                      ///< the file it came from, for messages
};

/// The box around every vertex a triangle uses (empty for a mesh without triangles).
Bounds3 meshBounds(const TriangleMesh& mesh);

}  // namespace kerf
