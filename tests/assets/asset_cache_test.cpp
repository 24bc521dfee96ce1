// The asset cache (assets/asset_cache.h) across compiles: a model with a ~100 k-triangle mesh
// and an image texture compiled twice with one cache reads each file once; after the mesh is
// rewritten only the mesh is read again. And `mist … bake N` is only a request in the compiled
// scene: no grid is made until render/ prepares the medium.
#include "assets/asset_cache.h"
#include "assets/file_identity.h"
#include "io/image.h"
#include "lang/compile.h"
#include "render/medium_bake.h"
#include "util/scratch_folder.h"
#include "volume/grids/bricked_field.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <vector>

using namespace kerf;
using namespace kerf::test;

namespace {

/// A UV sphere of radius r as binary STL: fans at the poles, two triangles per quad elsewhere,
/// counter-clockwise seen from outside; 2·lon·(lat − 1) triangles. Returns the count.
uint32_t writeSphereStl(const std::string& path, int lat, int lon, double r) {
    auto point = [&](int i, int j) {
        if (i == 0) return Vec3(0, 0, r);
        if (i == lat) return Vec3(0, 0, -r);
        const double theta = M_PI * i / lat, phi = 2 * M_PI * (j % lon) / lon;
        return Vec3(r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi),
                    r * std::cos(theta));
    };
    std::vector<std::array<Vec3, 3>> tris;
    for (int i = 0; i < lat; ++i)
        for (int j = 0; j < lon; ++j) {
            const Vec3 a = point(i, j), b = point(i + 1, j), c = point(i + 1, j + 1),
                       d = point(i, j + 1);
            if (i == 0)
                tris.push_back({a, b, c});
            else if (i == lat - 1)
                tris.push_back({a, b, d});
            else
                tris.push_back({a, b, c}), tris.push_back({a, c, d});
        }
    std::ofstream out(path, std::ios::binary);
    char header[80] = {};
    out.write(header, 80);
    const uint32_t count = uint32_t(tris.size());
    out.write(reinterpret_cast<const char*>(&count), 4);
    for (const auto& t : tris) {
        float v[12] = {};  // normal (left 0: readers compute it), then the three corners
        for (int k = 0; k < 3; ++k)
            for (int a = 0; a < 3; ++a) v[3 + 3 * k + a] = float(t[size_t(k)][a]);
        out.write(reinterpret_cast<const char*>(v), sizeof(v));
        const uint16_t attributes = 0;
        out.write(reinterpret_cast<const char*>(&attributes), 2);
    }
    return count;
}

const char* const kModel = R"(
material wood { pattern image { file "grain.png" } }
object mesh "ball.stl" material wood;
object mesh "ball.stl" translate <3, 0, 0>;
camera { eye <0, 0, -6> look_at <0, 0, 0> }
)";

std::optional<Scene> compileIn(const ScratchFolder& folder, AssetCache& cache,
                               DiagnosticSink& sink) {
    cache.clearInputs();
    return compileString(kModel, folder.file("model.kerf"), sink, cache);
}

}  // namespace

TEST_CASE("AssetCache: a recompile reuses unchanged assets and reloads a changed one") {
    ScratchFolder folder;
    const uint32_t triangles = writeSphereStl(folder.file("ball.stl"), 224, 224, 1.0);
    REQUIRE(triangles > 99000);
    Image grain(4, 4, 3);
    for (size_t i = 0; i < grain.pixels.size(); ++i) grain.pixels[i] = float(i % 7) / 7.0f;
    writeImage(grain, folder.file("grain.png"));

    AssetCache cache;
    DiagnosticSink sink;
    const std::optional<Scene> first = compileIn(folder, cache, sink);
    INFO(sink.format());
    REQUIRE(first);
    REQUIRE(first->objects.size() == 2);
    // Two uses of the mesh, one read of its file; one texture.
    CHECK(cache.loads().meshes == 1);
    CHECK(cache.loads().textures == 1);
    CHECK(cache.loads().total() == 2);
    CHECK(cache.reuses().total() == 0);
    REQUIRE(cache.inputs().size() == 2);
    CHECK(cache.inputs()[0].path == canonicalPath(folder.file("grain.png")));
    CHECK(cache.inputs()[1].path == canonicalPath(folder.file("ball.stl")));
    CHECK(cache.inputs()[1].size == 84 + 50 * uint64_t(triangles));

    DiagnosticSink again;
    const std::optional<Scene> second = compileIn(folder, cache, again);
    INFO(again.format());
    REQUIRE(second);
    CHECK(cache.loads().total() == 2);  // nothing read again
    CHECK(cache.reuses().meshes == 1);
    CHECK(cache.reuses().textures == 1);
    CHECK(cache.inputs().size() == 2);  // the same files, listed for this compile too

    // A coarser sphere in the mesh's place: a new size and mtime; only the mesh is read.
    const uint32_t fewer = writeSphereStl(folder.file("ball.stl"), 20, 20, 1.0);
    DiagnosticSink third;
    const std::optional<Scene> changed = compileIn(folder, cache, third);
    INFO(third.format());
    REQUIRE(changed);
    CHECK(cache.loads().meshes == 2);
    CHECK(cache.loads().textures == 1);
    CHECK(cache.reuses().textures == 2);
    CHECK(cache.inputs()[1].size == 84 + 50 * uint64_t(fewer));
}

TEST_CASE("AssetCache: a failed load is an error at the file and is not kept") {
    ScratchFolder folder;
    AssetCache cache;
    DiagnosticSink sink;
    CHECK_FALSE(compileIn(folder, cache, sink));
    CHECK(sink.errorCount() == 2);  // the texture and the mesh (once for its two uses)
    CHECK_THAT(sink.format(), Catch::Matchers::Contains("cannot load mesh 'ball.stl'"));
    CHECK(cache.inputs().empty());
    writeSphereStl(folder.file("ball.stl"), 8, 8, 1.0);
    writeImage(Image(2, 2, 3), folder.file("grain.png"));
    DiagnosticSink fixed;
    CHECK(compileIn(folder, cache, fixed));
    CHECK(cache.loads().meshes == 2);
}

TEST_CASE("mist bake: the compiled scene holds the request, render/ makes the grid") {
    // What `kerf check` compiles: the density is still the expression, no grid is made.
    DiagnosticSink sink;
    const std::optional<Scene> scene = compileString(
        "mist { density 0.5 + 0.25 * x bounds box { min <0, 0, 0> max <4, 2, 1> } bake 33 }",
        "bake.kerf", sink);
    INFO(sink.format());
    REQUIRE(scene);
    const Medium& m = scene->medium;
    REQUIRE(m.bake);
    CHECK(m.bake->resolution == 33);
    CHECK(m.bake->where == "bake.kerf:1:79");
    CHECK(dynamic_cast<const BrickedField*>(m.density.get()) == nullptr);
    // Prepared for rendering: the bricked field of 33 samples along x (spacing 4/32), equal to
    // the linear density at its samples.
    const Scene baked = withBakedMedium(*scene);
    CHECK_FALSE(baked.medium.bake);
    const auto* field = dynamic_cast<const BrickedField*>(baked.medium.density.get());
    REQUIRE(field != nullptr);
    CHECK(field->spacing() == 0.125);
    CHECK(field->value(Vec3(2.0, 1.0, 0.5)) == Approx(1.0).margin(0x1p-22));
}
