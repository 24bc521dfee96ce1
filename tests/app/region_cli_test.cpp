// `kerf render --region`, `kerf assemble` and `kerf-mpi render` (issue 15 §1, §3): region
// parts stitched together and the MPI render equal the single full render bit for bit; a bad
// region, a missing or overlapping part are clear errors with exit code 2.
#include "io/image.h"
#include "kerf_runner.h"

#include <catch2/catch.hpp>

#include <cstring>
#include <string>
#include <vector>

#include <unistd.h>

using namespace kerf;
using namespace kerf::test;

namespace {

/// A lit scene whose pixels all differ a little (shading, a shadow, an edge per tile row).
const char* kModel =
    R"(material clay { color <0.8, 0.5, 0.3> ambient 0.1 diffuse 0.8 specular 0.3 shininess 20 }
material blue { color <0.4, 0.6, 0.8> diffuse 0.9 }
object sphere { center <0, 0, 0> radius 1 } material clay;
object box { min <-3, -1.4, -3> max <3, -1, 3> } material blue;
camera { eye <0.5, 1, -5> look_at <0, 0, 0> up <0, 1, 0> fov 40 }
light point { at <4, 6, -6> color <1, 1, 1> power 100 }
render { width 45 height 34 spp 4 }
)";

bool sameBits(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.channels == b.channels &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

/// Renders the four quarters of the image, split at (21, 13), none aligned to the tiles.
std::vector<std::string> renderQuarters(const TempDir& dir, const std::vector<std::string>& extra) {
    std::vector<std::string> parts;
    for (const char* region : {"0,0,21,13", "21,0,45,13", "0,13,21,34", "21,13,45,34"}) {
        const std::string name = std::string("part_") + region + ".exr";
        std::vector<std::string> args{"render", "m.kerf", "-q", "--region", region, "-o", name};
        args.insert(args.end(), extra.begin(), extra.end());
        const KerfRun run = runKerf(dir, args);
        REQUIRE(run.exitCode == 0);
        parts.push_back(name);
    }
    return parts;
}

}  // namespace

TEST_CASE("kerf render --region: an EXR whose data window is the region") {
    TempDir dir;
    dir.write("m.kerf", kModel);
    REQUIRE(
        runKerf(dir, {"render", "m.kerf", "-q", "--region", "3,5,20,9", "-o", "r.exr"}).exitCode ==
        0);
    ImageWindow window;
    const Image part = readImage(dir.file("r.exr"), window);
    CHECK(part.width == 17);
    CHECK(part.height == 4);
    CHECK(window.x == 3);
    CHECK(window.y == 5);
    CHECK(window.fullWidth == 45);
    CHECK(window.fullHeight == 34);
}

TEST_CASE("kerf assemble: four region parts make the full render, bit for bit") {
    for (const char* filter : {"box", "mitchell"}) {
        CAPTURE(filter);
        TempDir dir;
        dir.write("m.kerf", kModel);
        const std::vector<std::string> options{"--filter", filter, "--aov", "depth=d.exr"};
        std::vector<std::string> full{"render", "m.kerf", "-q", "-o", "full.exr"};
        full.insert(full.end(), options.begin(), options.end());
        REQUIRE(runKerf(dir, full).exitCode == 0);
        std::vector<std::string> assemble{"assemble", "whole.exr"};
        for (const std::string& p : renderQuarters(dir, {"--filter", filter}))
            assemble.push_back(p);
        const KerfRun run = runKerf(dir, assemble);
        INFO(run.err);
        REQUIRE(run.exitCode == 0);
        CHECK(sameBits(readImage(dir.file("whole.exr")), readImage(dir.file("full.exr"))));
    }
}

