/// @file io/coverage_raster.h
/// @brief The exact area coverage of closed polygons over a pixel grid, behind sectionRaster
/// (io/section_writers.h) and its tests. By Green's theorem the area of the region inside
/// pixel (i, j) is the sum over the boundary's pieces within the pixel row of ∫ clamp(x − i,
/// 0, 1) dy: a piece inside column i adds the trapezoid between it and the column's left
/// side, a piece right of the column adds its whole Δy. Each edge is clipped to rows, then to
/// columns; the right-of terms are summed from the right. Work: the pixels the edges cross
/// plus one pass over each row; memory: one row.
#pragma once

#include <functional>
#include <vector>

#include "io/section_writers.h"

namespace kerf {

/// Calls `row(j, coverage)` for every pixel row j of `grid` from the top (0) down, where
/// coverage[i] is the integral of the loops' winding number over pixel (i, j) divided by the
/// pixel's area: for loops as SectionLoop prescribes (outer boundaries counter-clockwise,
/// holes clockwise, no crossings) the exact fraction of the pixel inside, up to rounding
/// (a few ulps of the row's width in pixels). Not clamped. Throws std::invalid_argument for
/// a grid with a negative size or a pixel that is not positive and finite, and for a
/// non-finite point.
void coverageRows(const std::vector<SectionLoop>& loops, const SectionGrid& grid,
                  const std::function<void(int row, const double* coverage)>& row);

/// The same, all rows at once: width × height values, row-major from the top row.
std::vector<double> coverageGrid(const std::vector<SectionLoop>& loops, const SectionGrid& grid);

}  // namespace kerf
