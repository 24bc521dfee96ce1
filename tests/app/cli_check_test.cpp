// End-to-end tests of `kerf check`: the summary's counts and bounds against values worked out
// by hand from the model text.
#include "kerf_runner.h"

#include <catch2/catch.hpp>

#include <regex>

using namespace kerf::test;

namespace {

/// The integer after `label:` in the summary, or -1.
long summaryNumber(const std::string& text, const std::string& label) {
    std::smatch match;
    if (!std::regex_search(text, match, std::regex("\\n\\s*" + label + ":\\s+(\\d+)"))) return -1;
    return std::stol(match[1].str());
}

}  // namespace

TEST_CASE("kerf check: the cup") {
    TempDir dir;
    const KerfRun run = runKerf(dir, {"check", (modelsDir() / "cup.kerf").string()});
    INFO("stdout:\n" << run.out << "\nstderr:\n" << run.err);
    REQUIRE(run.exitCode == 0);
    CHECK(run.err.empty());
    // Two cups, the gyroid, the lamp and the floor.
    CHECK(summaryNumber(run.out, "objects") == 5);
    // clay, glass, mirror, lamp (the built-in default is not counted).
    CHECK(summaryNumber(run.out, "materials") == 4);
    CHECK(summaryNumber(run.out, "lights") == 2);
    // A cup is 2 cylinders (body) + 2 cylinders and a half-space (handle) = 5 leaves, and is
    // used twice; + gyroid + lamp sphere + floor half-space = 13.
    CHECK(summaryNumber(run.out, "primitives") == 13);
    // union → difference → cylinder at least.
    CHECK(summaryNumber(run.out, "csg depth") >= 3);
    // The floor is unbounded in x and z and below; the top is the lamp: 4 + 0.3.
    CHECK(run.out.find("bounds:      x unbounded  y [unbounded, 4.3]  z unbounded") !=
          std::string::npos);
    CHECK(run.out.find("render:      800 x 600, spp 4, max depth 8") != std::string::npos);
}

TEST_CASE("kerf check: bounds of a bounded scene") {
    TempDir dir;
    dir.write("two.kerf",
              "object sphere { center <1, 2, 3> radius 0.5 };\n"
              "object box { min <-2, 0, 0> max <0, 1, 1> } translate <0, 0, 10>;\n");
    const KerfRun run = runKerf(dir, {"check", "two.kerf"});
    INFO("stdout:\n" << run.out << "\nstderr:\n" << run.err);
    REQUIRE(run.exitCode == 0);
    CHECK(summaryNumber(run.out, "objects") == 2);
    CHECK(summaryNumber(run.out, "materials") == 0);
    CHECK(summaryNumber(run.out, "lights") == 0);
    CHECK(summaryNumber(run.out, "primitives") == 2);
    // Hull of [0.5,1.5]×[1.5,2.5]×[2.5,3.5] and [-2,0]×[0,1]×[10,11].
    CHECK(run.out.find("bounds:      x [-2, 1.5]  y [0, 2.5]  z [2.5, 11]") != std::string::npos);
}

TEST_CASE("kerf check: shared subtrees are counted once, their uses in 64 bits") {
    // s<i> is two copies of s<i-1>: 2^32 spheres written out. A walk per use took minutes at
    // 31 levels and printed -2147483648; a memoised walk visits each definition once.
    TempDir dir;
    std::string text = "solid s0 = sphere { radius 0.4 };\n";
    for (int i = 1; i <= 32; ++i)
        text += "solid s" + std::to_string(i) + " = union { s" + std::to_string(i - 1) + " s" +
                std::to_string(i - 1) + " translate <" + std::to_string(1L << (i - 1)) +
                ", 0, 0> };\n";
    text += "object s32;\n";
    dir.write("doubled.kerf", text);
    const KerfRun run = runKerf(dir, {"check", "doubled.kerf"});
    INFO("stdout:\n" << run.out << "\nstderr:\n" << run.err);
    REQUIRE(run.exitCode == 0);
    CHECK(run.out.find("primitives:  4294967296 (1 unique)\n") != std::string::npos);
    // A union and a transform per level over the sphere.
    CHECK(summaryNumber(run.out, "csg depth") == 1 + 2 * 32);
}

