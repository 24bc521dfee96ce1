// Region renders (issue 15 §1): every pixel of a region equals, bit for bit, the same pixel of
// the full render, for tile-aligned and unaligned regions, each sampler, the wide filters
// (whose samples reach neighbouring tiles), adaptive sampling, the AOVs and section views.
#include "render/render.h"

#include "assets/asset_cache.h"
#include "lang/compile.h"
#include "lang/diagnostic.h"

#include <catch2/catch.hpp>

#include <cstring>
#include <string>
#include <vector>

using namespace kerf;

namespace {

Scene model(const std::string& name) {
    DiagnosticSink sink;
    AssetCache assets;
    std::optional<Scene> scene =
        compileFile(std::string(KERF_SOURCE_DIR) + "/models/" + name, sink, assets);
    REQUIRE(scene);
    return std::move(*scene);
}

/// Counts the pixels of `part` (holding `region` of the full image) whose bits differ from
/// the full image's; 0 when the part is exact.
int differingPixels(const Image& full, const Image& part, const PixelRect& region) {
    REQUIRE(part.width == region.width());
    REQUIRE(part.height == region.height());
    REQUIRE(part.channels == full.channels);
    int differing = 0;
    for (int y = 0; y < part.height; ++y)
        for (int x = 0; x < part.width; ++x)
            if (std::memcmp(&part.pixels[(size_t(y) * part.width + x) * part.channels],
                            &full.pixels[(size_t(y + region.y0) * full.width + x + region.x0) *
                                         full.channels],
                            sizeof(float) * size_t(full.channels)) != 0)
                ++differing;
    return differing;
}

const std::vector<PixelRect> kRegions = {
    {0, 0, 70, 50},    // the whole image
    {16, 16, 32, 32},  // one tile, aligned
    {5, 3, 37, 29},    // unaligned, across six tiles
    {69, 49, 70, 50},  // the corner pixel, in a partial tile
    {0, 21, 70, 22},   // one row
    {33, 0, 47, 50},   // a column band through the image's edges
};

void checkRegions(const Scene& scene, RenderOptions options) {
    options.width = 70;
    options.height = 50;
    options.threads = 2;
    const RenderResult full = render(scene, options);
    for (const PixelRect& region : kRegions) {
        CAPTURE(region.x0, region.y0, region.x1, region.y1);
        options.region = region;
        const RenderResult part = render(scene, options);
        CHECK(part.region == region);
        CHECK(part.fullWidth == 70);
        CHECK(part.fullHeight == 50);
        CHECK(differingPixels(full.color, part.color, region) == 0);
        if (options.wantDepth) CHECK(differingPixels(full.depth, part.depth, region) == 0);
        if (options.wantNormal) CHECK(differingPixels(full.normal, part.normal, region) == 0);
    }
}

}  // namespace

TEST_CASE("regionTiles: the tiles whose pixels reach the region") {
    // 70 × 50: tiles of 16 are 5 across (the last 6 wide) and 4 down (the last 2 high).
    CHECK(regionTiles(70, 50, {5, 3, 37, 29}, 0) == std::vector<int>{0, 1, 2, 5, 6, 7});
    CHECK(regionTiles(70, 50, {16, 16, 32, 32}, 0) == std::vector<int>{6});
    // A filter reaching 2 pixels takes the eight neighbours of a tile.
    CHECK(regionTiles(70, 50, {16, 16, 32, 32}, 2) ==
          std::vector<int>{0, 1, 2, 5, 6, 7, 10, 11, 12});
    // The corner pixel's reach (rows 47-49) crosses into the row of tiles above.
    CHECK(regionTiles(70, 50, {69, 49, 70, 50}, 0) == std::vector<int>{19});
    CHECK(regionTiles(70, 50, {69, 49, 70, 50}, 2) == std::vector<int>{14, 19});
    CHECK(tileRect(19, 70, 50) == PixelRect{64, 48, 70, 50});
}

TEST_CASE("region renders equal the full render's pixels: box filter, each sampler") {
    const Scene scene = model("cup.kerf");
    RenderOptions options;
    options.spp = 4;
    options.filter = FilterKind::Box;
    for (SamplerKind s :
         {SamplerKind::Regular, SamplerKind::Random, SamplerKind::Jittered, SamplerKind::Lattice}) {
        CAPTURE(int(s));
        options.sampler = s;
        checkRegions(scene, options);
    }
}

TEST_CASE("region renders equal the full render's pixels: wide filters") {
    const Scene scene = model("cup.kerf");
    RenderOptions options;
    options.spp = 4;
    for (FilterKind f : {FilterKind::Gaussian, FilterKind::Mitchell}) {
        CAPTURE(int(f));
        options.filter = f;
        checkRegions(scene, options);
    }
}

TEST_CASE("region renders equal the full render's pixels: adaptive sampling and AOVs") {
    const Scene scene = model("glass.kerf");
    RenderOptions options;
    options.spp = 32;
    options.noise = 0.01;
    options.filter = FilterKind::Gaussian;
    options.wantDepth = true;
    options.wantNormal = true;
    checkRegions(scene, options);
}

TEST_CASE("region renders equal the full render's pixels: section views") {
    const Scene scene = model("cup_section.kerf");
    REQUIRE(!scene.sections.empty());
    RenderOptions options;
    options.spp = 2;
    options.filter = FilterKind::Mitchell;
    options.wantDepth = true;
    checkRegions(scene, options);
}

TEST_CASE("a region outside the image is refused") {
    const Scene scene = model("cup.kerf");
    RenderOptions options;
    options.width = 20;
    options.height = 10;
    options.region = PixelRect{0, 0, 21, 10};
    CHECK_THROWS_AS(render(scene, options), std::invalid_argument);
    options.region = PixelRect{5, 5, 5, 8};
    CHECK_THROWS_AS(render(scene, options), std::invalid_argument);
}
