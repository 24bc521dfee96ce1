// `kerf slice --stack … --layers A-B`: a farm's parts of a stack are the same files, byte for
// byte, as the same layers of the full stack, with the same numbers; bad ranges are refused
// with exit code 2 before anything is written.
#include "app/kerf_runner.h"

#include <catch2/catch.hpp>

using namespace kerf::test;

namespace {
// Off-centre and cut by a box, so that every layer's section is different.
const char* kModel =
    "object difference { sphere { center <0.1, 0, 0> radius 1 } box { min <0, 0, -2> max <2, 2, "
    "0.3> } };\n";
}  // namespace

TEST_CASE("kerf slice --layers parts equal the same layers of the full stack byte for byte") {
    for (const char* ext : {"svg", "png"}) {
        TempDir dir;
        dir.write("m.kerf", kModel);
        const std::string stack = "z=-0.9:0.9:0.2";  // layers 0 to 9
        const std::vector<std::string> size = std::string(ext) == "png"
                                                  ? std::vector<std::string>{"--width", "64"}
                                                  : std::vector<std::string>{};
        auto slice = [&](const std::string& prefix, const std::vector<std::string>& extra) {
            std::vector<std::string> args{
                "slice", "m.kerf", "--stack", stack, "-o", prefix + "_%02d." + ext, "-q"};
            args.insert(args.end(), size.begin(), size.end());
            args.insert(args.end(), extra.begin(), extra.end());
            const KerfRun run = runKerf(dir, args);
            INFO(run.err);
            REQUIRE(run.exitCode == 0);
        };
        slice("full", {});
        slice("part", {"--layers", "0-3"});
        slice("part", {"--layers", "4-8"});
        slice("part", {"--layers", "9"});
        INFO(ext);
        for (int i = 0; i < 10; ++i) {
            char name[32];
            std::snprintf(name, sizeof name, "_%02d.%s", i, ext);
            INFO("layer " << i);
            const std::string full = readFile(dir.file(std::string("full") + name));
            REQUIRE(!full.empty());
            CHECK(full == readFile(dir.file(std::string("part") + name)));
        }
        CHECK(readFile(dir.file(std::string("full_03.") + ext)) !=
              readFile(dir.file(std::string("full_04.") + ext)));
        CHECK(dir.listing().size() == 21);  // the model and 10 + 10 layers: no other file
    }
}

TEST_CASE("kerf slice --layers refuses bad ranges with exit code 2") {
    TempDir dir;
    dir.write("m.kerf", kModel);
    struct Case {
        std::vector<std::string> args;
        std::string says;
    };
    const std::vector<Case> cases = {
        {{"--stack", "z=-0.9:0.9:0.2", "--layers", "5-10"}, "has layers 0 to 9"},
        {{"--stack", "z=-0.9:0.9:0.2", "--layers", "10"}, "has layers 0 to 9"},
        {{"--stack", "z=-0.9:0.9:0.2", "--layers", "4-2"}, "is empty"},
        {{"--stack", "z=-0.9:0.9:0.2", "--layers", "-3"}, "--layers expects A-B or N"},
        {{"--stack", "z=-0.9:0.9:0.2", "--layers", ""}, "--layers expects A-B or N"},
        {{"--plane", "z=0", "--layers", "1"}, "--layers goes with --stack"},
    };
    for (const Case& c : cases) {
        std::vector<std::string> args{"slice", "m.kerf", "-o", "c_%02d.svg"};
        args.insert(args.end(), c.args.begin(), c.args.end());
        const KerfRun run = runKerf(dir, args);
        INFO(c.args[0] << " " << c.args[1] << "\nstderr: " << run.err);
        CHECK(run.exitCode == 2);
        CHECK(run.err.find(c.says) != std::string::npos);
        CHECK(dir.listing() == std::vector<std::string>{"m.kerf"});
    }
}

// Issue 24: the value was printed by std::to_string, so 1e-300 read "got 0.000000".
TEST_CASE("kerf slice --tolerance below what doubles resolve names the value as given") {
    TempDir dir;
    dir.write("m.kerf", kModel);
    const KerfRun run =
        runKerf(dir, {"slice", "m.kerf", "-o", "c.svg", "--plane", "z=0", "--tolerance", "1e-300"});
    INFO("stderr: " << run.err);
    CHECK(run.exitCode == 2);
    CHECK(run.err.find("at least 1e-13 (finer than doubles resolve; got 1e-300)") !=
          std::string::npos);
    CHECK(dir.listing() == std::vector<std::string>{"m.kerf"});
}
