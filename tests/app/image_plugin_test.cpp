// End-to-end tests of the image plug-in's loading: commands that write no image load no image
// library, and a missing plug-in is a clear error that leaves no file behind.
#include <catch2/catch.hpp>

#include "kerf_runner.h"

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
    SECTION("a render loads the plug-in and OpenImageIO") {
        const KerfRun run =
            runBinary(dir, "LD_DEBUG=files", KERF_BINARY, {"render", "ball.kerf", "-o", "b.png"});
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
    SECTION("render fails with a clear error and writes nothing") {
        const KerfRun run = runBinary(dir, "", kerf, {"render", "ball.kerf", "-o", "b.png"});
        CHECK(run.exitCode == 1);
        const std::string expected = "kerf: error: cannot load image support '" + plugin + "': ";
        CHECK(run.err.rfind(expected, 0) == 0);
        CHECK(run.err.find("No such file") != std::string::npos);
        CHECK(dir.listing() == std::vector<std::string>{"ball.kerf", "kerf"});
    }
    SECTION("a shared object without the entry point is refused") {
        fs::copy_file(KERF_SOME_SHARED_LIBRARY, plugin);
        const KerfRun run = runBinary(dir, "", kerf, {"render", "ball.kerf", "-o", "b.png"});
        CHECK(run.exitCode == 1);
        CHECK(run.err.rfind(
                  "kerf: error: cannot load image support '" + plugin + "': no entry point", 0) ==
              0);
        CHECK(!fs::exists(dir.file("b.png")));
    }
    SECTION("a file that is not a plug-in is refused the same way") {
        dir.write("kerf_image_plugin.so", "not a shared object");
        const KerfRun run = runBinary(dir, "", kerf, {"render", "ball.kerf", "-o", "b.png"});
        CHECK(run.exitCode == 1);
        CHECK(run.err.rfind("kerf: error: cannot load image support '" + plugin + "': ", 0) == 0);
        CHECK(!fs::exists(dir.file("b.png")));
    }
}
