// The .csg reader: small OpenSCAD CSG texts lowered and traced, against depths, places and
// colours worked out by hand. kerf's (x, y, z) is OpenSCAD's (x, z, −y): a point OpenSCAD puts
// at height z is at kerf y = z.
#include "lang/openscad_csg.h"
#include "openscad_test_util.h"

#include "csg/trace_context.h"
#include "csg/tree/span.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace kerf;
using namespace kerf::test;

namespace {

/// The span ends as a flat list t0, t1, t2, ….
std::vector<double> ends(const SpanList& s) {
    std::vector<double> t;
    for (int i = 0; i < s.size(); ++i) {
        t.push_back(s[i].in.t);
        t.push_back(s[i].out.t);
    }
    return t;
}

void requireEnds(const SpanList& s, const std::vector<double>& expected) {
    const std::vector<double> got = ends(s);
    INFO("spans: " << ::Catch::Detail::stringify(got));
    REQUIRE(got.size() == expected.size());
    for (size_t i = 0; i < got.size(); ++i) CHECK(got[i] == Approx(expected[i]).epsilon(1e-12));
}

}  // namespace

TEST_CASE("openscad/cube minus sphere has the analytic depths") {
    // OpenSCAD's example004: a 30-cube centred at the origin minus a sphere of radius 20.
    const Read r = readCsg(
        "group() {\n\tdifference() {\n\t\tcube(size = [30, 30, 30], center = true);\n"
        "\t\tsphere($fn = 0, $fa = 12, $fs = 2, r = 20);\n\t}\n}\n");
    INFO(r.sink.format());
    SECTION("along x at OpenSCAD height z = 14: the corners outside the sphere") {
        // The sphere's chord at z = 14 has half-length √(400 − 196) = √204 < 15.
        const double h = std::sqrt(204.0);
        requireEnds(spansOf(r, {-50, 14, 0}, {1, 0, 0}), {35, 50 - h, 50 + h, 65});
    }
    SECTION("through a corner region along OpenSCAD's y: kerf's −z") {
        // At x = 14, z = 14 the sphere is left where y² < 400 − 392 = 8.
        const double h = std::sqrt(8.0);
        requireEnds(spansOf(r, {14, 14, 50}, {0, 0, -1}), {35, 50 - h, 50 + h, 65});
    }
    SECTION("through the centre: nothing is left") {
        CHECK(spansOf(r, {0, -50, 0}, {0, 1, 0}).size() == 0);
    }
}

TEST_CASE("openscad/multmatrix places its children") {
    SECTION("a translation: OpenSCAD (5, 0, 7) is kerf (5, 7, 0)") {
        const Read r = readCsg(
            "multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 7], [0, 0, 0, 1]]) {\n"
            "  sphere(r = 1);\n}\n");
        requireEnds(spansOf(r, {5, 7, -10}, {0, 0, 1}), {9, 11});
        CHECK(spansOf(r, {5, 0, -10}, {0, 0, 1}).size() == 0);
    }
    SECTION("a quarter turn about z lays a bar along OpenSCAD's +y, kerf's −z") {
        // cube([4, 1, 1]) turned: x in [−1, 0], y in [0, 4], z in [0, 1] (OpenSCAD).
        const Read r = readCsg(
            "multmatrix([[0, -1, 0, 0], [1, 0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])\n"
            "  cube(size = [4, 1, 1], center = false);\n");
        requireEnds(spansOf(r, {-0.5, 0.5, -10}, {0, 0, 1}), {6, 10});
    }
    SECTION("nested matrices compose, the inner applied first") {
        // Scale by 2, then move up by 3: a unit sphere becomes radius 2 at OpenSCAD z = 3.
        const Read r = readCsg(
            "multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 3], [0, 0, 0, 1]]) {\n"
            " multmatrix([[2, 0, 0, 0], [0, 2, 0, 0], [0, 0, 2, 0], [0, 0, 0, 1]]) {\n"
            "  sphere(r = 1);\n }\n}\n");
        requireEnds(spansOf(r, {0, -10, 0}, {0, 1, 0}), {11, 15});
    }
    SECTION("a singular or projective matrix is an error at the matrix") {
        const Read flat = readCsg(
            "multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 1]]) cube(size = "
            "1);\n");
        REQUIRE_FALSE(flat.scene.has_value());
        REQUIRE(flat.sink.errorCount() == 1);
        CHECK(flat.sink.diagnostics()[0].loc.col == 12);
        CHECK_THAT(flat.sink.diagnostics()[0].message, Catch::Contains("singular"));
        const Read projective = readCsg(
            "multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 1, 1]]) cube(size = "
            "1);\n");
        REQUIRE_FALSE(projective.scene.has_value());
        CHECK_THAT(projective.sink.diagnostics()[0].message, Catch::Contains("projective"));
        const Read overflow = readCsg(
            "multmatrix([[1e300, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])\n"
            "  cube(size = [1e300, 1, 1]);\n");
        REQUIRE_FALSE(overflow.scene.has_value());
        CHECK_THAT(overflow.sink.diagnostics()[0].message, Catch::Contains("overflows"));
    }
}

