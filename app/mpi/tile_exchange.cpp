/// @file app/mpi/tile_exchange.cpp
#include "app/mpi/tile_exchange.h"

#include <cstdint>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>

namespace kerf::app::mpi {

namespace {

template <typename T>
void put(std::vector<char>& out, const T* data, size_t count) {
    const char* bytes = reinterpret_cast<const char*>(data);
    out.insert(out.end(), bytes, bytes + count * sizeof(T));
}

template <typename T>
void put(std::vector<char>& out, T value) {
    put(out, &value, 1);
}

/// Reads from a packed buffer, checking every read stays inside it.
class Reader {
public:
    explicit Reader(const std::vector<char>& bytes) : mBytes(bytes) {}
    bool done() const { return mAt == mBytes.size(); }
    template <typename T>
    void get(T* data, size_t count) {
        if (count * sizeof(T) > mBytes.size() - mAt)
            throw std::runtime_error("tile data cut short");
        std::memcpy(data, mBytes.data() + mAt, count * sizeof(T));
        mAt += count * sizeof(T);
    }
    template <typename T>
    T get() {
        T value;
        get(&value, 1);
        return value;
    }

private:
    const std::vector<char>& mBytes;
    size_t mAt = 0;
};

/// The rows of `part` (full-image pixels inside the region) of a region-sized image.
void putPixels(std::vector<char>& out, const Image& image, const PixelRect& region,
               const PixelRect& part) {
    for (int y = part.y0; y < part.y1; ++y)
        put(out,
            &image.pixels[(size_t(y - region.y0) * image.width + (part.x0 - region.x0)) *
                          image.channels],
            size_t(part.width()) * image.channels);
}

void getPixels(Reader& in, Image& image, const PixelRect& region, const PixelRect& part) {
    for (int y = part.y0; y < part.y1; ++y)
        in.get(&image.pixels[(size_t(y - region.y0) * image.width + (part.x0 - region.x0)) *
                             image.channels],
               size_t(part.width()) * image.channels);
}

}  // namespace

std::vector<char> packTiles(const RenderResult& result) {
    std::vector<char> out;
    const bool films = !result.films.empty();
    for (size_t k = 0; k < result.tiles.size(); ++k) {
        const int tile = result.tiles[k];
        put(out, int32_t(tile));
        const PixelRect part =
            intersect(tileRect(tile, result.fullWidth, result.fullHeight), result.region);
        if (films) {
            const TileFilm& f = result.films[k];
            const int32_t extent[4] = {f.filmX0(), f.filmY0(), f.filmWidth(), f.filmHeight()};
            put(out, extent, 4);
            put(out, f.sums().data(), f.sums().size());
        } else if (!part.empty()) {
            putPixels(out, result.color, result.region, part);
        }
        if (part.empty()) continue;  // a tile traced only for its filtered samples
        if (result.depth.channels > 0) putPixels(out, result.depth, result.region, part);
        if (result.normal.channels > 0) putPixels(out, result.normal, result.region, part);
    }
    return out;
}

RenderResult assembleTiles(const RenderResult& local, const std::vector<std::vector<char>>& packs) {
    RenderResult full;
    full.region = local.region;
    full.fullWidth = local.fullWidth;
    full.fullHeight = local.fullHeight;
    full.stats = local.stats;
    const PixelRect& region = local.region;
    full.color = Image(region.width(), region.height(), 3);
    if (local.depth.channels > 0) full.depth = Image(region.width(), region.height(), 1);
    if (local.normal.channels > 0) full.normal = Image(region.width(), region.height(), 3);
    const bool filtered = local.stats.filter != FilterKind::Box;
    const std::vector<int> expected =
        regionTiles(local.fullWidth, local.fullHeight, region, filterMargin(local.stats.filter));

    std::map<int, TileFilm> films;
    std::map<int, bool> seen;
    for (const std::vector<char>& pack : packs) {
        Reader in(pack);
        while (!in.done()) {
            const int tile = in.get<int32_t>();
            if (seen[tile])
                throw std::runtime_error("tile " + std::to_string(tile) + " came twice");
            seen[tile] = true;
            const PixelRect part =
                intersect(tileRect(tile, local.fullWidth, local.fullHeight), region);
            if (filtered) {
                int32_t e[4];
                in.get(e, 4);
                std::vector<double> sums(size_t(e[2]) * size_t(e[3]) * 4);
                in.get(sums.data(), sums.size());
                films[tile] = TileFilm::fromParts(e[0], e[1], e[2], e[3], std::move(sums));
            } else if (!part.empty()) {
                getPixels(in, full.color, region, part);
            }
            if (part.empty()) continue;
            if (full.depth.channels > 0) getPixels(in, full.depth, region, part);
            if (full.normal.channels > 0) getPixels(in, full.normal, region, part);
        }
    }
    if (seen.size() != expected.size())
        throw std::runtime_error("gathered " + std::to_string(seen.size()) + " tiles of " +
                                 std::to_string(expected.size()));
    if (filtered) {
        // The full render's sum: every tile's film, in increasing tile order.
        std::vector<const TileFilm*> inOrder;
        for (int tile : expected) {
            const auto it = films.find(tile);
            if (it == films.end())
                throw std::runtime_error("tile " + std::to_string(tile) + " is missing");
            inOrder.push_back(&it->second);
        }
        resolveTileFilms(inOrder, region, full.color);
    }
    return full;
}

}  // namespace kerf::app::mpi
