/// @file io/coverage_raster.cpp
/// @brief Exact pixel coverage of polygons (io/coverage_raster.h) and sectionRaster, which
/// composites the layers' coverages into an RGBA image.
#include "io/coverage_raster.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace kerf {
namespace {

/// An edge in pixel coordinates: x to the right, y down from the grid's top (so a loop
/// counter-clockwise in the model runs clockwise here, and the sums come out negated).
struct Edge {
    double x0, y0, x1, y1;
    int firstRow, lastRow;

    /// x where the edge crosses height y; an endpoint's y gives that endpoint exactly, and the
    /// same y always gives the same x, so the pieces of neighbouring rows meet.
    double xAt(double y) const {
        if (y == y0) return x0;
        if (y == y1) return x1;
        return x0 + (y - y0) * ((x1 - x0) / (y1 - y0));
    }
};

/// One row's sums: area[k] the trapezoids inside column k, cover[m] the Δy of pieces in
/// column m (m = width for pieces right of the grid), which counts fully for every column
/// left of m.
struct RowSums {
    std::vector<double> area, cover;

    /// Adds the piece (xa, ya) → (xb, yb), which lies within one pixel row.
    void addPiece(double xa, double ya, double xb, double yb, int width) {
        const double lo = std::min(xa, xb), hi = std::max(xa, xb);
        if (hi <= 0) return;  // left of the grid: adds to no pixel
        const int kLo = lo < 0 ? -1 : int(std::min(std::floor(lo), double(width)));
        const int kHi = hi >= width ? width : int(std::ceil(hi)) - 1;
        if (kLo >= kHi) {  // one column (a vertical piece included)
            addInColumn(std::max(kLo, kHi), 0.5 * (xa + xb), yb - ya, width);
            return;
        }
        const double slope = (yb - ya) / (xb - xa);
        const auto yAt = [&](double x) {
            if (x == xa) return ya;
            if (x == xb) return yb;
            return ya + (x - xa) * slope;
        };
        const bool rightward = xa < xb;
        for (int k = kLo; k <= kHi; ++k) {
            const double left = k <= kLo ? lo : double(k);
            const double right = k >= kHi ? hi : double(k + 1);
            const double dy = rightward ? yAt(right) - yAt(left) : yAt(left) - yAt(right);
            addInColumn(k, 0.5 * (left + right), dy, width);
        }
    }

    void addInColumn(int k, double meanX, double dy, int width) {
        if (k < 0) return;
        if (k >= width) {
            cover[width] += dy;
            return;
        }
        area[k] += dy * (meanX - k);
        cover[k] += dy;
    }
};

void checkPoint(const std::array<double, 2>& p) {
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]))
        throw std::invalid_argument("a section loop has a non-finite point");
}

}  // namespace

