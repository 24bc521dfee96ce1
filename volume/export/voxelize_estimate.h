/// @file volume/export/voxelize_estimate.h
/// @brief How many voxels a narrow band round a solid's surface will hold, estimated from its
/// surface area before anything is allocated (`kerf voxelize --max-voxels`).
#pragma once

#include "csg/tape/tape.h"
#include "csg/types.h"

#include <cstdint>
#include <memory>

namespace kerf {

struct BandEstimate {
    double area = 0.0;    ///< estimated surface area, in voxel faces (area / H²)
    double voxels = 0.0;  ///< estimated active voxels: area · 2 · band
    uint64_t cells = 0;   ///< interval evaluations spent
};

/// Regions of kEstimateRegion³ voxels over `bounds` classified coarse to fine by interval
/// arithmetic on `tape` (simplified per region); the n regions left that the surface may cross
/// estimate its area as n · kEstimateRegion² / 1.5 voxel faces (a plane crosses on average 1.5
/// cubes of a lattice per cube face of its area, over all directions). An overestimate where
/// interval arithmetic cannot tell a region near the surface from one it crosses; an
/// underestimate where many sheets cross one region. Stops early (coarser regions, a larger
/// estimate) once a level holds more than 2^21 regions.
BandEstimate estimateBand(std::shared_ptr<const Tape> tape, const Bounds3& bounds, double voxel,
                          double band);

/// Voxels per side of the regions estimateBand() counts.
constexpr int kEstimateRegion = 16;

}  // namespace kerf
