// Issue 24: no output replaces a file the compile read, included model files among them; a
// model that fails to parse opens none of its assets; `kerf assemble` never opens a FIFO or a
// device as a part.
#include "app/exit_codes.h"
#include "kerf_runner.h"

#include <catch2/catch.hpp>

#include <sys/stat.h>

using namespace kerf::test;
using kerf::app::kExitUsage;

TEST_CASE("kerf render, mesh, slice: an output that is an included file is exit 2") {
    // The included file is named like an output (its extension is the writers'), the only way
    // an output can name model text: .kerf is no output format.
    TempDir dir;
    const std::string helper = "object sphere { center <0, 0, 0> radius 1 };\n";
    dir.write("parts.png", helper);
    dir.write("parts.obj", helper);
    dir.write("scene.kerf",
              std::string("include \"parts.png\";\ninclude \"parts.obj\";\n") + kTinySphereModel);
    const std::vector<std::vector<std::string>> runs = {
        {"render", "scene.kerf", "-o", "parts.png"},
        {"render", "scene.kerf", "-o", "sub/../parts.png"},
        {"mesh", "scene.kerf", "-o", "./parts.obj", "--voxel", "0.2"},
        {"slice", "scene.kerf", "--plane", "z=0", "-o", "parts.png"}};
    fs::create_directories(dir.path() / "sub");
    for (const auto& args : runs) {
        const KerfRun run = runKerf(dir, args);
        INFO(args[0] << " -o " << args[3] << "\nstderr:\n" << run.err);
        CHECK(run.exitCode == kExitUsage);
        CHECK(run.err.find("is a file the model reads") != std::string::npos);
        CHECK(readFile(dir.file("parts.png")) == helper);
        CHECK(readFile(dir.file("parts.obj")) == helper);
    }
}

TEST_CASE("kerf render: an output that links to an included file is exit 2") {
    TempDir dir;
    const std::string helper = "object sphere { center <0, 0, 0> radius 1 };\n";
    dir.write("parts.kerf", helper);
    dir.write("scene.kerf", std::string("include \"parts.kerf\";\n") + kTinySphereModel);
    fs::create_symlink(dir.file("parts.kerf"), dir.file("picture.png"));
    const KerfRun run = runKerf(dir, {"render", "scene.kerf", "-o", "picture.png"});
    INFO("stderr:\n" << run.err);
    CHECK(run.exitCode == kExitUsage);
    CHECK(run.err.find("is a file the model reads") != std::string::npos);
    CHECK(readFile(dir.file("parts.kerf")) == helper);
}

TEST_CASE("kerf check: a model with a syntax error opens none of its assets") {
    // The lowering after a syntax error still reports semantic errors, but no mesh, volume or
    // texture is read for a compile that fails anyway: the missing files are not reported.
    TempDir dir;
    dir.write("scene.kerf",
              "object mesh \"missing.obj\";\n"
              "object volume \"missing.vdb\";\n"
              "material m { pattern image { file \"missing.png\" } }\n"
              "object sphere { radius 1 } material m;\n"
              "object box { min <0, 0, 0> max <1, 1 1> };\n");
    const KerfRun run = runKerf(dir, {"check", "scene.kerf"});
    INFO("stderr:\n" << run.err);
    CHECK(run.exitCode == kExitUsage);
    CHECK(run.err.find("scene.kerf:5:") != std::string::npos);
    CHECK(run.err.find("missing") == std::string::npos);
}

TEST_CASE("kerf assemble: a FIFO or a device as a part is exit 2, never opened") {
    TempDir dir;
    REQUIRE(mkfifo(dir.file("part.exr").c_str(), 0600) == 0);
    for (const std::string part : {"part.exr", "/dev/zero"}) {
        const KerfRun run = runKerf(dir, {"assemble", "out.exr", part});
        INFO(part << "\nstderr:\n" << run.err);
        CHECK(run.exitCode == kExitUsage);
        CHECK(run.err.find("not a regular file") != std::string::npos);
        CHECK_FALSE(fs::exists(dir.path() / "out.exr"));
    }
}
