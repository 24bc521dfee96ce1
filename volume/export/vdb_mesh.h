/// @file volume/export/vdb_mesh.h
/// @brief The sampled field to polygons by OpenVDB's volume-to-mesh (the only OpenVDB use of
/// `kerf mesh`, in volume/export/vdb_mesh.cpp).
#pragma once

#include "volume/export/mesh_field.h"

#include <array>
#include <vector>

namespace kerf {

/// Polygons in lattice index space (point i of the lattice at index i), counter-clockwise seen
/// from outside; every edge of a closed surface is shared by two polygons, in opposite order.
/// Quads are split later, once their vertices are on the surface (volume/export/mesh_placement.h).
struct LatticePolygons {
    std::vector<Vec3> points;
    std::vector<std::array<uint32_t, 3>> triangles;
    std::vector<std::array<uint32_t, 4>> quads;
    uint64_t leaves = 0;  ///< OpenVDB leaves made (boundary blocks and the ring round them)
};

/// The isosurface at 0 of the field (negative inside), at OpenVDB's `adaptivity` in [0, 1].
LatticePolygons polygonizeField(const SampledField& field, double adaptivity);

}  // namespace kerf
