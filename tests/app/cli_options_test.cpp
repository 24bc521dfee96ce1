// End-to-end tests of `kerf render` option handling: usage errors exit 2 with a message that
// names the option, and never write anything; flags override the model's render block.
#include "kerf_runner.h"

#include "io/image.h"

#include <catch2/catch.hpp>

#include <regex>

using namespace kerf::test;

namespace {

const char* kTinyModel = R"(material red { color <0.9, 0.2, 0.1> }
object sphere { center <0, 0, 0> radius 1 } material red;
camera { eye <0, 0, -5> look_at <0, 0, 0> up <0, 1, 0> fov 40 }
light point { at <-3, 4, -5> color <1, 1, 1> power 400 }
render { width 20 height 10 spp 1 }
)";

/// Runs `kerf render tiny.kerf <extra…>` and checks a usage error naming `option`.
void requireUsageError(const std::vector<std::string>& extra, const std::string& option) {
    TempDir dir;
    dir.write("tiny.kerf", kTinyModel);
    std::vector<std::string> args{"render", "tiny.kerf", "--quiet"};
    args.insert(args.end(), extra.begin(), extra.end());
    if (std::find(extra.begin(), extra.end(), "-o") == extra.end()) {
        args.insert(args.end(), {"-o", "out.png"});
    }
    const KerfRun run = runKerf(dir, args);
    INFO("stderr: " << run.err);
    CHECK(run.exitCode == 2);
    CHECK(run.err.find("kerf: error:") != std::string::npos);
    CHECK(run.err.find(option) != std::string::npos);
    // Nothing was rendered or written.
    CHECK(dir.listing() == std::vector<std::string>{"tiny.kerf"});
}

}  // namespace

TEST_CASE("kerf render: numeric option ranges") {
    SECTION("--width 0") { requireUsageError({"--width", "0"}, "--width"); }
    SECTION("--height -3") { requireUsageError({"--height=-3"}, "--height"); }
    SECTION("--spp 0") { requireUsageError({"--spp", "0"}, "--spp"); }
    SECTION("--threads -1") { requireUsageError({"--threads=-1"}, "--threads"); }
    // 70,000 crashed inside TBB's thread creation (issue 24); the limit is scene/limits.h's.
    SECTION("--threads 70000") {
        requireUsageError({"--threads=70000"}, "--threads must be at most 4096 (got 70000)");
    }
    SECTION("--tolerance 0") { requireUsageError({"--tolerance", "0"}, "--tolerance"); }
    SECTION("--tolerance 1") { requireUsageError({"--tolerance", "1"}, "--tolerance"); }
    SECTION("--tolerance -1e-3") { requireUsageError({"--tolerance=-1e-3"}, "--tolerance"); }
    SECTION("--width not a number") { requireUsageError({"--width", "wide"}, "--width"); }
}

TEST_CASE("kerf render: --method names") {
    SECTION("unknown") { requireUsageError({"--method", "bogus"}, "--method"); }
    SECTION("misspelt") { requireUsageError({"--method", "sphere_trace"}, "--method"); }
}

TEST_CASE("kerf render: --accel names and depths") {
    SECTION("unknown") { requireUsageError({"--accel", "kdtree"}, "--accel"); }
    SECTION("depth too deep") { requireUsageError({"--accel-depth", "11"}, "--accel-depth"); }
    SECTION("depth below a brick") { requireUsageError({"--accel-depth", "2"}, "--accel-depth"); }
    SECTION("negative depth") { requireUsageError({"--accel-depth=-1"}, "--accel-depth"); }
}

TEST_CASE("kerf render: --aov specifications") {
    SECTION("unknown kind") { requireUsageError({"--aov", "albedo=a.exr"}, "albedo"); }
    SECTION("no '='") { requireUsageError({"--aov", "depth.exr"}, "--aov"); }
    SECTION("no file") { requireUsageError({"--aov", "depth="}, "--aov depth"); }
    SECTION("8-bit format") { requireUsageError({"--aov", "depth=d.png"}, "--aov depth"); }
    SECTION("same kind twice") {
        requireUsageError({"--aov", "depth=a.exr", "--aov", "depth=b.exr"}, "--aov depth");
    }
    SECTION("two AOVs into one file") {
        requireUsageError({"--aov", "depth=a.exr", "--aov", "normal=./a.exr"}, "--aov normal");
    }
    SECTION("AOV into the colour output") {
        requireUsageError({"-o", "x.exr", "--aov", "depth=x.exr"}, "--aov depth");
    }
}

