/// @file io/section_writers.h
/// @brief The files of a plane section (slice/, `kerf slice`): closed polygons in the plane's
/// own 2D coordinates, in model units, grouped by material, written as SVG, DXF or a raster
/// with exact area coverage. io/ knows nothing of solids: slice/ hands it plain loops.
#pragma once

#include "io/image.h"

#include <array>
#include <string>
#include <vector>

namespace kerf {

/// A closed loop in the section plane's (u, v) coordinates, model units, v up. The last point
/// is not repeated. Outer boundaries run counter-clockwise and holes clockwise, so the
/// nonzero and even-odd rules fill the same region.
struct SectionLoop {
    std::vector<std::array<double, 2>> points;
};

/// One material's part of the section: its loops, its name (an SVG group id, a DXF layer name)
/// and its colour (linear RGB in [0, 1]).
struct SectionLayer {
    std::string name;
    std::array<double, 3> color{0.8, 0.8, 0.8};
    std::vector<SectionLoop> loops;
};

/// A whole section: its layers and the rectangle it is drawn in (model units; for an empty
/// section, the plane's part of the scene's bounds, or a unit square).
struct SectionDrawing {
    std::vector<SectionLayer> layers;
    double minU = 0.0, minV = 0.0, maxU = 1.0, maxV = 1.0;
};

/// SVG: a viewBox in model units (v up: the y axis is flipped by a transform on the one
/// group, so coordinates are the model's), one <path> per layer with fill-rule evenodd and
/// the layer's colour (sRGB), or strokes only when `outline`. Numbers are written with enough
/// digits to read back the doubles' first 12 significant digits.
std::string sectionSvg(const SectionDrawing& drawing, bool outline);

/// DXF (R12 ASCII, plus LWPOLYLINE from R2000: AC1015): every loop a closed LWPOLYLINE on its
/// layer's layer, the units in the header ($INSUNITS), the extent in $EXTMIN/$EXTMAX.
std::string sectionDxf(const SectionDrawing& drawing);

/// A pixel grid over the section plane: pixel (i, j) (j from the top row) covers
/// [u0 + i·pixel, u0 + (i+1)·pixel] × [v1 − (j+1)·pixel, v1 − j·pixel].
struct SectionGrid {
    int width = 0;
    int height = 0;
    double u0 = 0.0;
    double v1 = 0.0;
    double pixel = 1.0;
};

/// RGBA float image: each pixel's alpha is the exact fraction of its area the section covers
/// (up to rounding, not point samples), its colour the layers' colours weighted by their
/// coverage (premultiplied by nothing: straight colour, background transparent).
Image sectionRaster(const SectionDrawing& drawing, const SectionGrid& grid);

}  // namespace kerf
