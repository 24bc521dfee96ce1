/// @file slice/contour.h
/// @brief The section of one object by one plane as closed loops: a quadtree over the plane
/// rectangle classified by interval evaluation, contour vertices on the true boundary.
///
/// Method (slice/contour.cpp):
/// - Cells are classified by Tape::evalInterval over the cell (recording min/max choices):
///   empty (f > 0), full (f ≤ 0), boundary. A boundary cell takes its parent's tape simplified
///   to what matters in it.
/// - A boundary cell stops splitting when its boundary is proved simple by the interval
///   slopes (slice/section_tape.h): f monotone in both u and v, or monotone in one with the
///   two edges across that direction wholly inside and wholly outside. Then every line across
///   the cell meets the boundary once, and the curve is followed by root finding along such
///   lines, adding vertices until the chord between neighbours is within the tolerance of the
///   curve at their middle. Other boundary cells split down to half the tolerance (the finest
///   cells), where straight segments join the crossings of the cell's edges.
/// - Crossings are root-found once per edge piece between two neighbouring sample points
///   (corners of the cell and of smaller neighbours along its edges), shared by the two cells
///   on either side: no cracks between cells of different sizes.
/// - Segments run with the inside on their left: outer loops counter-clockwise, holes
///   clockwise.
#pragma once

#include "csg/tape/tape.h"
#include "io/section_writers.h"
#include "slice/plane.h"

#include <cstddef>
#include <vector>

namespace kerf {

struct ContourOptions {
    /// Absolute tolerance (model units): vertices within it of the boundary, chords within it
    /// of the curve, features thicker than it kept.
    double tolerance = 1e-6;
    /// The part of the plane to contour; the boundary must lie strictly inside it (the caller
    /// pads the plane's part of the object's bounds).
    PlaneRect rect;
};

struct ContourStats {
    size_t cells = 0;             ///< quadtree cells classified
    size_t boundaryLeaves = 0;    ///< boundary cells contoured
    size_t simpleLeaves = 0;      ///< of those, proved simple before the finest level
    size_t pointEvals = 0;        ///< tape evaluations at points (signs and root finding)
    size_t repairedLoops = 0;     ///< open chains closed by a segment (rounding at a tangency)
    size_t flatCells = 0;         ///< cells where f is within rounding of 0 (a face in the plane)
    bool budgetExceeded = false;  ///< the cell budget (2^21 per object) was reached
    int depth = 0;                ///< the finest level allowed
    void add(const ContourStats& o);
};

/// The loops of {f ≤ 0} on the plane at offset w, f given by `tape` over (u, v, w).
std::vector<SectionLoop> contourSection(const Tape& tape, double w, const ContourOptions& options,
                                        ContourStats& stats);

/// Signed area (shoelace) and length of a closed loop.
double loopArea(const SectionLoop& loop);
double loopLength(const SectionLoop& loop);

}  // namespace kerf
