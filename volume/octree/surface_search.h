/// @file volume/octree/surface_search.h
/// @brief Finding the solid's surface near a point of a mesh, shared by vertex placement and
/// the mesh's error measurement: the tape that holds near a lattice point, and root finding
/// along the gradient or along a segment (bracketed, so a reported root is a real crossing).
#pragma once

#include "volume/export/mesh_field.h"

namespace kerf {

/// The tape of the boundary block whose widened box holds the lattice cells within two
/// voxels of the cell at `index` (lattice index space); the whole solid's tape when no
/// boundary block is that near.
const Tape& tapeNear(const SampledField& field, const Vec3& index);

/// Where the segment from + t·dir (t in [ta, tb]) crosses the surface, given f(ta) = fa and
/// f(tb) = fb on opposite sides (inside is f ≤ 0): Illinois false position until the bracket
/// is narrower than `tolerance` (in t). Returns the end of the final bracket with the
/// smaller |f|.
double refineCrossing(const Tape& tape, const Vec3& from, const Vec3& dir, double ta, double fa,
                      double tb, double fb, double tolerance);

/// The nearest crossing of the surface from `p` along ±∇f within `reach`: searches the
/// direction in which f moves toward 0, first at the Newton step, then at reach/4, /2, /1.
/// On success writes the crossing into `surface` and returns true; false where f has no
/// usable gradient or no crossing was bracketed.
bool rootAlongGradient(const Tape& tape, const Vec3& p, double reach, double tolerance,
                       Vec3& surface);

/// An upper bound of the distance from q to the surface: the nearest crossing bracketed along
/// the gradient from q, or from the points of up to three Newton steps from q (which reach a
/// crease, where the gradient at q points along the wrong sheet). Stops once a crossing is
/// within 1.5× the first-order estimate |f|/|∇f| at q; otherwise also marches along 26 fixed
/// directions (8 steps up to the best so far, or `reach`). Where none is bracketed, returns
/// the first-order estimate and sets `firstOrder`.
double surfaceDistance(const Tape& tape, const Vec3& q, double reach, double tolerance,
                       bool& firstOrder);

}  // namespace kerf
