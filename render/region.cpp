/// @file render/region.cpp
/// @brief The tile grid and the pixel rectangles of region renders (declared in
/// render/render.h): which tiles a region needs, and the tile-ordered sum of their films.
#include "render/render.h"

#include <algorithm>
#include <cmath>

namespace kerf {

PixelRect intersect(const PixelRect& a, const PixelRect& b) {
    PixelRect r{std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1),
                std::min(a.y1, b.y1)};
    if (r.empty()) r = PixelRect{};
    return r;
}

PixelRect tileRect(int tile, int width, int height) {
    const int tilesAcross = (width + kTileSize - 1) / kTileSize;
    const int x0 = (tile % tilesAcross) * kTileSize;
    const int y0 = (tile / tilesAcross) * kTileSize;
    return {x0, y0, std::min(x0 + kTileSize, width), std::min(y0 + kTileSize, height)};
}

std::vector<int> regionTiles(int width, int height, const PixelRect& region, int margin) {
    const int tilesAcross = (width + kTileSize - 1) / kTileSize;
    const PixelRect reach =
        intersect({region.x0 - margin, region.y0 - margin, region.x1 + margin, region.y1 + margin},
                  {0, 0, width, height});
    std::vector<int> tiles;
    if (reach.empty()) return tiles;
    for (int ty = reach.y0 / kTileSize; ty <= (reach.y1 - 1) / kTileSize; ++ty)
        for (int tx = reach.x0 / kTileSize; tx <= (reach.x1 - 1) / kTileSize; ++tx)
            tiles.push_back(ty * tilesAcross + tx);
    return tiles;
}

int filterMargin(FilterKind kind) {
    return kind == FilterKind::Box ? 0 : int(std::ceil(ReconstructionFilter::of(kind).radius));
}

void resolveTileFilms(const std::vector<const TileFilm*>& films, const PixelRect& region,
                      Image& color) {
    // Tile by tile in a fixed order: the same sums whatever the threads or processes did.
    std::vector<double> sums(size_t(region.width()) * size_t(region.height()) * 4, 0.0);
    for (const TileFilm* f : films)
        f->addInto(sums, region.x0, region.y0, region.width(), region.height());
    resolveFilm(sums, color);
}

}  // namespace kerf
