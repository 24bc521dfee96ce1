// `kerf mesh` end to end: a mesh written with its statistics; bad voxel sizes, adaptivity and
// outputs refused with exit code 2, a message naming the option, and nothing written.
#include "../app/kerf_runner.h"

#include <catch2/catch.hpp>

#include <cstring>

using namespace kerf::test;

TEST_CASE("mesh_cli/writes a mesh and its statistics") {
    TempDir dir;
    dir.write("ball.kerf",
              "object sphere { radius 1 };\nobject halfspace { normal <0, 1, 0> offset -1 };\n");
    const KerfRun run =
        runKerf(dir, {"mesh", "ball.kerf", "-o", "ball.stl", "--voxel", "0.2", "--stats"});
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    CHECK(run.err.find("left out 1 unbounded object") != std::string::npos);
    CHECK(run.err.find("hausdorff") != std::string::npos);
    CHECK(run.err.find("triangles:") != std::string::npos);
    const std::string stl = readFile(dir.file("ball.stl"));
    REQUIRE(stl.size() > 84);
    uint32_t count = 0;
    std::memcpy(&count, stl.data() + 80, 4);
    CHECK(stl.size() == 84 + 50 * size_t(count));
}

TEST_CASE("mesh_cli/bad options exit 2 and write nothing") {
    TempDir dir;
    dir.write("ball.kerf", "object sphere { radius 1 };\n");
    struct Case {
        std::vector<std::string> args;
        const char* message;
    };
    const Case cases[] = {
        {{"--voxel", "0"}, "--voxel must be a finite number greater than 0"},
        {{"--voxel=-0.1"}, "--voxel must be a finite number greater than 0"},
        {{"--voxel", "nan"}, "--voxel must be a finite number greater than 0"},
        {{"--voxel", "inf"}, "--voxel must be a finite number greater than 0"},
        {{"--voxel", "abc"}, "--voxel must be a number"},
        {{"--voxel", "1e-9"}, "too fine for this model"},
        {{"--voxel", "1e-4"}, "too fine for this model"},
        {{"--voxel", "0.1", "--adaptivity", "2"}, "--adaptivity must be a number from 0 to 1"},
    };
    for (const Case& c : cases) {
        std::vector<std::string> args = {"mesh", "ball.kerf", "-o", "ball.obj"};
        args.insert(args.end(), c.args.begin(), c.args.end());
        const KerfRun run = runKerf(dir, args);
        INFO(c.args[0] << " " << (c.args.size() > 1 ? c.args[1] : "") << ": " << run.err);
        CHECK(run.exitCode == 2);
        CHECK(run.err.find(c.message) != std::string::npos);
        CHECK(dir.listing() == std::vector<std::string>{"ball.kerf"});
    }
    const KerfRun wrongFormat =
        runKerf(dir, {"mesh", "ball.kerf", "-o", "ball.png", "--voxel", "0.1"});
    CHECK(wrongFormat.exitCode == 2);
    CHECK(wrongFormat.err.find("must end in .obj, .ply or .stl") != std::string::npos);
    CHECK(dir.listing() == std::vector<std::string>{"ball.kerf"});
}