void coverageRows(const std::vector<SectionLoop>& loops, const SectionGrid& grid,
                  const std::function<void(int row, const double* coverage)>& row) {
    if (grid.width < 0 || grid.height < 0)
        throw std::invalid_argument("a raster with a negative size");
    if (!(grid.pixel > 0) || !std::isfinite(grid.pixel) || !std::isfinite(grid.u0) ||
        !std::isfinite(grid.v1))
        throw std::invalid_argument(
            "a raster whose pixel size or origin is not finite and positive");
    const int width = grid.width, height = grid.height;

    std::vector<Edge> edges;
    for (const SectionLoop& loop : loops) {
        const size_t n = loop.points.size();
        for (size_t k = 0; k < n; ++k) {
            const auto& a = loop.points[k];
            const auto& b = loop.points[(k + 1) % n];
            checkPoint(a);
            Edge e{(a[0] - grid.u0) / grid.pixel,
                   (grid.v1 - a[1]) / grid.pixel,
                   (b[0] - grid.u0) / grid.pixel,
                   (grid.v1 - b[1]) / grid.pixel,
                   0,
                   0};
            const double top = std::min(e.y0, e.y1), bottom = std::max(e.y0, e.y1);
            if (top == bottom || bottom <= 0 || top >= height) continue;  // adds nothing
            e.firstRow = top < 0 ? 0 : int(std::floor(top));
            e.lastRow = std::min(height - 1, int(std::ceil(std::min(bottom, double(height)))) - 1);
            edges.push_back(e);
        }
    }
    // The edges by first row (a counting sort: one pass, and the order within a row kept, so
    // the sums are added in the same order every run).
    std::vector<size_t> rowStart(size_t(height) + 1, 0);
    for (const Edge& e : edges) ++rowStart[size_t(e.firstRow) + 1];
    for (int j = 0; j < height; ++j) rowStart[j + 1] += rowStart[j];
    std::vector<const Edge*> byRow(edges.size());
    {
        std::vector<size_t> fill(rowStart.begin(), rowStart.end() - 1);
        for (const Edge& e : edges) byRow[fill[e.firstRow]++] = &e;
    }

    RowSums sums{std::vector<double>(width, 0.0), std::vector<double>(size_t(width) + 1, 0.0)};
    std::vector<double> coverage(width);
    std::vector<const Edge*> active;
    for (int j = 0; j < height; ++j) {
        active.insert(active.end(), byRow.begin() + rowStart[j], byRow.begin() + rowStart[j + 1]);
        for (const Edge* e : active) {
            const double ya = std::clamp(e->y0, double(j), double(j + 1));
            const double yb = std::clamp(e->y1, double(j), double(j + 1));
            if (ya != yb) sums.addPiece(e->xAt(ya), ya, e->xAt(yb), yb, width);
        }
        active.erase(std::remove_if(active.begin(), active.end(),
                                    [j](const Edge* e) { return e->lastRow <= j; }),
                     active.end());
        double right = sums.cover[width];
        for (int k = width - 1; k >= 0; --k) {
            coverage[k] = -(sums.area[k] + right);  // y runs down: the sums are negated
            right += sums.cover[k];
        }
        row(j, coverage.data());
        std::fill(sums.area.begin(), sums.area.end(), 0.0);
        std::fill(sums.cover.begin(), sums.cover.end(), 0.0);
    }
}

std::vector<double> coverageGrid(const std::vector<SectionLoop>& loops, const SectionGrid& grid) {
    std::vector<double> out(size_t(std::max(grid.width, 0)) * size_t(std::max(grid.height, 0)));
    coverageRows(loops, grid, [&](int j, const double* coverage) {
        std::copy(coverage, coverage + grid.width, out.begin() + size_t(j) * grid.width);
    });
    return out;
}

Image sectionRaster(const SectionDrawing& drawing, const SectionGrid& grid) {
    Image image(std::max(grid.width, 0), std::max(grid.height, 0), 4);
    for (const SectionLayer& layer : drawing.layers) {
        // A layer whose loops all run the wrong way (clockwise) is still drawn: the sign of
        // its total area says which way its outer boundaries run.
        double twiceArea = 0.0;
        for (const SectionLoop& loop : layer.loops)
            for (size_t k = 0, n = loop.points.size(); k < n; ++k) {
                const auto& a = loop.points[k];
                const auto& b = loop.points[(k + 1) % n];
                twiceArea += a[0] * b[1] - a[1] * b[0];
            }
        const double sign = twiceArea < 0 ? -1.0 : 1.0;
        coverageRows(layer.loops, grid, [&](int j, const double* coverage) {
            for (int i = 0; i < grid.width; ++i) {
                const double c = std::clamp(sign * coverage[i], 0.0, 1.0);
                if (c == 0.0) continue;
                for (int ch = 0; ch < 3; ++ch) image.at(i, j, ch) += float(c * layer.color[ch]);
                image.at(i, j, 3) += float(c);
            }
        });
    }
    // Materials do not overlap in a section, so the coverages add up to the covered fraction;
    // the colour is their coverage-weighted mean (straight, not premultiplied).
    for (int j = 0; j < image.height; ++j)
        for (int i = 0; i < image.width; ++i) {
            const float alpha = image.at(i, j, 3);
            if (alpha <= 0.f) continue;
            for (int ch = 0; ch < 3; ++ch) image.at(i, j, ch) /= alpha;
            image.at(i, j, 3) = std::min(alpha, 1.f);
        }
    return image;
}

}  // namespace kerf