TEST_CASE("kerf assemble: missing and overlapping parts are errors naming them") {
    TempDir dir;
    dir.write("m.kerf", kModel);
    const std::vector<std::string> parts = renderQuarters(dir, {});
    SECTION("a part missing") {
        const KerfRun run = runKerf(dir, {"assemble", "whole.exr", parts[0], parts[1], parts[3]});
        CHECK(run.exitCode == 2);
        CHECK(run.err.find("missing pixels 0,13,21,34") != std::string::npos);
        CHECK(!fs::exists(dir.file("whole.exr")));
    }
    SECTION("two parts overlap") {
        REQUIRE(
            runKerf(dir, {"render", "m.kerf", "-q", "--region", "15,10,30,20", "-o", "extra.exr"})
                .exitCode == 0);
        std::vector<std::string> args{"assemble", "whole.exr"};
        args.insert(args.end(), parts.begin(), parts.end());
        args.push_back("extra.exr");
        const KerfRun run = runKerf(dir, args);
        CHECK(run.exitCode == 2);
        CHECK(run.err.find("'part_0,0,21,13.exr' (pixels 0,0,21,13) and 'extra.exr' (pixels "
                           "15,10,30,20) overlap in 15,10,21,13") != std::string::npos);
    }
    SECTION("parts of different images") {
        REQUIRE(runKerf(dir, {"render", "m.kerf", "-q", "--width", "46", "--region", "0,0,21,13",
                              "-o", "other.exr"})
                    .exitCode == 0);
        const KerfRun run =
            runKerf(dir, {"assemble", "whole.exr", "other.exr", parts[1], parts[2], parts[3]});
        CHECK(run.exitCode == 2);
        CHECK(run.err.find("parts of different images") != std::string::npos);
    }
    SECTION("a PNG part, which holds no place") {
        REQUIRE(runKerf(dir, {"render", "m.kerf", "-q", "--region", "0,0,21,13", "-o", "p.png"})
                    .exitCode == 0);
        const KerfRun run =
            runKerf(dir, {"assemble", "whole.exr", "p.png", parts[1], parts[2], parts[3]});
        CHECK(run.exitCode == 2);
        CHECK(run.err.find("'p.png'") != std::string::npos);
    }
    SECTION("the output is one of the parts") {
        const std::string before = readFile(dir.file(parts[0]));
        const KerfRun run =
            runKerf(dir, {"assemble", parts[0], parts[0], parts[1], parts[2], parts[3]});
        CHECK(run.exitCode == 2);
        CHECK(readFile(dir.file(parts[0])) == before);
    }
}

TEST_CASE("kerf render --region: a bad region is an error naming --region") {
    TempDir dir;
    dir.write("m.kerf", kModel);
    for (const char* region : {"0,0,46,10", "0,0,10,35", "5,5,5,9", "9,5,4,7", "1,2,3", "1,2,3,4,5",
                               "a,0,3,3", "-1,0,3,3", ""}) {
        CAPTURE(region);
        const KerfRun run =
            runKerf(dir, {"render", "m.kerf", "-q", "--region", region, "-o", "r.exr"});
        CHECK(run.exitCode == 2);
        CHECK(run.err.find("--region") != std::string::npos);
        CHECK(!fs::exists(dir.file("r.exr")));
    }
}

#ifdef KERF_MPI_BINARY
namespace {

KerfRun runMpi(const TempDir& dir, const std::vector<std::string>& args) {
    // Open MPI's runtime leaks at MPI_Finalize from components it loaded with dlopen, whose
    // frames LeakSanitizer cannot name for a suppression: leak checking is off for the ranks
    // under the sanitizer build (kerf-mpi's own code is kerf's, checked by the other tests).
    std::string command = "cd " + shellQuote(dir.path().string()) + " && " +
                          "ASAN_OPTIONS=\"${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0\" " +
                          shellQuote(KERF_MPIEXEC) + " -x ASAN_OPTIONS -n 2 --oversubscribe" +
                          (::geteuid() == 0 ? " --allow-run-as-root" : "") + " " +
                          shellQuote(KERF_MPI_BINARY);
    for (const std::string& arg : args) command += " " + shellQuote(arg);
    command += " </dev/null >.mpi_out 2>.mpi_err";
    const int status = std::system(command.c_str());
    KerfRun run;
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.out = readFile(dir.file(".mpi_out"));
    run.err = readFile(dir.file(".mpi_err"));
    return run;
}

}  // namespace

