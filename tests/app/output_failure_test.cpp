// End-to-end tests of failed writes: exit code 1 with a message, and nothing left behind —
// no temporary file, no half image, no earlier output clobbered.
#include "kerf_runner.h"

#include <catch2/catch.hpp>

using namespace kerf::test;

TEST_CASE("kerf render: an output that cannot be written") {
    TempDir dir;
    dir.write("tiny.kerf", kTinySphereModel);

    SECTION("into a folder that does not exist") {
        const KerfRun run = runKerf(dir, {"render", "tiny.kerf", "-o", "nowhere/out.png"});
        INFO("stderr:\n" << run.err);
        CHECK(run.exitCode == 1);
        CHECK(run.err.find("kerf: error:") != std::string::npos);
        CHECK(run.err.find("nowhere/out.png") != std::string::npos);
        CHECK(dir.listing() == std::vector<std::string>{"tiny.kerf"});
    }
    SECTION("onto an existing folder: the temporary file is removed") {
        fs::create_directory(dir.path() / "out.png");
        const KerfRun run = runKerf(dir, {"render", "tiny.kerf", "-o", "out.png"});
        INFO("stderr:\n" << run.err);
        CHECK(run.exitCode == 1);
        CHECK(run.err.find("out.png") != std::string::npos);
        CHECK(dir.listing() == std::vector<std::string>{"out.png", "tiny.kerf"});
        CHECK(fs::is_empty(dir.path() / "out.png"));
    }
    SECTION("an AOV that cannot be written") {
        const KerfRun run = runKerf(
            dir, {"render", "tiny.kerf", "-o", "out.png", "--aov", "depth=nowhere/depth.exr"});
        INFO("stderr:\n" << run.err);
        CHECK(run.exitCode == 1);
        CHECK(run.err.find("nowhere/depth.exr") != std::string::npos);
    }
}

TEST_CASE("kerf render: a failed run leaves an earlier output alone") {
    TempDir dir;
    dir.write("tiny.kerf", kTinySphereModel);
    const std::string earlier = dir.write("out.png", "an earlier image");
    dir.write("bad.kerf", "object sphere { radius -1 };\n");
    const KerfRun run = runKerf(dir, {"render", "bad.kerf", "-o", "out.png"});
    CHECK(run.exitCode == 2);
    CHECK(readFile(earlier) == "an earlier image");
    CHECK(dir.listing() == std::vector<std::string>{"bad.kerf", "out.png", "tiny.kerf"});
}
