// `kerf slice` as a user runs it: usage errors (exit 2, the option named), empty sections
// (a file and a note, exit 0), stacks (one file per layer).
#include "app/kerf_runner.h"

#include <catch2/catch.hpp>

using namespace kerf::test;

namespace {
const char* kBall = "object sphere { center <0, 0, 0> radius 1 };\n";
}

TEST_CASE("kerf slice rejects bad options with exit code 2") {
    TempDir dir;
    dir.write("ball.kerf", kBall);
    struct Case {
        std::vector<std::string> args;
        std::string says;
    };
    const std::vector<Case> cases = {
        {{"--plane", "w=1", "-o", "a.svg"}, "--plane"},
        {{"--plane", "z=abc", "-o", "a.svg"}, "--plane"},
        {{"--plane", "z=0", "--stack", "z=0:1:0.1", "-o", "a.svg"}, "exactly one"},
        {{"--point", "0,0,0", "-o", "a.svg"}, "--normal"},
        {{"--point", "0,0,0", "--normal", "0,0,0", "-o", "a.svg"}, "--normal"},
        {{"--plane", "z=0", "-o", "a.txt"}, ".svg, .dxf or .png"},
        {{"--plane", "z=0", "-o", "a.svg", "--tolerance", "0"}, "--tolerance"},
        {{"--stack", "z=0:1:0", "-o", "a_%d.svg"}, "--stack"},
        {{"--stack", "z=0:1:0.5", "-o", "a.svg"}, "%d"},
        {{"--plane", "z=0", "-o", "ball.kerf"}, ".svg"},
    };
    for (const Case& c : cases) {
        std::vector<std::string> args{"slice", "ball.kerf"};
        args.insert(args.end(), c.args.begin(), c.args.end());
        const KerfRun run = runKerf(dir, args);
        INFO(c.args[0] << " " << c.args[1] << "\nstderr: " << run.err);
        CHECK(run.exitCode == 2);
        CHECK(run.err.find(c.says) != std::string::npos);
    }
    CHECK(!fs::exists(dir.file("a.svg")));
}

TEST_CASE("kerf slice reports a model's errors at their place") {
    TempDir dir;
    dir.write("bad.kerf", "object sphere { center <0, 0, 0> radius };\n");
    const KerfRun run = runKerf(dir, {"slice", "bad.kerf", "--plane", "z=0", "-o", "a.svg"});
    CHECK(run.exitCode == 2);
    CHECK(run.err.find("bad.kerf:1:") != std::string::npos);
    CHECK(!fs::exists(dir.file("a.svg")));
}

TEST_CASE("kerf slice writes an empty section and says so") {
    TempDir dir;
    dir.write("ball.kerf", kBall);
    const KerfRun run = runKerf(dir, {"slice", "ball.kerf", "--plane", "z=5", "-o", "empty.svg"});
    INFO(run.err);
    CHECK(run.exitCode == 0);
    CHECK(run.err.find("empty") != std::string::npos);
    CHECK(fs::file_size(dir.file("empty.svg")) > 0);
}

TEST_CASE("kerf slice --stack writes one file per layer and --stats the areas") {
    TempDir dir;
    dir.write("ball.kerf", kBall);
    const KerfRun run = runKerf(
        dir, {"slice", "ball.kerf", "--stack", "z=-0.5:0.5:0.25", "-o", "cut_%02d.svg", "--stats"});
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    for (const char* name : {"cut_00.svg", "cut_01.svg", "cut_02.svg", "cut_03.svg", "cut_04.svg"})
        CHECK(fs::exists(dir.file(name)));
    CHECK(!fs::exists(dir.file("cut_05.svg")));
    CHECK(run.err.find("area") != std::string::npos);
}
