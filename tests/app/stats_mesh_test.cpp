// `kerf render --stats` on scenes with and without meshes: the triangle BVH's counters appear
// only when a mesh was walked, each with its per-ray figure equal to the total over the rays.
#include "kerf_runner.h"
#include "mesh/mesh_files.h"

#include <catch2/catch.hpp>

#include <regex>

using namespace kerf::test;

namespace {

/// The whole number after `label` (two or more spaces) in the statistics, or -1.
double statistic(const std::string& err, const std::string& label) {
    std::smatch match;
    if (!std::regex_search(err, match, std::regex("\\n  " + label + " +([0-9.e+]+)"))) return -1;
    return std::stod(match[1].str());
}

/// The "(x per ray)" figure after `label`, or -1.
double perRay(const std::string& err, const std::string& label) {
    std::smatch match;
    if (!std::regex_search(err, match,
                           std::regex("\\n  " + label + " +[0-9]+ \\(([0-9.e+-]+) per ray\\)")))
        return -1;
    return std::stod(match[1].str());
}

}  // namespace

TEST_CASE("kerf render --stats: mesh BVH nodes and triangle tests per ray, only with meshes") {
    TempDir dir;
    dir.write("octa.obj", kerf::test::objText());
    dir.write("mesh.kerf",
              "object mesh \"octa.obj\" translate <-0.5, 2, -3>;\n"  // the octahedron at the origin
              "camera { eye <0, 0, -5> look_at <0, 0, 0> fov 40 }\n"
              "light point { at <2, 3, -4> color <1, 1, 1> power 40 }\n");
    dir.write("ball.kerf", kTinySphereModel);
    const KerfRun mesh = runKerf(
        dir, {"render", "mesh.kerf", "--width", "32", "--height", "24", "-o", "m.png", "--stats"});
    INFO(mesh.err);
    REQUIRE(mesh.exitCode == 0);
    const double rays = statistic(mesh.err, "rays in total");
    const double nodes = statistic(mesh.err, "mesh BVH nodes");
    const double tests = statistic(mesh.err, "triangle tests");
    REQUIRE(rays > 0);
    // Every camera ray aimed at the octahedron's box visits the BVH's root at least.
    CHECK(nodes > 0);
    CHECK(tests > 0);
    // Printed to 3 significant digits.
    CHECK(perRay(mesh.err, "mesh BVH nodes") == Approx(nodes / rays).epsilon(5e-3));
    CHECK(perRay(mesh.err, "triangle tests") == Approx(tests / rays).epsilon(5e-3));

    const KerfRun ball = runKerf(
        dir, {"render", "ball.kerf", "--width", "32", "--height", "24", "-o", "b.png", "--stats"});
    INFO(ball.err);
    REQUIRE(ball.exitCode == 0);
    CHECK(ball.err.find("rays in total") != std::string::npos);
    CHECK(ball.err.find("mesh BVH nodes") == std::string::npos);
    CHECK(ball.err.find("triangle tests") == std::string::npos);
}
