/// @file io/mesh_weld.h
/// @brief One vertex per written position: a mesher gives two vertices at one point where a
/// sharp feature is met from two sides (1,080 of 9,626 in models/gear.kerf at voxel 0.05), and
/// PLY and STL store floats, so doubles that differ can still be written equal. A reader then
/// sees two vertices at one place, and its edges do not pair.
#pragma once

#include <cstdint>
#include <vector>

namespace kerf {

struct MeshArrays;

/// A mesh with exactly-equal positions joined, as they will be written.
struct WeldedMesh {
    std::vector<double> xyz;
    std::vector<uint32_t> indices;
};

/// Joins vertices whose written positions are equal: the doubles themselves, or when
/// `asFloat` their float roundings (-0 and +0 are one). A triangle left with two equal
/// corners (zero area, its two other edges the same edge) is dropped. Vertices keep their
/// first-seen order, triangles their order.
WeldedMesh weldWrittenPositions(const MeshArrays& mesh, bool asFloat);

}  // namespace kerf
