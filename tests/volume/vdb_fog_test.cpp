// Fog volumes (volume/grids/vdb_fog.h): a .vdb written here (volume/grids/vdb_grid_files.h) is read
// back as a density field whose values match the grid's trilinear interpolation, whose range holds
// every value in a box and proves empty space empty; bad files, grids and values are clear errors,
// and a model that names one exits 2 with file:line:col.
#include "volume/grids/vdb_fog.h"

#include "../app/kerf_runner.h"

#include "util/level_set_files.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace kerf;
using namespace kerf::test;

namespace {

constexpr double kVoxel = 0.1;

/// A ball of radius 1 whose density falls linearly from 1 at the centre to 0 at the edge.
double ballDensity(double x, double y, double z) {
    return std::max(0.0, 1.0 - std::sqrt(x * x + y * y + z * z));
}

Grid fogBall(float scale = 1.0f) {
    Grid grid;
    grid.kind = Grid::Kind::FogVolume;
    grid.voxel = kVoxel;
    grid.name = "density";
    for (int k = -12; k <= 12; ++k)
        for (int j = -12; j <= 12; ++j)
            for (int i = -12; i <= 12; ++i) {
                const double d = ballDensity(i * kVoxel, j * kVoxel, k * kVoxel);
                if (d > 0.0) grid.values.push_back({{i, j, k}, scale * float(d)});
            }
    return grid;
}

std::string loadError(const std::string& path, const std::string& grid) {
    try {
        loadVdbFog(path, grid);
    } catch (const VdbFogError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("vdb_fog/values, ranges and bounds of a fog ball") {
    TempDir dir;
    const std::string path = dir.file("ball.vdb");
    writeGrids(path, {fogBall()});
    const VdbFog fog = loadVdbFog(path, "");
    CHECK(fog.gridName == "density");
    // The active voxels reach ±0.9 (density 0 at radius 1): the bounds one voxel wider.
    CHECK(fog.bounds.lo.x == Approx(-1.0).margin(1e-9));
    CHECK(fog.bounds.hi.z == Approx(1.0).margin(1e-9));
    const ScalarField& f = *fog.density;
    // At voxel centres the value is the voxel's; between them, trilinear.
    CHECK(f.value(Vec3(0.0)) == Approx(1.0).margin(1e-6));
    CHECK(f.value(Vec3(0.3, 0.0, 0.0)) == Approx(0.7).margin(1e-6));
    CHECK(f.value(Vec3(0.35, 0.0, 0.0)) == Approx(0.5 * (0.7 + 0.6)).margin(1e-6));
    // Every value inside a box lies in the box's range.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.2, 1.2), w(0.0, 0.8);
    for (int n = 0; n < 300; ++n) {
        const Vec3 lo(u(rng), u(rng), u(rng));
        const Vec3 hi = lo + Vec3(w(rng), w(rng), w(rng));
        const Interval r =
            f.range(Interval(lo.x, hi.x), Interval(lo.y, hi.y), Interval(lo.z, hi.z));
        for (int s = 0; s < 20; ++s) {
            const Vec3 p = lo + (hi - lo) * Vec3(w(rng) / 0.8, w(rng) / 0.8, w(rng) / 0.8);
            const double v = f.value(p);
            INFO("box " << lo.x << "," << lo.y << "," << lo.z << " .. " << hi.x << "," << hi.y
                        << "," << hi.z << " range [" << r.lo << ", " << r.hi << "], value " << v);
            CHECK(v >= r.lo - 1e-6);
            CHECK(v <= r.hi + 1e-6);
        }
    }
    // Empty space is proved empty, and the centre's blocks bound the peak tightly.
    const Interval corner =
        f.range(Interval(-3.0, -2.0), Interval(-3.0, -2.0), Interval(-3.0, -2.0));
    CHECK(corner.hi == 0.0);
    const Interval centre =
        f.range(Interval(-0.05, 0.05), Interval(-0.05, 0.05), Interval(-0.05, 0.05));
    CHECK(centre.hi >= 1.0 - 1e-6);
    CHECK(centre.hi <= 1.0 + 1e-6);
}

TEST_CASE("vdb_fog/bad files and grids are clear errors") {
    TempDir dir;
    CHECK(loadError(dir.file("missing.vdb"), "") == "no such file");
    dir.write("junk.vdb", "not a vdb file at all");
    // Checked by kerf before OpenVDB reads it (volume/grids/checked_vdb_layout.h).
    CHECK(loadError(dir.file("junk.vdb"), "") ==
          "not a .vdb file: its first 8 bytes are not OpenVDB's magic number");

    const Grid sphere = sphereGrid(1.0, Vec3(0.0), 0.1, "surface");
    const Grid velocity = vectorGrid("vel");
    auto negative = fogBall(-1.0f);
    negative.name = "negative";
    const std::string path = dir.file("many.vdb");
    writeGrids(path, {fogBall(), sphere, velocity, negative});
    CHECK(loadError(path, "smoke") ==
          "the file has no grid 'smoke' (grids: 'density', 'negative', 'surface', 'vel')");
    CHECK(loadError(path, "surface") ==
          "grid 'surface' is a level set (a surface), not a fog volume of density");
    CHECK(loadError(path, "vel") == "grid 'vel' holds vec3s values; a fog volume is a float grid");
    CHECK_THAT(loadError(path, "negative"),
               Catch::Matchers::StartsWith("grid 'negative' holds negative density"));
    CHECK(loadError(path, "density").empty());
}

TEST_CASE("vdb_fog/a model reads a fog volume relative to itself, and bad ones exit 2") {
    TempDir dir;
    const Grid sphere = sphereGrid(1.0, Vec3(0.0), 0.1, "surface");
    dir.write("fog/good.kerf",
              "mist { density volume \"ball.vdb\" extinction 2 albedo <0, 0, 0> }\n"
              "background <1, 1, 1>;\nrender { width 8 height 8 }\n");
    writeGrids(dir.file("fog/ball.vdb"), {fogBall(), sphere});
    const KerfRun good =
        runKerf(dir, {"render", "fog/good.kerf", "-o", "good.exr", "--threads", "1"});
    INFO(good.err);
    CHECK(good.exitCode == 0);
    dir.write("bad.kerf", "\nmist { density volume \"fog/ball.vdb\" grid \"surface\" }\n");
    const KerfRun bad = runKerf(dir, {"check", "bad.kerf"});
    INFO(bad.err);
    CHECK(bad.exitCode == 2);
    CHECK(bad.err.find("bad.kerf:2:23: error: cannot read fog volume 'fog/ball.vdb': grid "
                       "'surface' is a level set") != std::string::npos);
    dir.write("missing.kerf", "mist { density volume \"nowhere.vdb\" grid \"density\" }\n");
    const KerfRun missing = runKerf(dir, {"render", "missing.kerf"});
    CHECK(missing.exitCode == 2);
    CHECK(missing.err.find(
              "missing.kerf:1:23: error: cannot read fog volume 'nowhere.vdb': no such file") !=
          std::string::npos);
}