TEST_CASE("kerf check: a solid doubled in place is one instance a ray meets") {
    // Issue 24: 20 doublings of one solid in one place, bare and under equal transforms,
    // rendered 16x12 in 8 to 46 s (every copy tested per ray); a union keeps one of each repeat.
    TempDir dir;
    std::string text = "solid s0 = sphere { radius 0.4 };\n";
    for (int i = 1; i <= 20; ++i) {
        const std::string prev = "s" + std::to_string(i - 1);
        text += "solid s" + std::to_string(i) + " = union { " + prev + " " + prev + " " + prev +
                " translate <0, 0, 1> " + prev + " translate <0, 0, 1> };\n";
    }
    text += "object s20;\n";
    dir.write("doubled.kerf", text);
    const KerfRun run = runKerf(dir, {"check", "doubled.kerf"});
    INFO("stdout:\n" << run.out << "\nstderr:\n" << run.err);
    REQUIRE(run.exitCode == 0);
    // Each level is the solid and one copy moved by 1: 2^20 distinct placements would be
    // 3^20 written out; the repeats are gone, so a ray meets 2^20 (z = 0 … 20), not 4^20.
    CHECK(run.out.find("primitives:  1048576 (1 unique)\n") != std::string::npos);
}

TEST_CASE("kerf check: text, a profile and an extrusion are counted and bounded") {
    // Text "HI" in DejaVu Sans, size 1 (the em), extruded 0.5 along y. The glyphs' ink spans
    // x from H's left bearing (201/2048 em) to I's right edge (its stem, like H's, is 201 to 403
    // of 2048 from its origin), and z (the profile's y) from the
    // baseline to the cap height (1493/2048 em). The bounds must hold the ink, padded by at
    // most a small fraction of the size (they come from the outline's control boxes).
    TempDir dir;
    dir.write("text.kerf",
              "object extrude { profile text { string \"HI\" font \"DejaVu Sans\" size 1 } height "
              "0.5 };\n");
    const KerfRun run = runKerf(dir, {"check", "text.kerf"});
    INFO("stdout:\n" << run.out << "\nstderr:\n" << run.err);
    REQUIRE(run.exitCode == 0);
    CHECK(summaryNumber(run.out, "objects") == 1);
    CHECK(summaryNumber(run.out, "primitives") == 1);
    std::smatch m;
    const std::string number = "(-?[0-9.e+-]+)";
    REQUIRE(std::regex_search(
        run.out, m,
        std::regex("bounds:\\s+x \\[" + number + ", " + number + "\\]\\s+y \\[" + number + ", " +
                   number + "\\]\\s+z \\[" + number + ", " + number + "\\]")));
    const double x0 = std::stod(m[1]), x1 = std::stod(m[2]), y0 = std::stod(m[3]),
                 y1 = std::stod(m[4]), z0 = std::stod(m[5]), z1 = std::stod(m[6]);
    const double em = 1.0 / 2048;
    CHECK(x0 <= 201 * em);
    CHECK(x0 >= 201 * em - 0.05);
    CHECK(x1 >= (1540 + 403) * em);  // H's advance, then I's stem from 201 to 403
    CHECK(x1 <= (1540 + 403) * em + 0.05);
    CHECK(y0 <= 0.0);
    CHECK(y0 >= -0.05);
    CHECK(y1 >= 0.5);
    CHECK(y1 <= 0.55);
    CHECK(z0 <= 0.0);
    CHECK(z0 >= -0.05);
    CHECK(z1 >= 1493 * em);
    CHECK(z1 <= 1493 * em + 0.05);
}
