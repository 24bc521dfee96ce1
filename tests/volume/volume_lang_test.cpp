// `volume "file.vdb"` in the language: lowered under the grid's transform and the user's, paths
// relative to the model file, usable in CSG, one shared grid per (file, grid name); every
// mistake as one error at the string it is about, and `kerf check` exits 2 with file:line:col
// and a caret. (Here rather than in tests/lang/ because the files are written with OpenVDB,
// which only this test binary links.)
#include "app/kerf_runner.h"
#include "lang/lang_test_util.h"
#include "util/level_set_files.h"
#include "volume/grids/level_set_grid.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>

using namespace kerf;
using namespace kerf::test;
namespace fs = std::filesystem;

namespace {

constexpr double kPiArea = 3.14159265358979323846;

/// A folder with models/parts/{sphere,many}.vdb: a sphere of radius 1 (voxel 0.05), and a file
/// holding a fog volume, a vec3 grid and the sphere.
struct VolumeFolder {
    TempDir dir;
    VolumeFolder() {
        fs::create_directories(dir.path() / "models" / "parts");
        writeGrids(part("sphere.vdb"), {sphereGrid(1.0, Vec3(0.0), 0.05)});
        writeGrids(part("many.vdb"),
                   {fogGrid(), vectorGrid(), sphereGrid(1.0, Vec3(0.0), 0.05, "surface")});
    }
    std::string part(const std::string& name) const {
        return (dir.path() / "models" / "parts" / name).string();
    }
    std::string model() const { return (dir.path() / "models" / "scene.kerf").string(); }
};

const LevelSetGrid* gridBelow(const Node* n) {
    while (n->kind() != NodeKind::Volume) {
        REQUIRE(n->children().size() >= 1);
        n = n->children()[0].get();
    }
    return std::get<VolumeParams>(n->params()).grid.get();
}

}  // namespace

TEST_CASE("volume lang: a level set under transforms and in CSG", "[volume]") {
    VolumeFolder f;
    const Compiled c = compileText(
        "object volume \"parts/sphere.vdb\" translate <3, 0, 0>;\n"
        "object difference { volume \"parts/many.vdb\" grid \"surface\"\n"
        "                    box { min <0, 0, -2> max <2, 2, 2> } };\n"
        "object volume \"parts/../parts/sphere.vdb\" scale 2;\n",
        f.model());
    INFO(c.sink.format());
    REQUIRE(c.scene);
    REQUIRE(c.scene->objects.size() == 3);
    // The sphere's inside cells, moved by 3: within two voxels of [2, 4] × [−1, 1]².
    const Bounds3 b = c.scene->objects[0]->bounds();
    CHECK(b.lo.x == Approx(2.0).margin(0.1));
    CHECK(b.hi.x == Approx(4.0).margin(0.1));
    CHECK(b.lo.x <= 2.0);
    CHECK(b.hi.y >= 1.0);
    CHECK(gridBelow(c.scene->objects[0].get()) == gridBelow(c.scene->objects[2].get()));  // shared
    CHECK(gridBelow(c.scene->objects[1].get())->info().gridName == "surface");
    // Down −y at x = 3.3: the sphere's top at y = √(1 − 0.09), to the trilinear error.
    TraceContext ctx;
    Boundary hit;
    bool entering;
    REQUIRE(c.scene->objects[0]->firstSurface(Ray{Vec3(3.3, 5, 0), Vec3(0, -1, 0)}, 0.0, kInf, ctx,
                                              hit, entering));
    CHECK(entering);
    CHECK(hit.t == Approx(5 - std::sqrt(0.91)).margin(0.001));
    // The difference: at x = 0.5 the box removed the upper half, so a ray down −y enters at y = 0.
    REQUIRE(c.scene->objects[1]->firstSurface(Ray{Vec3(0.5, 5, 0.1), Vec3(0, -1, 0)}, 0.0, kInf,
                                              ctx, hit, entering));
    CHECK(hit.t == Approx(5.0).epsilon(1e-12));
    // Scaled by 2: the radius is 2.
    REQUIRE(c.scene->objects[2]->firstSurface(Ray{Vec3(0, 0, 5), Vec3(0, 0, -1)}, 0.0, kInf, ctx,
                                              hit, entering));
    CHECK(hit.t == Approx(3.0).margin(0.002));
}