TEST_CASE("openscad/cylinder r1, r2 and center") {
    SECTION("a frustum from z = 0 to 10, radius 2 below and 1 above") {
        const Read r = readCsg(
            "cylinder($fn = 0, $fa = 12, $fs = 2, h = 10, r1 = 2, r2 = 1, center = false);\n");
        requireEnds(spansOf(r, {0, -20, 0}, {0, 1, 0}), {20, 30});
        // At height 5 the radius is 1.5.
        requireEnds(spansOf(r, {-10, 5, 0}, {1, 0, 0}), {8.5, 11.5});
    }
    SECTION("center = true puts it from z = −5 to 5") {
        const Read r = readCsg("cylinder(h = 10, r1 = 3, r2 = 3, center = true);\n");
        requireEnds(spansOf(r, {0, -20, 0}, {0, 1, 0}), {15, 25});
        requireEnds(spansOf(r, {-10, 4.9, 0}, {1, 0, 0}), {7, 13});
    }
    SECTION("positional h, r1, r2, center and diameters, as OpenSCAD reads them") {
        const Read r = readCsg("cylinder(10, 3, 3, true);\n");
        requireEnds(spansOf(r, {0, -20, 0}, {0, 1, 0}), {15, 25});
        const Read d = readCsg("cylinder(h = 2, d1 = 4, d2 = 4);\n");
        requireEnds(spansOf(d, {-10, 1, 0}, {1, 0, 0}), {8, 12});
    }
    SECTION("a cone to a point") {
        const Read r = readCsg("cylinder(h = 4, r1 = 2, r2 = 0, center = false);\n");
        requireEnds(spansOf(r, {-10, 2, 0}, {1, 0, 0}), {9, 11});
    }
    SECTION("zero height is empty, as in OpenSCAD, with a warning") {
        const Read r = readCsg("union() { cylinder(h = 0, r1 = 1, r2 = 1); sphere(r = 1); }\n");
        requireEnds(spansOf(r, {0, -10, 0}, {0, 1, 0}), {9, 11});
        CHECK(r.sink.diagnostics().front().severity == Severity::Warning);
    }
}

TEST_CASE("openscad/color gives a material of that colour") {
    const Read r = readCsg(
        "color([0, 0, 1, 1]) {\n  color([1, 0, 0, 1]) cube(size = [1, 1, 1]);\n"
        "  multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) sphere(r = "
        "1);\n}\n");
    INFO(r.sink.format());
    const SpanList cube = spansOf(r, {0.5, 0.5, 10}, {0, 0, -1});
    const SpanList sphere = spansOf(r, {5, 0, 10}, {0, 0, -1});
    REQUIRE(cube.size() == 1);
    REQUIRE(sphere.size() == 1);
    // The innermost colour wins, as in OpenSCAD.
    CHECK(r.scene->materials.at(cube[0].in.material).color == Vec3(1, 0, 0));
    CHECK(r.scene->materials.at(sphere[0].in.material).color == Vec3(0, 0, 1));
    SECTION("the same colour twice is one material") {
        const Read twice = readCsg(
            "color([0.5, 0.5, 0.5, 1]) cube(size = 1);\n"
            "color([0.5, 0.5, 0.5, 1]) sphere(r = 1);\n");
        REQUIRE(twice.scene.has_value());
        CHECK(twice.scene->materials.size() == 2);
    }
}

