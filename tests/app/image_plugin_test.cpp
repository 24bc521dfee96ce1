// End-to-end tests of the image plug-in's loading: commands that write no image, or only whole
// PNGs (io/png_write.h), load no image library, and a missing plug-in is a clear error that
// leaves no file behind.
#include <catch2/catch.hpp>

#include "io/image.h"
#include "kerf_runner.h"

#include <algorithm>

using namespace kerf::test;

namespace {

/// Runs `binary` with `args` in `cwd` under `environment` (e.g. "LD_DEBUG=files");
/// stdout and stderr captured as runKerf does.
KerfRun runBinary(const TempDir& cwd, const std::string& environment, const std::string& binary,
                  const std::vector<std::string>& args) {
    const std::string outPath = cwd.file(".stdout");
    const std::string errPath = cwd.file(".stderr");
    std::string command =
        "cd " + shellQuote(cwd.path().string()) + " && " + environment + " " + shellQuote(binary);
    for (const std::string& arg : args) command += " " + shellQuote(arg);
    command += " </dev/null >" + shellQuote(outPath) + " 2>" + shellQuote(errPath);
    const int status = std::system(command.c_str());
    KerfRun run;
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.out = readFile(outPath);
    run.err = readFile(errPath);
    fs::remove(outPath);
    fs::remove(errPath);
    return run;
}

const char* kModel = R"(object sphere { center <0, 0, 0> radius 1 };
camera { eye <0, 0, -5> look_at <0, 0, 0> fov 40 }
light point { at <-3, 4, -5> power 400 }
render { width 8 height 6 }
)";

}  // namespace

TEST_CASE("kerf --version, --help and check load no image library") {
    // The dynamic loader names every object it loads; OpenImageIO must not be among them.
    TempDir dir;
    dir.write("ball.kerf", kModel);
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"--version"}, {"--help"}, {"check", "ball.kerf"}}) {
        INFO(args.front());
        const KerfRun run = runBinary(dir, "LD_DEBUG=files", KERF_BINARY, args);
        CHECK(run.exitCode == 0);
        CHECK(run.err.find("file=") != std::string::npos);  // LD_DEBUG did report
        CHECK(run.err.find("OpenImageIO") == std::string::npos);
        CHECK(run.err.find("kerf_image_plugin") == std::string::npos);
    }
    SECTION("a PNG render loads neither: kerf encodes the PNG with libpng") {
        const KerfRun run =
            runBinary(dir, "LD_DEBUG=files", KERF_BINARY, {"render", "ball.kerf", "-o", "b.png"});
        CHECK(run.exitCode == 0);
        CHECK(run.err.find("file=") != std::string::npos);
        CHECK(run.err.find("kerf_image_plugin") == std::string::npos);
        CHECK(run.err.find("OpenImageIO") == std::string::npos);
        const kerf::Image image = kerf::readImage(dir.file("b.png"));
        CHECK(image.width == 8);
        CHECK(image.height == 6);
    }
    SECTION("a TIFF render loads the plug-in and OpenImageIO") {
        const KerfRun run =
            runBinary(dir, "LD_DEBUG=files", KERF_BINARY, {"render", "ball.kerf", "-o", "b.tif"});
        CHECK(run.exitCode == 0);
        CHECK(run.err.find("kerf_image_plugin") != std::string::npos);
        CHECK(run.err.find("OpenImageIO") != std::string::npos);
    }
}

