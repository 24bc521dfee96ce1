// `kerf check` as a user coming from another modeller sees it: bounds printed without the
// rounding residue of transforms, and a hint for a POV-Ray habit, with caret and exit code 2.
#include <catch2/catch.hpp>
#include <limits>

#include "csg/format.h"
#include "kerf_runner.h"

using namespace kerf::test;

namespace {

/// The bounds line of `kerf check` for a model of one line.
std::string boundsLine(const std::string& model) {
    TempDir dir;
    dir.write("m.kerf", model + "\n");
    const KerfRun run = runKerf(dir, {"check", "m.kerf"});
    INFO("stdout:\n" << run.out << "\nstderr:\n" << run.err);
    REQUIRE(run.exitCode == 0);
    const size_t at = run.out.find("bounds:");
    REQUIRE(at != std::string::npos);
    return run.out.substr(at, run.out.find('\n', at) - at);
}

}  // namespace

TEST_CASE("formatDoubleAtScale: residues within 16 ulps of the scale print as 0") {
    using kerf::formatDoubleAtScale;
    const double eps = std::numeric_limits<double>::epsilon();
    const double tiny = std::numeric_limits<double>::denorm_min();
    CHECK(formatDoubleAtScale("%.6g", -eps, 1.0) == "0");
    CHECK(formatDoubleAtScale("%.6g", 16 * eps, 1.0) == "0");
    CHECK(formatDoubleAtScale("%.6g", -tiny, 1.0) == "0");
    CHECK(formatDoubleAtScale("%.6g", -0.0, 1.0) == "0");
    // Past 16 ulps, or a value that is the scale itself, keeps its digits.
    CHECK(formatDoubleAtScale("%.6g", 17 * eps, 1.0) == "3.77476e-15");
    CHECK(formatDoubleAtScale("%.6g", 1e-300, 1e-300) == "1e-300");
    CHECK(formatDoubleAtScale("%.6g", -tiny, 0.0) == "-4.94066e-324");
    // Relative, not absolute: the same residue at scale 1e-300 and 1e300.
    CHECK(formatDoubleAtScale("%.6g", -eps * 1e-300, 1e-300) == "0");
    CHECK(formatDoubleAtScale("%.6g", eps * 1e300, 1e300) == "0");
    CHECK(formatDoubleAtScale("%.6g", 0.5 * 1e300, 1e300) == "5e+299");
}

TEST_CASE("kerf check: bounds of rotated solids print without rounding residue") {
    // Printed before: z [-1, 2.22045e-16]. (x, y, z) -> (z, y, -x) maps [0,1]^3 to z in [-1, 0].
    CHECK(boundsLine(
              "object box { min <0, 0, 0> max <1, 1, 1> } rotate <0, 60, 0> rotate <0, 30, 0>;") ==
          "bounds:      x [0, 1]  y [0, 1]  z [-1, 0]");
    // Printed before: z [-4.94066e-324, 1]. About x by 90: the axis y in [0, 1] becomes z.
    CHECK(boundsLine("object cone { from <0, 0, 0> to <0, 1, 0> radius1 1 } rotate <90, 0, 0>;") ==
          "bounds:      x [-1, 1]  y [-1, 1]  z [0, 1]");
    // Printed before: z [-2.22045e-16, 1].
    CHECK(boundsLine("object cylinder { from <0, 0, 0> to <0, 1, 0> radius 1 } rotate <45, 0, 0> "
                     "rotate <45, 0, 0>;") == "bounds:      x [-1, 1]  y [-1, 1]  z [0, 1]");
    // The same model scaled by 1e-300: the rule is relative to the bounds, not to 1.
    CHECK(boundsLine("object box { min <0, 0, 0> max <1, 1, 1> } rotate <0, 60, 0> rotate <0, 30, "
                     "0> scale 1e-300;") ==
          "bounds:      x [0, 1e-300]  y [0, 1e-300]  z [-1e-300, 0]");
}

TEST_CASE("kerf check: a POV-Ray habit is an error with caret, hint and exit code 2") {
    TempDir dir;
    dir.write("pov.kerf", "// from POV-Ray\nobject sphere { <0, 1, 0>, 2 };\n");
    const KerfRun run = runKerf(dir, {"check", "pov.kerf"});
    CHECK(run.exitCode == 2);
    CHECK(run.out.empty());
    CHECK(run.err ==
          "pov.kerf:2:17: error: expected a property name in sphere, found '<'\n"
          "object sphere { <0, 1, 0>, 2 };\n"
          "                ^\n"
          "  hint: kerf names each property: write 'sphere { center <0, 1, 0> radius 2 }'\n");
}

TEST_CASE("kerf check and render: echo lines on stderr, silenced by --quiet") {
    TempDir dir;
    dir.write("e.kerf", "let n = 3;\necho \"n is\", n;\nobject sphere { radius n };\n");
    for (const char* command : {"check", "render"}) {
        INFO(command);
        std::vector<std::string> args{command, "e.kerf"};
        if (std::string(command) == "render")
            args.insert(args.end(), {"-o", "e.png", "--width", "4", "--height", "3"});
        const KerfRun loud = runKerf(dir, args);
        CHECK(loud.exitCode == 0);
        CHECK(loud.err.find("e.kerf:2: echo: n is, 3") != std::string::npos);
        args.push_back("--quiet");
        const KerfRun quiet = runKerf(dir, args);
        CHECK(quiet.exitCode == 0);
        CHECK(quiet.err.find("echo") == std::string::npos);
    }
}
