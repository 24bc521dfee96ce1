// End-to-end tests of `kerf render`'s reporting: --stats values against hand counts, the
// progress bar only on a terminal, and the same pixels whatever --threads.
#include "kerf_runner.h"

#include "io/image.h"

#include <catch2/catch.hpp>

#include <regex>

using namespace kerf::test;

namespace {

// No mirror and no glass: no reflection or refraction rays.
const char* kMatteModel = R"(material red { color <0.9, 0.2, 0.1> }
object sphere { center <0, 0, 0> radius 1 } material red;
camera { eye <0, 0, -5> look_at <0, 0, 0> up <0, 1, 0> fov 40 }
light point { at <-3, 4, -5> color <1, 1, 1> power 400 }
render { width 20 height 10 spp 1 }
)";

/// The value printed after `label` in the --stats report.
std::string statsValue(const std::string& text, const std::string& label) {
    std::smatch match;
    if (!std::regex_search(text, match, std::regex("\\n\\s*" + label + "\\s+([^\\n]*)\\n"))) {
        return "<absent>";
    }
    return match[1].str();
}

/// Runs kerf with a pseudo-terminal on every stream through util-linux script(1), which
/// copies the terminal's output to its stdout; `out` is that transcript.
KerfRun runOnTerminal(const TempDir& dir, const std::string& kerfArgs) {
    const std::string transcript = dir.file(".transcript");
    const std::string command = "cd " + shellQuote(dir.path().string()) + " && script -qec " +
                                shellQuote(shellQuote(KERF_BINARY) + " " + kerfArgs) +
                                " /dev/null </dev/null >" + shellQuote(transcript) + " 2>&1";
    const int status = std::system(command.c_str());
    KerfRun run;
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.out = readFile(transcript);
    fs::remove(transcript);
    return run;
}

}  // namespace

TEST_CASE("kerf render --stats") {
    TempDir dir;
    dir.write("matte.kerf", kMatteModel);
    const KerfRun run = runKerf(dir, {"render", "matte.kerf", "-o", "m.png", "--stats", "--spp",
                                      "4", "--threads", "2", "--tolerance", "1e-6"});
    INFO("stderr:\n" << run.err);
    REQUIRE(run.exitCode == 0);
    CHECK(statsValue(run.err, "image") == "20 x 10");
    CHECK(statsValue(run.err, "samples per pixel") == "4, jittered, box filter");
    CHECK(statsValue(run.err, "threads") == "2");
    CHECK(statsValue(run.err, "tolerance") == "1e-06 (relative)");
    // spp 4: 4 camera rays per pixel.
    CHECK(statsValue(run.err, "camera rays") == std::to_string(20 * 10 * 4));
    CHECK(statsValue(run.err, "reflection rays") == "0");
    CHECK(statsValue(run.err, "refraction rays") == "0");
    for (const char* label : {"shadow rays", "primitive tests", "bounds tests", "root-finder steps",
                              "interval evaluations", "parse \\+ compile", "setup", "trace",
                              "write", "rays per second"}) {
        CHECK(statsValue(run.err, label) != "<absent>");
    }
}

TEST_CASE("kerf render --stats: samples per pixel as traced") {
    // spp means what it says: exactly that many samples (and camera rays) per pixel, placed
    // by the sampler the report names.
    TempDir dir;
    dir.write("matte.kerf", kMatteModel);
    struct Case {
        const char* spp;
        const char* sampler;
        const char* printed;
        int traced;
    };
    for (const Case& c : {Case{"5", "", "5, jittered, box filter", 5},
                          Case{"9", "lattice", "9, lattice, box filter", 9},
                          Case{"2", "random", "2, random, box filter", 2},
                          Case{"1", "regular", "1, regular, box filter", 1}}) {
        INFO("--spp " << c.spp << " --sampler " << c.sampler);
        std::vector<std::string> args{"render",  "matte.kerf", "-o", "m.png",
                                      "--stats", "--spp",      c.spp};
        if (*c.sampler) args.insert(args.end(), {"--sampler", c.sampler});
        const KerfRun run = runKerf(dir, args);
        REQUIRE(run.exitCode == 0);
        CHECK(statsValue(run.err, "samples per pixel") == c.printed);
        CHECK(statsValue(run.err, "camera rays") == std::to_string(20 * 10 * c.traced));
    }
    SECTION("the model's render { spp } when no --spp is given") {
        std::string model = kMatteModel;
        model.replace(model.find("spp 1"), 5, "spp 3");
        dir.write("spp3.kerf", model);
        const KerfRun run = runKerf(dir, {"render", "spp3.kerf", "-o", "m.png", "--stats"});
        REQUIRE(run.exitCode == 0);
        CHECK(statsValue(run.err, "samples per pixel") == "3, jittered, box filter");
    }
    SECTION("an unknown sampler is a usage error") {
        const KerfRun run =
            runKerf(dir, {"render", "matte.kerf", "-o", "m.png", "--sampler", "sobol"});
        CHECK(run.exitCode == 2);
        CHECK(
            run.err.find("--sampler must be regular, random, jittered or lattice (got 'sobol')") !=
            std::string::npos);
    }
}

TEST_CASE("kerf render: progress only on a terminal") {
    TempDir dir;
    dir.write("matte.kerf", kMatteModel);
    SECTION("stderr redirected to a file: silent") {
        const KerfRun run = runKerf(dir, {"render", "matte.kerf", "-o", "m.png"});
        CHECK(run.exitCode == 0);
        CHECK(run.err.empty());
        CHECK(run.out.empty());
    }
    SECTION("stderr on a pseudo-terminal: a bar redrawn with '\\r', unless --quiet") {
        const KerfRun bar = runOnTerminal(dir, "render matte.kerf -o t.png");
        INFO("terminal transcript:\n" << bar.out);
        REQUIRE(bar.exitCode == 0);
        CHECK(bar.out.find('\r') != std::string::npos);
        CHECK(bar.out.find("100%") != std::string::npos);
        CHECK(bar.out.find("left") != std::string::npos);

        const KerfRun quiet = runOnTerminal(dir, "render matte.kerf -o q.png --quiet");
        CHECK(quiet.exitCode == 0);
        CHECK(quiet.out.find('%') == std::string::npos);
    }
}

TEST_CASE("kerf render: the same pixels whatever --threads") {
    TempDir dir;
    const std::string model = (modelsDir() / "glass.kerf").string();
    for (const char* threads : {"1", "3"}) {
        const KerfRun run =
            runKerf(dir, {"render", model, "--width", "48", "--height", "36", "--spp", "4",
                          "--threads", threads, "-o", std::string("t") + threads + ".exr"});
        REQUIRE(run.exitCode == 0);
    }
    const kerf::Image one = kerf::readImage(dir.file("t1.exr"));
    REQUIRE(one.width == 48);
    CHECK(kerf::readImage(dir.file("t3.exr")).pixels == one.pixels);
}
