// `kerf voxelize` end to end: a .vdb written with its statistics and notes for objects left
// out; bad options, too many voxels and models with nothing to voxelize refused with exit
// code 2, a message naming the problem, and nothing written.
#include "kerf_runner.h"

#include <catch2/catch.hpp>

using namespace kerf::test;

TEST_CASE("cli_voxelize/writes a .vdb, its statistics and notes") {
    TempDir dir;
    dir.write("ball.kerf",
              "object sphere { radius 1 };\n"
              "object halfspace { normal <0, 1, 0> offset -1 };\n"
              "object disc { center <0, 3, 0> normal <0, 1, 0> radius 1 };\n");
    const KerfRun run =
        runKerf(dir, {"voxelize", "ball.kerf", "-o", "ball.vdb", "--voxel", "0.1", "--stats"});
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    CHECK(run.err.find("object_1 left out: unbounded") != std::string::npos);
    CHECK(run.err.find("object_2 left out: an open surface") != std::string::npos);
    CHECK(run.err.find("object_0: ") != std::string::npos);
    CHECK(run.err.find("active voxels") != std::string::npos);
    CHECK(run.err.find("dense alternative") != std::string::npos);
    CHECK(run.err.find("cells classified") != std::string::npos);
    const std::string vdb = readFile(dir.file("ball.vdb"));
    REQUIRE(vdb.size() > 100);
    CHECK(vdb.compare(0, 4, " BDV") == 0);  // OpenVDB's magic number, little-endian
    CHECK(dir.listing() == std::vector<std::string>{"ball.kerf", "ball.vdb"});
}

TEST_CASE("cli_voxelize/bad options exit 2 and write nothing") {
    TempDir dir;
    dir.write("ball.kerf", "object sphere { radius 1 };\n");
    dir.write("plane.kerf", "object halfspace { normal <0, 0, 1> offset 0 };\n");
    dir.write("big.kerf", "object sphere { radius 1e7 };\n");
    struct Case {
        std::vector<std::string> args;
        const char* message;
    };
    const Case cases[] = {
        {{"ball.kerf", "-o", "b.vdb", "--voxel", "0"},
         "--voxel must be a finite number greater than 0"},
        {{"ball.kerf", "-o", "b.vdb", "--voxel=-0.1"},
         "--voxel must be a finite number greater than 0"},
        {{"ball.kerf", "-o", "b.vdb", "--voxel", "nan"},
         "--voxel must be a finite number greater than 0"},
        {{"ball.kerf", "-o", "b.vdb", "--voxel", "abc"}, "--voxel must be a number"},
        {{"ball.kerf", "-o", "b.vdb", "--voxel", "0.1", "--band", "0.5"},
         "--band must be a number of voxels from 1 to 16"},
        {{"ball.kerf", "-o", "b.vdb", "--voxel", "0.1", "--band", "17"},
         "--band must be a number of voxels from 1 to 16"},
        {{"ball.kerf", "-o", "b.vdb", "--voxel", "0.1", "--max-voxels", "0"},
         "--max-voxels must be a whole number"},
        {{"ball.kerf", "-o", "b.vdb", "--voxel", "0.1", "--max-voxels", "1.5"},
         "--max-voxels must be a whole number"},
        {{"ball.kerf", "-o", "b.vdb", "--voxel", "0.001"},
         "active voxels estimated at --voxel 0.001"},
        {{"ball.kerf", "-o", "b.vdb", "--voxel", "0.1", "--max-voxels", "1000"},
         "more than the limit 1000"},
        {{"ball.kerf", "-o", "b.vdb", "--voxel", "1e-4"},
         "a surface of about 12.56 square units"},  // 4π
        {{"ball.kerf", "-o", "b.vdb", "--voxel", "1e-9"},
         "smaller than an OpenVDB transform can be"},
        {{"big.kerf", "-o", "b.vdb", "--voxel", "1e-3"}, "past OpenVDB's 32-bit coordinates"},
        {{"ball.kerf", "-o", "b.obj", "--voxel", "0.1"}, "-o: the output must end in .vdb"},
        {{"plane.kerf", "-o", "b.vdb", "--voxel", "0.1"}, "no solid object to voxelize"},
        {{"missing.kerf", "-o", "b.vdb", "--voxel", "0.1"}, "cannot read model file"},
    };
    for (const Case& c : cases) {
        std::vector<std::string> args = {"voxelize"};
        args.insert(args.end(), c.args.begin(), c.args.end());
        const KerfRun run = runKerf(dir, args);
        INFO(c.args[3] << " " << (c.args.size() > 4 ? c.args[4] : "") << ": " << run.err);
        CHECK(run.exitCode == 2);
        CHECK(run.err.find(c.message) != std::string::npos);
        CHECK(dir.listing() == std::vector<std::string>{"ball.kerf", "big.kerf", "plane.kerf"});
    }
}

TEST_CASE("cli_voxelize/an OpenSCAD .csg is read by its extension") {
    TempDir dir;
    const std::string model =
        (modelsDir().parent_path() / "tests" / "data" / "openscad" / "example004.csg").string();
    const KerfRun run = runKerf(dir, {"voxelize", model, "-o", "e4.vdb", "--voxel", "1"});
    INFO(run.err);
    CHECK(run.exitCode == 0);
    CHECK(readFile(dir.file("e4.vdb")).size() > 1000);
}
