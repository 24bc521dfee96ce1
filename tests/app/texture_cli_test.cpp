// `pattern image` from the command line: texture files are found relative to the model's
// folder, and a texture that cannot be read stops the run before rendering with exit 2 and a
// FILE:LINE:COL diagnostic at the `file` property naming the texture and the reason.
#include "app/exit_codes.h"
#include "io/image.h"
#include "kerf_runner.h"

#include <catch2/catch.hpp>

#include <regex>

using namespace kerf;
using namespace kerf::test;
using kerf::app::kExitSuccess;
using kerf::app::kExitUsage;

namespace {

std::string texturedModel(const std::string& file) {
    return "camera { eye <0, 0, -4> look_at <0, 0, 0> fov 40 }\n"
           "material tex { pattern image { file \"" +
           file +
           "\" mapping planar } ambient 1 diffuse 0 specular 0 }\n"
           "object box { min <-1, -1, -1> max <1, 1, 1> } material tex;\n"
           "render { width 8 height 8 spp 1 }\n";
}

}  // namespace

TEST_CASE("kerf render: a missing or unreadable texture is exit 2 at its file property") {
    struct Bad {
        const char* what;
        const char* file;
        const char* reason;  ///< a regular expression for the reason
    };
    const Bad cases[] = {{"missing", "nowhere.png", "no such file"},
                         {"not an image", "notes.png", ".+"},
                         {"a folder", "folder", "it is a folder"}};
    for (const Bad& bad : cases) {
        TempDir dir;
        dir.write("notes.png", "these are notes, not pixels\n");
        fs::create_directories(dir.path() / "models" / "folder");
        dir.write("models/notes.png", "these are notes, not pixels\n");
        dir.write("models/scene.kerf", texturedModel(bad.file));
        for (const char* command : {"render", "check"}) {
            std::vector<std::string> args{command, "models/scene.kerf"};
            if (std::string(command) == "render") args.insert(args.end(), {"-o", "out.png"});
            const KerfRun run = runKerf(dir, args);
            INFO(bad.what << ", " << command << "\nstderr:\n" << run.err);
            CHECK(run.exitCode == kExitUsage);
            // Line 2, the column of the file name's opening quote.
            const std::string expected =
                std::string(R"(models/scene\.kerf:2:\d+: error: cannot read texture ')") +
                bad.file + "': " + bad.reason;
            CHECK(std::regex_search(run.err, std::regex(expected)));
            CHECK_FALSE(fs::exists(dir.path() / "out.png"));
        }
    }
}

TEST_CASE("kerf render: texture files are relative to the model's folder") {
    TempDir dir;
    Image red(2, 2, 3);
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) red.at(i, j, 0) = 1.0f;
    fs::create_directories(dir.path() / "models" / "textures");
    writeImage(red, dir.file("models/textures/red.png"));
    dir.write("models/scene.kerf", texturedModel("textures/red.png"));
    const KerfRun run = runKerf(dir, {"render", "models/scene.kerf", "-o", "out.exr"});
    INFO("stderr:\n" << run.err);
    REQUIRE(run.exitCode == kExitSuccess);
    const Image out = readImage(dir.file("out.exr"));
    // The centre pixel sees the box's face: the texture's red, through ambient 1.
    CHECK(out.at(4, 4, 0) == Approx(1.0).margin(1e-3));
    CHECK(out.at(4, 4, 1) == Approx(0.0).margin(1e-3));
}

TEST_CASE("kerf render, mesh, slice: an output that is a file the model reads is exit 2") {
    // A run never writes over its inputs: the textures and the mesh of the model stay as they
    // were, byte for byte, and nothing is written.
    TempDir dir;
    Image grey(2, 2, 3);
    for (float& v : grey.pixels) v = 0.5f;
    writeImage(grey, dir.file("grain.exr"));
    writeImage(grey, dir.file("paper.png"));
    dir.write("ball.obj",
              "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    dir.write("scene.kerf",
              texturedModel("grain.exr") +
                  "material paper { pattern image { file \"paper.png\" mapping planar } }\n"
                  "object mesh \"ball.obj\" translate <2, 0, 0> material paper;\n");
    const auto contents = [&] {
        return readFile(dir.file("grain.exr")) + readFile(dir.file("paper.png")) +
               readFile(dir.file("ball.obj"));
    };
    const std::string before = contents();
    const std::vector<std::vector<std::string>> runs = {
        {"render", "scene.kerf", "-o", "grain.exr"},
        {"render", "scene.kerf", "-o", "out.png", "--aov", "depth=./grain.exr"},
        {"mesh", "scene.kerf", "-o", "ball.obj", "--voxel", "0.1"},
        {"slice", "scene.kerf", "--plane", "z=0.25", "-o", "paper.png"}};
    for (const auto& args : runs) {
        const KerfRun run = runKerf(dir, args);
        INFO(args[0] << " " << args[3] << "\nstderr:\n" << run.err);
        CHECK(run.exitCode == kExitUsage);
        CHECK(run.err.find("is a file the model reads") != std::string::npos);
        CHECK(contents() == before);
        CHECK_FALSE(fs::exists(dir.path() / "out.png"));
    }
}
