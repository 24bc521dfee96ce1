// End-to-end: `kerf check`, `kerf slice` and `kerf render` of OpenSCAD .csg exports, against
// bounds and areas worked out by hand, and the error format for nodes kerf cannot read.
#include "io/image.h"
#include "kerf_runner.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <regex>

using namespace kerf::test;

namespace {

fs::path openscadData(const std::string& name) { return testDataDir() / "openscad" / name; }

}  // namespace

TEST_CASE("kerf check: an OpenSCAD .csg is read by its extension") {
    TempDir dir;
    const KerfRun run = runKerf(dir, {"check", openscadData("CSG.csg").string()});
    INFO("stdout:\n" << run.out << "\nstderr:\n" << run.err);
    REQUIRE(run.exitCode == 0);
    // OpenSCAD's CSG.scad: at x = −24 a 15-cube ∪ a radius-10 ball (x from −34), at x = 24 a
    // 15-cube minus the ball (to 31.5). OpenSCAD's y (±10) is kerf's −z, its z kerf's y.
    CHECK(run.out.find("bounds:      x [-34, 31.5]  y [-10, 10]  z [-10, 10]") !=
          std::string::npos);
    // One note on $fn/$fa/$fs, nothing else.
    CHECK(run.err.find("note: $fn, $fa and $fs are ignored") != std::string::npos);
    CHECK(run.err.find("error") == std::string::npos);
}

TEST_CASE("kerf slice: an OpenSCAD cube minus a sphere has the analytic area") {
    TempDir dir;
    // example004: a 30-cube minus a radius-20 ball, cut at OpenSCAD's z = 0 (kerf's y = 0):
    // the square minus the disc, whose four caps beyond the square are disjoint
    // (15√2 > 20), so the area is 30² − (π·20² − 4·(20²·acos(15/20) − 15·√(20² − 15²))).
    const KerfRun run = runKerf(dir, {"slice", openscadData("example004.csg").string(), "--plane",
                                      "y=0", "-o", "cut.svg", "--stats"});
    INFO("stdout:\n" << run.out << "\nstderr:\n" << run.err);
    REQUIRE(run.exitCode == 0);
    std::smatch m;
    const std::string err = run.err;
    REQUIRE(std::regex_search(err, m, std::regex("total: area ([0-9.eE+-]+)")));
    const double area = std::stod(m[1].str());
    const double exact =
        900.0 - (M_PI * 400.0 - 4.0 * (400.0 * std::acos(0.75) - 15.0 * std::sqrt(175.0)));
    // The default tolerance puts every contour vertex within 1e-7 of the model's size (here
    // 3e-6) of the true section: the area moves by at most that times the perimeter (≈ 24.2).
    CHECK(std::abs(area - exact) <= 3e-6 * 24.2);
    CHECK(fs::exists(dir.file("cut.svg")));
}

TEST_CASE("kerf render: an OpenSCAD .csg is framed by its default camera") {
    TempDir dir;
    // A unit ball: its box's ball has radius √3, and the default camera looks at its centre
    // from 1.1·√3 / sin(20°) (the ball fills 1/1.1 of the 40° field of view), so the centre
    // pixel of an odd-sized image sees the ball at that distance minus 1, and a corner misses.
    const std::string model = dir.write("ball.csg", "sphere($fn = 0, $fa = 12, $fs = 2, r = 1);\n");
    const KerfRun run = runKerf(dir, {"render", "-q", model, "--width", "33", "--height", "25",
                                      "-o", "ball.png", "--aov", "depth=depth.exr"});
    INFO("stdout:\n" << run.out << "\nstderr:\n" << run.err);
    REQUIRE(run.exitCode == 0);
    const kerf::Image depth = kerf::readImage(dir.file("depth.exr"));
    REQUIRE(depth.width == 33);
    const double distance = 1.1 * std::sqrt(3.0) / std::sin(20.0 * M_PI / 180.0);
    // The EXR holds floats: half an ulp of 2^-24 relative.
    CHECK(depth.at(16, 12, 0) == Approx(distance - 1.0).epsilon(1e-7));
    CHECK(std::isinf(depth.at(0, 0, 0)));
    CHECK(fs::file_size(dir.file("ball.png")) > 0);
}

TEST_CASE("kerf check: nodes kerf cannot read are errors at their line, exit code 2") {
    TempDir dir;
    const std::string model = dir.write("hulls.csg",
                                        "union() {\n\thull() {\n\t\tsphere(r = 1);\n\t}\n"
                                        "\tminkowski() { cube(size = 1); }\n}\n");
    const KerfRun run = runKerf(dir, {"check", model});
    INFO("stdout:\n" << run.out << "\nstderr:\n" << run.err);
    CHECK(run.exitCode == 2);
    CHECK(run.err.find("hulls.csg:2:2: error: hull is not supported") != std::string::npos);
    CHECK(run.err.find("hulls.csg:5:2: error: minkowski is not supported") != std::string::npos);
    // The source line and a caret under the node.
    CHECK(run.err.find("\thull() {\n\t^") != std::string::npos);
    CHECK(run.out.empty());
}

TEST_CASE("kerf slice: OpenSCAD extrusions have the analytic areas") {
    TempDir dir;
    struct Case {
        const char* name;
        const char* text;
        const char* plane;
        double area, perimeter;
    };
    // A 10-square with a 4-square hole (paths fill even-odd), cut across at height 1; a circle
    // of radius 1 at x = 3 turned about z (a torus), cut through the axis by OpenSCAD's y = 0
    // plane (kerf's z = 0): two unit discs.
    const Case cases[] = {
        {"holed.csg",
         "linear_extrude(height = 2, center = false, convexity = 1, scale = [1, 1]) {\n"
         "\tpolygon(points = [[0, 0], [10, 0], [10, 10], [0, 10], [3, 3], [7, 3], [7, 7], [3, 7]],"
         " paths = [[0, 1, 2, 3], [4, 5, 6, 7]], convexity = 1);\n}\n",
         "y=1", 84.0, 56.0},
        {"torus.csg",
         "rotate_extrude(angle = 360, convexity = 2) {\n"
         "\tmultmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n"
         "\t\tcircle($fn = 0, $fa = 12, $fs = 2, r = 1);\n\t}\n}\n",
         "z=0", 2 * M_PI, 4 * M_PI},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        {
            std::ofstream out(dir.file(c.name));
            out << c.text;
        }
        const KerfRun run = runKerf(
            dir, {"slice", dir.file(c.name), "--plane", c.plane, "-o", "cut.svg", "--stats"});
        INFO("stdout:\n" << run.out << "\nstderr:\n" << run.err);
        REQUIRE(run.exitCode == 0);
        std::smatch m;
        const std::string err = run.err;
        REQUIRE(std::regex_search(err, m, std::regex("total: area ([0-9.eE+-]+)")));
        // As above: every contour vertex within 1e-7 of the model's size (at most 10) of the
        // true section, so the area moves by at most that times the perimeter.
        CHECK(std::abs(std::stod(m[1].str()) - c.area) <= 1e-6 * c.perimeter);
    }
}