TEST_CASE("volume lang: each mistake is one error at its string", "[volume]") {
    VolumeFolder f;
    requireOneError(compileText("object volume \"parts/none.vdb\";\n", f.model()), 1, 15,
                    "cannot use volume 'parts/none.vdb' as a solid: no such file");
    requireOneError(
        compileText("object union {\n  volume \"parts/many.vdb\" grid \"solid\"\n  sphere { radius "
                    "1 } };\n",
                    f.model()),
        2, 32,
        "it has no grid named 'solid'; its grids: 'density' (float, fog volume), 'surface' (float, "
        "level set), 'vel' (vec3s, unknown class)");
    requireOneError(compileText("object volume \"parts/many.vdb\" grid \"density\";\n", f.model()),
                    1, 37,
                    "grid 'density' is a fog volume (grid class fog volume), not a level set");
    requireOneError(compileText("object volume \"parts/many.vdb\" grid \"vel\";\n", f.model()), 1,
                    37, "grid 'vel' holds vec3s values; a solid needs a float level set");
    requireOneError(compileText("object volume \"parts/sphere.vdb\" grid 3;\n", f.model()), 1, 39,
                    "grid expects the grid's name in quotes");
}

TEST_CASE("volume lang: kerf check reports the grid, and exits 2 on a bad volume", "[volume]") {
    VolumeFolder f;
    fs::copy_file(f.part("many.vdb"), f.dir.file("many.vdb"));
    fs::copy_file(f.part("sphere.vdb"), f.dir.file("sphere.vdb"));
    f.dir.write("good.kerf", "object volume \"sphere.vdb\";\n");
    const KerfRun good = runKerf(f.dir, {"check", "good.kerf"});
    CHECK(good.exitCode == 0);
    CHECK_THAT(good.out, Catch::Matchers::Contains("volume 'sphere.vdb' grid 'sphere':"));
    CHECK_THAT(good.out, Catch::Matchers::Contains("voxel size:           0.05"));
    CHECK_THAT(good.out, Catch::Matchers::Contains("active voxels:"));
    f.dir.write("fog.kerf", "object volume \"many.vdb\" grid \"density\";\n");
    const KerfRun fog = runKerf(f.dir, {"check", "fog.kerf"});
    CHECK(fog.exitCode == 2);
    CHECK_THAT(fog.err, Catch::Matchers::Contains(
                            "fog.kerf:1:31: error: cannot use volume 'many.vdb' as a solid: "
                            "grid 'density' is a fog volume"));
    CHECK_THAT(fog.err,
               Catch::Matchers::Contains("object volume \"many.vdb\" grid \"density\";\n"));
    CHECK_THAT(fog.err, Catch::Matchers::Contains("^"));
    f.dir.write("vel.kerf", "object volume \"many.vdb\" grid \"vel\";\n");
    const KerfRun vel = runKerf(f.dir, {"check", "vel.kerf"});
    CHECK(vel.exitCode == 2);
    CHECK_THAT(vel.err, Catch::Matchers::Contains(
                            "vel.kerf:1:31: error: cannot use volume 'many.vdb' as a solid: "
                            "grid 'vel' holds vec3s values"));
    f.dir.write("nogrid.kerf", "object volume \"many.vdb\" grid \"sdf\";\n");
    const KerfRun nogrid = runKerf(f.dir, {"check", "nogrid.kerf"});
    CHECK(nogrid.exitCode == 2);
    CHECK_THAT(nogrid.err, Catch::Matchers::Contains(
                               "nogrid.kerf:1:31: error: cannot use volume 'many.vdb' as a "
                               "solid: it has no grid named 'sdf'; its grids: 'density'"));
    f.dir.write("missing.kerf", "object volume \"nothing.vdb\";\n");
    const KerfRun missing = runKerf(f.dir, {"check", "missing.kerf"});
    CHECK(missing.exitCode == 2);
    CHECK_THAT(missing.err, Catch::Matchers::Contains(
                                "missing.kerf:1:15: error: cannot use volume 'nothing.vdb' as a "
                                "solid: no such file"));
}

TEST_CASE("volume lang: kerf slice of a sphere level set has the circle's area", "[volume]") {
    VolumeFolder f;
    fs::copy_file(f.part("sphere.vdb"), f.dir.file("sphere.vdb"));
    f.dir.write("ball.kerf", "object volume \"sphere.vdb\";\n");
    const KerfRun run =
        runKerf(f.dir, {"slice", "ball.kerf", "--plane", "z=0.3", "-o", "cut.svg", "--stats"});
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    const size_t at = run.err.find("total: area ");
    REQUIRE(at != std::string::npos);
    const double area = std::stod(run.err.substr(at + 12));
    // Points of the interpolant's zero set are within the trilinear bound b = h²/(4(R − 2h))
    // of the unit sphere (voxel 0.05), so in the plane z = 0.3 their radius is between
    // √((1 − b)² − 0.09) and √((1 + b)² − 0.09); the slice's own tolerance (1e-7 of the
    // model's size) is far below that.
    const double b = 0.05 * 0.05 / (4 * 0.9) + 1e-6;
    const double rlo = std::sqrt((1 - b) * (1 - b) - 0.09),
                 rhi = std::sqrt((1 + b) * (1 + b) - 0.09);
    CHECK(area >= kPiArea * rlo * rlo);
    CHECK(area <= kPiArea * rhi * rhi);
}