TEST_CASE("openscad/polyhedron cube is a solid") {
    // A 10 × 7 × 5 box, faces listed clockwise seen from outside as OpenSCAD wants them.
    const std::string points =
        "points = [[0, 0, 0], [10, 0, 0], [10, 7, 0], [0, 7, 0], [0, 0, 5], [10, 0, 5], "
        "[10, 7, 5], [0, 7, 5]]";
    const std::string clockwise =
        "[[0, 1, 2, 3], [4, 5, 1, 0], [7, 6, 5, 4], [5, 6, 2, 1], [6, 7, 3, 2], [7, 4, 0, 3]]";
    SECTION("it traces as the box") {
        const Read r = readCsg("difference() {\n  polyhedron(" + points + ", faces = " + clockwise +
                               ", convexity = 1);\n  sphere(r = 1);\n}\n");
        INFO(r.sink.format());
        // Vertically through OpenSCAD (5, 3.5): z from 0 to 5.
        requireEnds(spansOf(r, {5, -10, -3.5}, {0, 1, 0}), {10, 15});
        // Along x at OpenSCAD y = 0.5, z = 0.5: the unit sphere at the corner cuts x < √0.5.
        requireEnds(spansOf(r, {-10, 0.5, -0.5}, {1, 0, 0}), {10 + std::sqrt(0.5), 20});
    }
    SECTION("faces written the other way round are taken as they are") {
        const std::string counter =
            "[[3, 2, 1, 0], [0, 1, 5, 4], [4, 5, 6, 7], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]";
        const Read r = readCsg("difference() { polyhedron(" + points + ", faces = " + counter +
                               "); sphere(r = 1); }\n");
        requireEnds(spansOf(r, {5, -10, -3.5}, {0, 1, 0}), {10, 15});
    }
    SECTION("an open polyhedron is an error naming an edge") {
        const Read r =
            readCsg("\n  polyhedron(" + points + ", faces = [[0, 1, 2, 3], [4, 5, 1, 0]]);\n");
        REQUIRE_FALSE(r.scene.has_value());
        REQUIRE(r.sink.errorCount() == 1);
        CHECK(r.sink.diagnostics()[0].loc.line == 2);
        CHECK(r.sink.diagnostics()[0].loc.col == 3);
        CHECK_THAT(r.sink.diagnostics()[0].message, Catch::Contains("not a closed solid"));
    }
    SECTION("faces that are not convex are cut into ears") {
        // An L-shaped prism: the L (0, 0) (2, 0) (2, 1) (1, 1) (1, 2) (0, 2) from z = 0 to 1;
        // its bottom and top are six-sided and not convex.
        const Read r = readCsg(
            "polyhedron(points = [[0, 0, 0], [2, 0, 0], [2, 1, 0], [1, 1, 0], [1, 2, 0], [0, 2, "
            "0],\n"
            "  [0, 0, 1], [2, 0, 1], [2, 1, 1], [1, 1, 1], [1, 2, 1], [0, 2, 1]],\n"
            "  faces = [[0, 1, 2, 3, 4, 5], [11, 10, 9, 8, 7, 6], [0, 6, 7, 1], [1, 7, 8, 2], [2, "
            "8, 9, 3],\n"
            "  [3, 9, 10, 4], [4, 10, 11, 5], [5, 11, 6, 0]]);\n");
        INFO(r.sink.format());
        // Along x at OpenSCAD y = 0.5 (the foot, x to 2) and y = 1.5 (the upright, x to 1).
        requireEnds(spansOf(r, {-10, 0.5, -0.5}, {1, 0, 0}), {10, 12});
        requireEnds(spansOf(r, {-10, 0.5, -1.5}, {1, 0, 0}), {10, 11});
        // Down through the notch (1.5, 1.5): nothing; through (0.5, 1.5): z from 0 to 1.
        CHECK(spansOf(r, {1.5, 10, -1.5}, {0, -1, 0}).size() == 0);
        requireEnds(spansOf(r, {0.5, 10, -1.5}, {0, -1, 0}), {9, 10});
    }
    SECTION("a face that crosses itself is an error at the face") {
        const Read r = readCsg(
            "polyhedron(points = [[0, 0, 0], [2, 0, 0], [0, 2, 0], [2, 2, 0], [1, 1, 3]], "
            "faces = [[0, 1, 2, 3], [0, 4, 1], [1, 4, 2], [2, 4, 3], [3, 4, 0]]);\n");
        REQUIRE_FALSE(r.scene.has_value());
        CHECK_THAT(r.sink.diagnostics()[0].message, Catch::Contains("face 0 crosses itself"));
        CHECK(r.sink.diagnostics()[0].loc.col == 87);
    }
}

TEST_CASE("openscad/$fn, $fa and $fs give one note with OpenSCAD's facet count") {
    // r = 10, $fa 12, $fs 2: min(360/12, 2π·10/2) = 30; $fn = 7 wins where it is set.
    const Read r = readCsg(
        "union() {\n  sphere($fn = 0, $fa = 12, $fs = 2, r = 10);\n"
        "  cylinder($fn = 7, h = 1, r1 = 1, r2 = 1);\n}\n");
    REQUIRE(r.scene.has_value());
    int notes = 0;
    for (const Diagnostic& d : r.sink.diagnostics()) {
        if (d.severity != Severity::Note) continue;
        ++notes;
        CHECK(d.loc.line == 2);
        CHECK_THAT(d.message, Catch::Contains("2 here") && Catch::Contains("7 to 30 facets"));
    }
    CHECK(notes == 1);
}

TEST_CASE("openscad/the model is framed and lit by default") {
    const Read r = readCsg("cube(size = [2, 2, 2], center = true);\n");
    REQUIRE(r.scene.has_value());
    const CameraDesc& cam = r.scene->camera;
    CHECK(cam.lookAt == Vec3(0.0));
    // The whole bounding ball (radius √3) is inside the vertical field of view.
    const double angle = std::asin(std::sqrt(3.0) / glm::length(cam.eye - cam.lookAt)) * 180 / M_PI;
    CHECK(angle < 0.5 * cam.fovDegrees);
    // Seen from OpenSCAD's front (−y: kerf +z), right (+x) and above (+z: kerf +y).
    CHECK(cam.eye.x > 0);
    CHECK(cam.eye.y > 0);
    CHECK(cam.eye.z > 0);
    CHECK_FALSE(r.scene->lights.empty());
}
