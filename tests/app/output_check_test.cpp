// Outputs that cannot be written are found before any work: a missing folder, a folder in the
// way, a path through a file, for the image and each AOV and the benchmark's tables; and a
// file name that is only an extension is refused with a clear message.
#include "kerf_runner.h"

#include <catch2/catch.hpp>

using namespace kerf::test;

namespace {

// A model with an error: if it were compiled, its diagnostic (exit 2) would come first. An
// output error instead shows the outputs were checked before the model was even read.
const char* kBrokenModel = "object sphere { radius -1 };\n";

}  // namespace

TEST_CASE("kerf render checks every output before any work") {
    TempDir dir;
    dir.write("tiny.kerf", kTinySphereModel);
    dir.write("broken.kerf", kBrokenModel);
    dir.write("notes.txt", "a file, not a folder\n");

    SECTION("the image's folder does not exist") {
        const KerfRun run = runKerf(dir, {"render", "broken.kerf", "-o", "out/x.png", "--stats"});
        CHECK(run.exitCode == 1);
        CHECK(run.err == "kerf: error: cannot write 'out/x.png': folder 'out' does not exist\n");
    }
    SECTION("a nested folder does not exist") {
        const KerfRun run = runKerf(dir, {"render", "broken.kerf", "-o", "a/b/x.exr"});
        CHECK(run.exitCode == 1);
        CHECK(run.err == "kerf: error: cannot write 'a/b/x.exr': folder 'a/b' does not exist\n");
    }
    SECTION("an AOV's folder does not exist") {
        const KerfRun run =
            runKerf(dir, {"render", "broken.kerf", "-o", "x.png", "--aov", "normal=maps/n.exr"});
        CHECK(run.exitCode == 1);
        CHECK(run.err == "kerf: error: cannot write 'maps/n.exr': folder 'maps' does not exist\n");
    }
    SECTION("the output is a folder") {
        fs::create_directory(dir.path() / "x.png");
        const KerfRun run = runKerf(dir, {"render", "broken.kerf", "-o", "x.png"});
        CHECK(run.exitCode == 1);
        CHECK(run.err == "kerf: error: cannot write 'x.png': it is a folder\n");
    }
    SECTION("the folder is a file") {
        const KerfRun run = runKerf(dir, {"render", "broken.kerf", "-o", "notes.txt/x.png"});
        CHECK(run.exitCode == 1);
        CHECK(run.err ==
              "kerf: error: cannot write 'notes.txt/x.png': 'notes.txt' is not a folder\n");
    }
    SECTION("nothing is written and nothing is left behind") {
        runKerf(dir, {"render", "tiny.kerf", "-o", "out/x.png", "--aov", "depth=d.exr"});
        CHECK(dir.listing() == std::vector<std::string>{"broken.kerf", "notes.txt", "tiny.kerf"});
    }
}

TEST_CASE("kerf render: an output name that is only an extension") {
    TempDir dir;
    dir.write("tiny.kerf", kTinySphereModel);
    SECTION("-o .png") {
        const KerfRun run = runKerf(dir, {"render", "tiny.kerf", "-o", ".png"});
        CHECK(run.exitCode == 2);
        CHECK(run.err == "kerf: error: -o: output '.png' has no file name before the extension\n");
    }
    SECTION("-o out/.JPG") {
        fs::create_directory(dir.path() / "out");
        const KerfRun run = runKerf(dir, {"render", "tiny.kerf", "-o", "out/.JPG"});
        CHECK(run.exitCode == 2);
        CHECK(run.err ==
              "kerf: error: -o: output 'out/.JPG' has no file name before the extension\n");
    }
    SECTION("--aov depth=.exr") {
        const KerfRun run = runKerf(dir, {"render", "tiny.kerf", "--aov", "depth=.exr"});
        CHECK(run.exitCode == 2);
        CHECK(run.err ==
              "kerf: error: --aov depth: output '.exr' has no file name before the extension\n");
    }
    SECTION("a hidden file with a name is fine") {
        const KerfRun run = runKerf(dir, {"render", "tiny.kerf", "-q", "-o", ".hidden.png"});
        CHECK(run.exitCode == 0);
        CHECK(fs::exists(dir.path() / ".hidden.png"));
    }
}

TEST_CASE("kerf bench accuracy checks its tables before the run") {
    TempDir dir;
    fs::create_directories(dir.path() / "out" / "accuracy.svg");  // a folder in the way
    const std::string sceneDir = (fs::path(KERF_SOURCE_DIR) / "accuracy" / "scenes").string();
    const KerfRun run = runKerf(dir, {"bench", "accuracy", "--quick", "--out", "out", "--scene-dir",
                                      sceneDir, "--scenes", "sphere"});
    INFO("stderr:\n" << run.err);
    CHECK(run.exitCode == 1);
    // Only the error: the run announces itself ("kerf bench accuracy: 1 scenes …") first.
    CHECK(run.err == "kerf: error: cannot write 'out/accuracy.svg': it is a folder\n");
}
