// End-to-end tests of `kerf render --section`: the option gives the same image as the model's
// own section block, and bad planes are usage errors that name the option and write nothing.
#include "kerf_runner.h"

#include <catch2/catch.hpp>

using namespace kerf::test;

namespace {

const std::string kModel = R"(material clay { color <0.8, 0.5, 0.3> }
object sphere { center <0, 0, 0> radius 1 } material clay;
camera { eye <2, 3, 6> look_at <0, 0, 0> up <0, 1, 0> fov 40 }
light point { at <3, 6, 4> power 400 }
render { width 24 height 16 spp 1 }
)";

void requireSectionError(const std::vector<std::string>& extra, const std::string& message) {
    TempDir dir;
    dir.write("m.kerf", kModel);
    std::vector<std::string> args{"render", "m.kerf", "--quiet", "-o", "out.png"};
    args.insert(args.end(), extra.begin(), extra.end());
    const KerfRun run = runKerf(dir, args);
    INFO("stderr: " << run.err);
    CHECK(run.exitCode == 2);
    CHECK(run.err.find("kerf: error:") != std::string::npos);
    CHECK(run.err.find(message) != std::string::npos);
    CHECK(dir.listing() == std::vector<std::string>{"m.kerf"});
}

}  // namespace

TEST_CASE("kerf render --section: the same image as the model's section block") {
    TempDir dir;
    dir.write("m.kerf", kModel);
    dir.write("cut.kerf",
              kModel +
                  "section { point <0, 0, 0.25> normal <0, 0, 1> color <0.2, 0.4, 0.9> }\n"
                  "section { point <0.1, 0, 0> normal <1, 1, 0> color <0.2, 0.4, 0.9> }\n");
    const KerfRun a =
        runKerf(dir, {"render", "m.kerf", "--quiet", "-o", "a.png", "--section", "z=0.25",
                      "--section", "0.1,0,0:1,1,0", "--section-color", "0.2,0.4,0.9"});
    const KerfRun b = runKerf(dir, {"render", "cut.kerf", "--quiet", "-o", "b.png"});
    const KerfRun plain = runKerf(dir, {"render", "m.kerf", "--quiet", "-o", "plain.png"});
    INFO(a.err << b.err << plain.err);
    REQUIRE(a.exitCode == 0);
    REQUIRE(b.exitCode == 0);
    REQUIRE(plain.exitCode == 0);
    CHECK(readFile(dir.file("a.png")) == readFile(dir.file("b.png")));
    CHECK(readFile(dir.file("a.png")) != readFile(dir.file("plain.png")));  // the cut shows

    // A plane beyond the sphere leaves it untouched: the same bytes as no section.
    REQUIRE(runKerf(dir, {"render", "m.kerf", "--quiet", "-o", "c.png", "--section", "y=1.5"})
                .exitCode == 0);
    CHECK(readFile(dir.file("c.png")) == readFile(dir.file("plain.png")));
}

TEST_CASE("kerf render --section: bad planes are usage errors") {
    requireSectionError({"--section", "w=1"},
                        "--section expects x=V, y=V, z=V or PX,PY,PZ:NX,NY,NZ (got 'w=1')");
    requireSectionError({"--section", "z="}, "(got 'z=')");
    requireSectionError({"--section", "z=1e999"}, "(got 'z=1e999')");
    requireSectionError({"--section", "z=0.5x"}, "(got 'z=0.5x')");
    requireSectionError({"--section", "1,2:0,0,1"}, "(got '1,2:0,0,1')");
    requireSectionError({"--section", "0,0,0:0,0,1,"}, "(got '0,0,0:0,0,1,')");
    requireSectionError({"--section", "0,0,0:0,0,0"}, "--section: the normal must not be zero");
    requireSectionError({"--section", "z=0", "--section-color", "1,-1,0"},
                        "--section-color expects R,G,B");
    std::vector<std::string> many;
    for (int i = 0; i < 65; ++i) many.insert(many.end(), {"--section", "z=" + std::to_string(i)});
    requireSectionError(many, "--section: at most 64 section planes");
}
