/// @file volume/export/mesh_measure.h
/// @brief How far a mesh is from the solid it was made from (`kerf mesh --stats`, tests).
#pragma once

#include "volume/export/mesh_field.h"

#include <array>
#include <vector>

namespace kerf {

/// The one-sided Hausdorff distance from the mesh to the implicit surface, estimated at the
/// vertices, the edge midpoints and the triangle centroids. A point's distance is the
/// distance to the crossing found along its gradient within two voxels (a surface point that
/// near exists, so it is an upper bound of the true distance); where no crossing is bracketed
/// it is the first-order estimate |f|/|∇f| (counted in `firstOrder`).
struct SurfaceDistance {
    double hausdorff = 0.0;
    double mean = 0.0;  ///< over all sample points
    uint64_t samples = 0;
    uint64_t firstOrder = 0;
};
SurfaceDistance measureSurfaceDistance(const SampledField& field, const std::vector<Vec3>& vertices,
                                       const std::vector<std::array<uint32_t, 3>>& triangles);

/// The volume a closed, consistently wound (counter-clockwise from outside) mesh encloses:
/// Σ det(v0, v1, v2) / 6, summed in triangle order.
double enclosedVolume(const std::vector<Vec3>& vertices,
                      const std::vector<std::array<uint32_t, 3>>& triangles);

/// Bounds on the solid's own volume from interval classification: full regions and full
/// cells (half a voxel wide near the surface) below, plus the cells the surface may cross
/// above.
struct VolumeBounds {
    double lo = 0.0;
    double hi = 0.0;
};
VolumeBounds modelVolumeBounds(const SampledField& field);

}  // namespace kerf