TEST_CASE("kerf without its image plug-in") {
    // A copy of kerf in a folder without kerf_image_plugin.so.
    TempDir dir;
    dir.write("ball.kerf", kModel);
    const std::string kerf = dir.file("kerf");
    fs::copy_file(KERF_BINARY, kerf);
    const std::string plugin = dir.file("kerf_image_plugin.so");

    SECTION("check still works: it needs no image support") {
        const KerfRun run = runBinary(dir, "", kerf, {"check", "ball.kerf"});
        CHECK(run.exitCode == 0);
    }
    SECTION("a PNG render needs no plug-in") {
        const KerfRun run = runBinary(dir, "", kerf, {"render", "ball.kerf", "-o", "b.png"});
        CHECK(run.exitCode == 0);
        CHECK(fs::exists(dir.file("b.png")));
    }
    SECTION("render fails at once with the paths it tried and writes nothing") {
        const KerfRun run = runBinary(dir, "", kerf, {"render", "ball.kerf", "-o", "b.tif"});
        CHECK(run.exitCode == 2);
        const std::string installed =
            (dir.path().parent_path() / "lib" / "kerf" / "kerf_image_plugin.so").string();
        CHECK(run.err ==
              "kerf: error: cannot load image support: kerf_image_plugin.so is in none "
              "of the places kerf looks: '" +
                  plugin + "', '" + installed + "'\n");
        CHECK(dir.listing() == std::vector<std::string>{"ball.kerf", "kerf"});
    }
    SECTION("slice to TIFF checks too; slice to SVG or PNG needs no plug-in") {
        const std::vector<std::string> slice = {"slice", "ball.kerf", "--plane", "z=0", "-o"};
        std::vector<std::string> tif = slice, svg = slice, png = slice;
        tif.push_back("cut.tif");
        svg.push_back("cut.svg");
        png.push_back("cut.png");
        const KerfRun toTif = runBinary(dir, "", kerf, tif);
        CHECK(toTif.exitCode == 2);
        CHECK(toTif.err.find("is in none of the places kerf looks") != std::string::npos);
        CHECK(!fs::exists(dir.file("cut.tif")));
        CHECK(runBinary(dir, "", kerf, svg).exitCode == 0);
        CHECK(fs::exists(dir.file("cut.svg")));
        CHECK(runBinary(dir, "", kerf, png).exitCode == 0);
        CHECK(fs::exists(dir.file("cut.png")));
    }
    SECTION("a shared object without the entry point is refused") {
        fs::copy_file(KERF_SOME_SHARED_LIBRARY, plugin);
        const KerfRun run = runBinary(dir, "", kerf, {"render", "ball.kerf", "-o", "b.tif"});
        CHECK(run.exitCode == 2);
        CHECK(run.err.rfind(
                  "kerf: error: cannot load image support '" + plugin + "': no entry point", 0) ==
              0);
        CHECK(!fs::exists(dir.file("b.tif")));
    }
    SECTION("a file that is not a plug-in is refused the same way") {
        dir.write("kerf_image_plugin.so", "not a shared object");
        const KerfRun run = runBinary(dir, "", kerf, {"render", "ball.kerf", "-o", "b.tif"});
        CHECK(run.exitCode == 2);
        CHECK(run.err.rfind("kerf: error: cannot load image support '" + plugin + "': ", 0) == 0);
        CHECK(!fs::exists(dir.file("b.tif")));
    }
}

TEST_CASE("an installed kerf finds its plug-in in ../lib/kerf, wherever the prefix moves") {
    // The layout of `cmake --install build --prefix P`: P/bin/kerf, P/lib/kerf/the plug-in.
    TempDir dir;
    dir.write("ball.kerf", kModel);
    const fs::path first = dir.path() / "prefix";
    fs::create_directories(first / "bin");
    fs::create_directories(first / "lib" / "kerf");
    fs::copy_file(KERF_BINARY, first / "bin" / "kerf");
    fs::copy_file(KERF_IMAGE_PLUGIN, first / "lib" / "kerf" / "kerf_image_plugin.so");
    const fs::path moved = dir.path() / "elsewhere" / "kerf-0";
    fs::create_directories(moved.parent_path());
    fs::rename(first, moved);

    const KerfRun installed = runBinary(dir, "", (moved / "bin" / "kerf").string(),
                                        {"render", "ball.kerf", "-o", "installed.tif"});
    REQUIRE(installed.exitCode == 0);
    // The oracle: the build tree's kerf, which finds the plug-in beside itself.
    REQUIRE(runBinary(dir, "", KERF_BINARY, {"render", "ball.kerf", "-o", "built.tif"}).exitCode ==
            0);
    const kerf::Image got = kerf::readImage(dir.file("installed.tif"));
    const kerf::Image want = kerf::readImage(dir.file("built.tif"));
    REQUIRE(got.width == 8);
    REQUIRE(got.height == 6);
    REQUIRE(got.pixels.size() == want.pixels.size());
    CHECK(got.pixels == want.pixels);
    // The sphere fills the middle of the frame: lit there, not black.
    float middle = 0.0f;
    for (int c = 0; c < std::min(got.channels, 3); ++c) middle += got.at(4, 3, c);
    CHECK(middle > 0.0f);
}