TEST_CASE("kerf render: never writes over its input") {
    TempDir dir;
    const std::string model = dir.write("scene.kerf", kTinyModel);
    fs::create_directories(dir.path() / "sub");
    fs::create_symlink(model, dir.path() / "link.png");
    // The same file named four ways, and through a symbolic link.
    for (const std::string& out :
         {std::string("scene.kerf"), std::string("./scene.kerf"), dir.file("scene.kerf"),
          std::string("sub/../scene.kerf"), std::string("link.png")}) {
        INFO("-o " << out);
        const KerfRun run = runKerf(dir, {"render", "scene.kerf", "-o", out});
        CHECK(run.exitCode == 2);
        CHECK(run.err.find("kerf: error: -o: ") != std::string::npos);
        CHECK(readFile(model) == kTinyModel);
        CHECK(fs::is_symlink(dir.path() / "link.png"));
    }
}

TEST_CASE("kerf render: unknown output format") { requireUsageError({"-o", "picture.bmpx"}, "-o"); }

TEST_CASE("kerf: command-line structure errors") {
    TempDir dir;
    dir.write("tiny.kerf", kTinyModel);
    SECTION("no subcommand") { CHECK(runKerf(dir, {}).exitCode == 2); }
    SECTION("unknown subcommand") { CHECK(runKerf(dir, {"draw", "tiny.kerf"}).exitCode == 2); }
    SECTION("unknown option") {
        const KerfRun run = runKerf(dir, {"render", "tiny.kerf", "--colour", "red"});
        CHECK(run.exitCode == 2);
        CHECK(run.err.find("--colour") != std::string::npos);
    }
    SECTION("missing model") {
        const KerfRun run = runKerf(dir, {"render"});
        CHECK(run.exitCode == 2);
        CHECK(run.err.find("FILE") != std::string::npos);
    }
}

TEST_CASE("kerf: --help and --version") {
    TempDir dir;
    const KerfRun version = runKerf(dir, {"--version"});
    CHECK(version.exitCode == 0);
    // The version is the project's, as declared in the top-level CMakeLists.txt.
    const std::string cmake = readFile(KERF_SOURCE_DIR "/CMakeLists.txt");
    std::smatch match;
    REQUIRE(std::regex_search(cmake, match, std::regex(R"(project\(kerf VERSION ([0-9.]+))")));
    CHECK(version.out == "kerf " + match[1].str() + "\n");

    const KerfRun help = runKerf(dir, {"--help"});
    CHECK(help.exitCode == 0);
    CHECK(help.out.find("render") != std::string::npos);
    CHECK(help.out.find("check") != std::string::npos);

    const KerfRun renderHelp = runKerf(dir, {"render", "--help"});
    CHECK(renderHelp.exitCode == 0);
    for (const char* flag : {"--width", "--height", "--spp", "--threads", "--tolerance", "--aov",
                             "--stats", "--quiet", "-o"}) {
        CHECK(renderHelp.out.find(flag) != std::string::npos);
    }
}

TEST_CASE("kerf render: flags override the render block, 0 flags take it") {
    TempDir dir;
    dir.write("tiny.kerf", kTinyModel);
    SECTION("the model's size when no flag is given, default output name here") {
        dir.write("models/deep/tiny2.kerf", kTinyModel);
        const KerfRun run = runKerf(dir, {"render", "models/deep/tiny2.kerf"});
        REQUIRE(run.exitCode == 0);
        CHECK(run.err.empty());  // stderr is not a terminal: no progress bar
        const kerf::Image image = kerf::readImage(dir.file("tiny2.png"));
        CHECK(image.width == 20);
        CHECK(image.height == 10);
    }
    SECTION("--width and --height override") {
        const KerfRun run =
            runKerf(dir, {"render", "tiny.kerf", "--width", "13", "--height", "7", "-o", "o.png"});
        REQUIRE(run.exitCode == 0);
        const kerf::Image image = kerf::readImage(dir.file("o.png"));
        CHECK(image.width == 13);
        CHECK(image.height == 7);
    }
}