TEST_CASE("kerf-mpi render on 2 ranks: the same image as kerf render, bit for bit") {
    for (const char* filter : {"box", "gaussian"}) {
        CAPTURE(filter);
        TempDir dir;
        dir.write("m.kerf", kModel);
        const std::vector<std::string> common{"m.kerf",   "-q",   "--threads", "1",
                                              "--filter", filter, "--aov",     "normal=n.exr"};
        std::vector<std::string> one{"render", "-o", "one.exr"}, two{"render", "-o", "two.exr"};
        one.insert(one.end(), common.begin(), common.end());
        two.insert(two.end(), common.begin(), common.end());
        REQUIRE(runKerf(dir, one).exitCode == 0);
        const Image normalOne = readImage(dir.file("n.exr"));
        const KerfRun run = runMpi(dir, two);
        INFO(run.err);
        REQUIRE(run.exitCode == 0);
        CHECK(sameBits(readImage(dir.file("one.exr")), readImage(dir.file("two.exr"))));
        CHECK(sameBits(normalOne, readImage(dir.file("n.exr"))));
    }
}

TEST_CASE("kerf-mpi render --frames: each frame the same as kerf render's, bit for bit") {
    // A sphere growing with the frame: the two frames differ, and each equals the single-
    // process render of it.
    TempDir dir;
    dir.write("grow.kerf",
              "object sphere { center <0, 0, 0> radius 1 + 0.1 * frame };\n"
              "camera { eye <0, 0, -5> look_at <0, 0, 0> fov 40 }\n"
              "light point { at <-2, 5, -3> power 400 }\n"
              "render { width 40 height 30 }\n");
    REQUIRE(runKerf(dir, {"render", "grow.kerf", "-q", "--frames", "1-2", "-o", "one_%d.exr"})
                .exitCode == 0);
    const KerfRun run =
        runMpi(dir, {"render", "grow.kerf", "-q", "--frames", "1-2", "-o", "two_%d.exr"});
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    CHECK(sameBits(readImage(dir.file("one_1.exr")), readImage(dir.file("two_1.exr"))));
    CHECK(sameBits(readImage(dir.file("one_2.exr")), readImage(dir.file("two_2.exr"))));
    CHECK_FALSE(sameBits(readImage(dir.file("two_1.exr")), readImage(dir.file("two_2.exr"))));
}

TEST_CASE("kerf-mpi slice --stack: the layers shared out, the files those of kerf slice") {
    TempDir dir;
    dir.write("m.kerf", kModel);
    REQUIRE(
        runKerf(dir, {"slice", "m.kerf", "-q", "--stack", "y=-0.8:0.8:0.2", "-o", "one_%02d.svg"})
            .exitCode == 0);
    const KerfRun run =
        runMpi(dir, {"slice", "m.kerf", "-q", "--stack", "y=-0.8:0.8:0.2", "-o", "two_%02d.svg"});
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    int layers = 0;
    for (int i = 0; i <= 8; ++i) {
        char one[32], two[32];
        std::snprintf(one, sizeof one, "one_%02d.svg", i);
        std::snprintf(two, sizeof two, "two_%02d.svg", i);
        REQUIRE(fs::exists(dir.file(two)));
        CHECK(readFile(dir.file(one)) == readFile(dir.file(two)));
        ++layers;
    }
    CHECK(layers == 9);
    CHECK(!fs::exists(dir.file("two_09.svg")));
}

TEST_CASE("kerf-mpi render: a bad model stops every rank with exit 2, reported once") {
    TempDir dir;
    dir.write("bad.kerf", "object sphere { center <0, 0, 0> radius };\n");
    const KerfRun run = runMpi(dir, {"render", "bad.kerf", "-o", "x.png"});
    CHECK(run.exitCode == 2);
    const size_t first = run.err.find("bad.kerf:1:");
    REQUIRE(first != std::string::npos);
    CHECK(run.err.find("bad.kerf:1:", first + 1) == std::string::npos);
    CHECK(!fs::exists(dir.file("x.png")));
}
#endif
