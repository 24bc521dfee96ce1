/// @file render/film.cpp
/// @brief Filtered splatting of samples into tile films, and their sum.
#include "render/film.h"

#include "csg/check.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace kerf {

ReconstructionFilter ReconstructionFilter::of(FilterKind kind) {
    switch (kind) {
        case FilterKind::Box: return {kind, 0.5};
        case FilterKind::Gaussian: return {kind, 1.5};
        case FilterKind::Mitchell: return {kind, 2.0};
    }
    return {};
}

double ReconstructionFilter::weight1D(double x) const {
    x = std::fabs(x);
    if (!(x < radius)) return 0.0;
    switch (kind) {
        case FilterKind::Box: return 1.0;
        case FilterKind::Gaussian: return std::exp(-2.0 * x * x) - std::exp(-2.0 * radius * radius);
        case FilterKind::Mitchell: {
            constexpr double B = 1.0 / 3.0, C = 1.0 / 3.0;
            const double x2 = x * x, x3 = x2 * x;
            if (x < 1.0)
                return ((12 - 9 * B - 6 * C) * x3 + (-18 + 12 * B + 6 * C) * x2 + (6 - 2 * B)) /
                       6.0;
            return ((-B - 6 * C) * x3 + (6 * B + 30 * C) * x2 + (-12 * B - 48 * C) * x +
                    (8 * B + 24 * C)) /
                   6.0;
        }
    }
    return 0.0;
}

TileFilm::TileFilm(int x0, int y0, int x1, int y1, int margin)
    : mX0(x0 - margin),
      mY0(y0 - margin),
      mWidth(x1 - x0 + 2 * margin),
      mHeight(y1 - y0 + 2 * margin),
      mSums(size_t(mWidth) * size_t(mHeight) * 4, 0.0) {}

void TileFilm::add(double fx, double fy, const Vec3& radiance, const ReconstructionFilter& filter) {
    // Pixel k's centre is k + 0.5: the pixels within the radius of the sample.
    const int kx0 = int(std::ceil(fx - filter.radius - 0.5)),
              kx1 = int(std::floor(fx + filter.radius - 0.5));
    const int ky0 = int(std::ceil(fy - filter.radius - 0.5)),
              ky1 = int(std::floor(fy + filter.radius - 0.5));
    for (int ky = std::max(ky0, mY0); ky <= std::min(ky1, mY0 + mHeight - 1); ++ky) {
        const double wy = filter.weight1D(ky + 0.5 - fy);
        if (wy == 0.0) continue;
        for (int kx = std::max(kx0, mX0); kx <= std::min(kx1, mX0 + mWidth - 1); ++kx) {
            const double w = wy * filter.weight1D(kx + 0.5 - fx);
            if (w == 0.0) continue;
            double* s = &mSums[(size_t(ky - mY0) * size_t(mWidth) + size_t(kx - mX0)) * 4];
            s[0] += w * radiance.x;
            s[1] += w * radiance.y;
            s[2] += w * radiance.z;
            s[3] += w;
        }
    }
}

void TileFilm::addInto(std::vector<double>& sums, int width, int height) const {
    addInto(sums, 0, 0, width, height);
}

void TileFilm::addInto(std::vector<double>& sums, int x0, int y0, int width, int height) const {
    KERF_DCHECK_GE(sums.size(), size_t(width) * size_t(height) * 4);
    for (int y = std::max(mY0, y0); y < std::min(mY0 + mHeight, y0 + height); ++y)
        for (int x = std::max(mX0, x0); x < std::min(mX0 + mWidth, x0 + width); ++x) {
            const double* s = &mSums[(size_t(y - mY0) * size_t(mWidth) + size_t(x - mX0)) * 4];
            double* d = &sums[(size_t(y - y0) * size_t(width) + size_t(x - x0)) * 4];
            for (int k = 0; k < 4; ++k) d[k] += s[k];
        }
}

TileFilm TileFilm::fromParts(int filmX0, int filmY0, int filmWidth, int filmHeight,
                             std::vector<double> sums) {
    KERF_DCHECK_EQ(sums.size(), size_t(filmWidth) * size_t(filmHeight) * 4);
    TileFilm film;
    film.mX0 = filmX0;
    film.mY0 = filmY0;
    film.mWidth = filmWidth;
    film.mHeight = filmHeight;
    film.mSums = std::move(sums);
    return film;
}

void resolveFilm(const std::vector<double>& sums, Image& color) {
    for (int y = 0; y < color.height; ++y)
        for (int x = 0; x < color.width; ++x) {
            const double* s = &sums[(size_t(y) * size_t(color.width) + size_t(x)) * 4];
            for (int k = 0; k < 3; ++k)
                color.at(x, y, k) = s[3] > 0.0 ? float(std::max(0.0, s[k] / s[3])) : 0.0f;
        }
}

}  // namespace kerf
