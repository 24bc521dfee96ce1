/// @file volume/export/mesh_unpinch.h
/// @brief Edges of more than two faces undone where crease placement made them. Several of
/// OpenVDB's vertices may go to one crease point (mesh_placement.h): their polygons then have
/// no area. Where the vertices came from two sheets of surface, the mesh, once its equal
/// positions are joined (as every reader of the file does), has an edge of four faces. Those
/// vertices are placed again by projection along the gradient from where OpenVDB put them,
/// which gives each its own point on the surface.
#pragma once

#include "volume/export/mesh_field.h"

#include <array>
#include <cstdint>
#include <vector>

namespace kerf {

struct UnpinchResult {
    uint64_t replaced = 0;     ///< vertices placed again
    uint64_t crowdedLeft = 0;  ///< edges of more than two faces after the last round
};

/// Rounds of re-placement, each over the vertices of the edges still shared by more than two
/// faces. `lattice` are OpenVDB's positions (lattice index space), `points` the placed ones
/// (model space).
UnpinchResult unpinchCreases(const SampledField& field, const std::vector<Vec3>& lattice,
                             std::vector<Vec3>& points,
                             const std::vector<std::array<uint32_t, 3>>& triangles);

/// The number of edges shared by more than two faces once equal positions are joined
/// (triangles left with two equal corners do not count, as the writers drop them).
uint64_t crowdedEdges(const std::vector<Vec3>& points,
                      const std::vector<std::array<uint32_t, 3>>& triangles);

}  // namespace kerf
