/// @file render/film.h
/// @brief Reconstruction filters and the film that sums filtered samples (issue 10 §1).
///
/// With the box filter a pixel is the mean of its own samples (the renderer does that itself).
/// With a wider filter every sample adds weight·radiance to each pixel whose centre is within
/// the filter's radius, and each pixel is divided by its summed weight. Tiles render in
/// parallel, so each splats into a film of its own (the tile and a margin of the radius);
/// the tile films are then added into the image one after the other in tile order, so the
/// image does not depend on the thread count or schedule.
#pragma once

#include "csg/types.h"
#include "io/image.h"
#include "scene/sampling.h"

#include <vector>

namespace kerf {

/// A separable filter: weight(dx, dy) = w(dx)·w(dy), zero beyond the radius (pixels).
struct ReconstructionFilter {
    FilterKind kind = FilterKind::Box;
    double radius = 0.5;
    /// Box: 1 within half a pixel. Gaussian: exp(−2x²) − exp(−2r²) on |x| < r = 1.5 (the
    /// Gaussian lowered to reach 0 at the radius). Mitchell–Netravali with B = C = 1/3 on
    /// |x| < r = 2 (negative lobes: sharper edges, slight ringing).
    double weight1D(double x) const;
    static ReconstructionFilter of(FilterKind kind);
};

/// One tile's share of the image: sums of weight·radiance and of weight for the pixels the
/// tile's samples reach.
class TileFilm {
public:
    TileFilm() = default;
    /// The tile covers pixels [x0, x1) × [y0, y1); its film reaches `margin` pixels further.
    TileFilm(int x0, int y0, int x1, int y1, int margin);
    /// A sample at film position (fx, fy) (pixels from the image's top-left corner).
    void add(double fx, double fy, const Vec3& radiance, const ReconstructionFilter& filter);
    /// Adds this tile's sums into the image-wide sums (width × height, 4 per pixel).
    void addInto(std::vector<double>& sums, int width, int height) const;
    /// The same for sums that cover only the pixels [x0, x0 + width) × [y0, y0 + height).
    void addInto(std::vector<double>& sums, int x0, int y0, int width, int height) const;

    /// The film's extent (margin included) and sums, to send it to another process.
    int filmX0() const { return mX0; }
    int filmY0() const { return mY0; }
    int filmWidth() const { return mWidth; }
    int filmHeight() const { return mHeight; }
    const std::vector<double>& sums() const { return mSums; }
    /// A film received from another process (`sums`: filmWidth × filmHeight × 4 values).
    static TileFilm fromParts(int filmX0, int filmY0, int filmWidth, int filmHeight,
                              std::vector<double> sums);

private:
    int mX0 = 0, mY0 = 0, mWidth = 0, mHeight = 0;  ///< the film's own extent, margin included
    std::vector<double> mSums;                      ///< r, g, b, weight per pixel
};

/// The image from the summed tiles: radiance sums over weight sums; a pixel with no weight
/// (or none left after Mitchell's negative lobes) is black.
void resolveFilm(const std::vector<double>& sums, Image& color);

}  // namespace kerf
