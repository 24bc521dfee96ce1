// The .csg reader's 2-D nodes and extrusions, traced against closed forms. kerf's (x, y, z) is
// OpenSCAD's (x, z, −y): OpenSCAD's height z is kerf's y, its y is kerf's −z. OpenSCAD's
// conventions below were checked against OpenSCAD 2021.01's own STL output (a twist of 90°
// takes the corner (2, 0) of square([2, 1]) to (0, −2) at the top; polygon paths fill even-odd:
// two 4×4 squares overlapping in a 2×2 one extrude to a volume of 24, not 28; rotate_extrude by
// 90° fills x, y ≥ 0, by −90° x ≥ 0, y ≤ 0).
#include "lang/openscad_csg.h"
#include "openscad_test_util.h"

#include "csg/profiles/profile.h"
#include "csg/tape/tape.h"
#include "csg/trace_context.h"
#include "csg/tree/span.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace kerf;
using namespace kerf::test;

namespace {

/// Implicit surfaces are found by root isolation to within its tolerance; 1e-6 is far above
/// it and far below any feature here.
void requireEnds(const SpanList& s, const std::vector<double>& expected) {
    std::vector<double> got;
    for (int i = 0; i < s.size(); ++i) {
        got.push_back(s[i].in.t);
        got.push_back(s[i].out.t);
    }
    INFO("spans: " << ::Catch::Detail::stringify(got));
    REQUIRE(got.size() == expected.size());
    for (size_t i = 0; i < got.size(); ++i) CHECK(got[i] == Approx(expected[i]).margin(1e-6));
}

std::string extrude(const std::string& args, const std::string& body) {
    return "linear_extrude(" + args + ") {\n  " + body + "\n}\n";
}

void requireError(const Read& r, int line, int col, const std::string& text) {
    INFO(r.sink.format());
    REQUIRE_FALSE(r.scene.has_value());
    bool found = false;
    for (const Diagnostic& d : r.sink.diagnostics())
        if (d.severity == Severity::Error && d.loc.line == line && d.loc.col == col &&
            d.message.find(text) != std::string::npos)
            found = true;
    CHECK(found);
}

}  // namespace

TEST_CASE("openscad/linear_extrude of a circle is the cylinder") {
    const Read r = readCsg(extrude("height = 10, center = false", "circle(r = 2);"));
    // Across at height 5, OpenSCAD y = 1 (kerf z = −1): the chord's half-length is √3.
    requireEnds(spansOf(r, {-10, 5, -1}, {1, 0, 0}), {10 - std::sqrt(3.0), 10 + std::sqrt(3.0)});
    // Along the axis: the caps at heights 0 and 10.
    requireEnds(spansOf(r, {1, -5, 0}, {0, 1, 0}), {5, 15});
    const Read centered = readCsg(extrude("height = 10, center = true", "circle(d = 4);"));
    requireEnds(spansOf(centered, {1, -10, 0}, {0, 1, 0}), {5, 15});
}

TEST_CASE("openscad/square, centred or not") {
    const Read corner = readCsg(extrude("height = 2", "square(size = [4, 2], center = false);"));
    // OpenSCAD x in [0, 4], y in [0, 2]: kerf z in [−2, 0].
    requireEnds(spansOf(corner, {1, 1, -10}, {0, 0, 1}), {8, 10});
    requireEnds(spansOf(corner, {-10, 1, -1}, {1, 0, 0}), {10, 14});
    const Read centered = readCsg(extrude("height = 2", "square(size = [4, 2], center = true);"));
    requireEnds(spansOf(centered, {0, 1, -10}, {0, 0, 1}), {9, 11});
    requireEnds(spansOf(centered, {-10, 1, 0}, {1, 0, 0}), {8, 12});
    const Read unit = readCsg(extrude("height = 1", "square(3);"));
    requireEnds(spansOf(unit, {-10, 0.5, -1}, {1, 0, 0}), {10, 13});
}

TEST_CASE("openscad/polygon paths fill by the even-odd rule") {
    SECTION("an outline and a hole") {
        const Read r = readCsg(
            extrude("height = 1",
                    "polygon(points = [[0, 0], [10, 0], [10, 10], [0, 10], [3, 3], [7, 3], [7, 7], "
                    "[3, 7]], paths = [[0, 1, 2, 3], [4, 5, 6, 7]], convexity = 1);"));
        requireEnds(spansOf(r, {-10, 0.5, -5}, {1, 0, 0}), {10, 13, 17, 20});
        requireEnds(spansOf(r, {-10, 0.5, -1}, {1, 0, 0}), {10, 20});
    }
    SECTION("two overlapping outlines leave their overlap empty, as in OpenSCAD") {
        const Read r = readCsg(extrude(
            "height = 1",
            "polygon(points = [[0, 0], [4, 0], [4, 4], [0, 4], [2, 2], [6, 2], [6, 6], [2, 6]], "
            "paths = [[0, 1, 2, 3], [4, 5, 6, 7]]);"));
        // At OpenSCAD y = 3: x in [0, 2] and [4, 6].
        requireEnds(spansOf(r, {-10, 0.5, -3}, {1, 0, 0}), {10, 12, 14, 16});
    }
    SECTION("no paths: the points in order") {
        const Read r =
            readCsg(extrude("height = 1", "polygon(points = [[0, 0], [4, 0], [0, 4]]);"));
        // At OpenSCAD y = 1 the triangle spans x in [0, 3].
        requireEnds(spansOf(r, {-10, 0.5, -1}, {1, 0, 0}), {10, 13});
    }
}

TEST_CASE("openscad/linear_extrude twists clockwise seen from +z") {
    // square([2, 1]) turned by 90° over a height of 10. At height z the profile is turned by
    // −9z degrees, so OpenSCAD's point (0.5, −1.5) is inside when the turn φ has
    // tan φ ≥ 3 (the rectangle's y ≥ 0 there; its other sides are not reached): from
    // z = 10·atan(3)/(π/2) to the top.
    const Read r = readCsg(extrude("height = 10, twist = 90", "square(size = [2, 1]);"));
    const double zIn = 10 * std::atan(3.0) / (M_PI / 2);
    requireEnds(spansOf(r, {0.5, 20, 1.5}, {0, -1, 0}), {10, 20 - zIn});
    // Turned the other way the top is at x in [−1, 0], y in [0, 2]: (0.5, −1.5) is outside
    // at every height, and (−0.5, 1.5), turned back by φ, is (1.5 sin φ − 0.5 cos φ,
    // 0.5 sin φ + 1.5 cos φ): inside once 0.5 sin φ + 1.5 cos φ ≤ 1, i.e. from
    // φ = atan(1/3) + acos(1/√2.5).
    const Read ccw = readCsg(extrude("height = 10, twist = -90", "square(size = [2, 1]);"));
    CHECK(spansOf(ccw, {0.5, 20, 1.5}, {0, -1, 0}).size() == 0);
    const double zCcw = 10 * (std::atan(1.0 / 3) + std::acos(1 / std::sqrt(2.5))) / (M_PI / 2);
    requireEnds(spansOf(ccw, {-0.5, 20, -1.5}, {0, -1, 0}), {10, 20 - zCcw});
}

TEST_CASE("openscad/linear_extrude scale") {
    // The radius goes from 2 at the bottom to 1 at the top: 1.5 at height 5.
    const Read r = readCsg(extrude("height = 10, scale = [0.5, 0.5]", "circle(r = 2);"));
    requireEnds(spansOf(r, {-10, 5, 0}, {1, 0, 0}), {8.5, 11.5});
    const Read number = readCsg(extrude("height = 10, scale = 2", "circle(r = 2);"));
    requireEnds(spansOf(number, {-10, 5, 0}, {1, 0, 0}), {7, 13});
    // Per axis: at height 5 the circle is an ellipse of half-axes 2 (along x) and 3 (along y,
    // kerf's z).
    const Read ellipse = readCsg(extrude("height = 10, scale = [1, 2]", "circle(r = 2);"));
    requireEnds(spansOf(ellipse, {-10, 5, 0}, {1, 0, 0}), {8, 12});
    requireEnds(spansOf(ellipse, {0, 5, -10}, {0, 0, 1}), {7, 13});
    requireEnds(spansOf(ellipse, {0, 9.5, -10}, {0, 0, 1}), {10 - 3.9, 10 + 3.9});
    requireError(readCsg(extrude("height = 10, scale = [0, 0]", "circle(r = 2);")), 1, 37,
                 "must be > 0");
}

TEST_CASE("openscad/rotate_extrude of a translated circle is a torus") {
    const Read r = readCsg(
        "rotate_extrude(angle = 360, convexity = 2) {\n"
        "  multmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) circle(r = 1);\n"
        "}\n");
    requireEnds(spansOf(r, {-10, 0, 0}, {1, 0, 0}), {6, 8, 12, 14});
    // At height 0.5 the tube's half-width is √0.75.
    const double s = std::sqrt(0.75);
    requireEnds(spansOf(r, {-10, 0.5, 0}, {1, 0, 0}), {7 - s, 7 + s, 13 - s, 13 + s});
    requireEnds(spansOf(r, {0, 0.5, -10}, {0, 0, 1}), {7 - s, 7 + s, 13 - s, 13 + s});
    requireEnds(spansOf(r, {3, -10, 0}, {0, 1, 0}), {9, 11});
    SECTION("a profile left of the axis is turned as its mirror image, as in OpenSCAD") {
        const Read left = readCsg(
            "rotate_extrude() multmatrix([[1, 0, 0, -3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, "
            "1]]) circle(r = 1);\n");
        requireEnds(spansOf(left, {-10, 0.5, 0}, {1, 0, 0}), {7 - s, 7 + s, 13 - s, 13 + s});
    }
    SECTION("a profile across the axis: its part at x ≥ 0, with a warning") {
        const Read across = readCsg("rotate_extrude() square(size = [4, 2], center = true);\n");
        requireEnds(spansOf(across, {-10, 0.5, 0}, {1, 0, 0}), {8, 12});
        bool warned = false;
        for (const Diagnostic& d : across.sink.diagnostics())
            warned |=
                d.severity == Severity::Warning && d.message.find("x < 0") != std::string::npos;
        CHECK(warned);
    }
}

TEST_CASE("openscad/a partial rotate_extrude turns from +x toward +y") {
    // The ring 2 ≤ ρ ≤ 3, 0 ≤ z ≤ 1. At x = ±2.5 the ring holds |y| ≤ √(9 − 6.25).
    const double w = std::sqrt(2.75);
    auto ring = [](const std::string& angle) {
        return readCsg("rotate_extrude(angle = " + angle +
                       ") {\n  multmatrix([[1, 0, 0, 2], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, "
                       "1]]) square(size = [1, 1]);\n}\n");
    };
    // Rays along kerf −z, OpenSCAD +y, from y = −10.
    const Read quarter = ring("90");
    requireEnds(spansOf(quarter, {2.5, 0.5, 10}, {0, 0, -1}), {10, 10 + w});
    CHECK(spansOf(quarter, {-2.5, 0.5, 10}, {0, 0, -1}).size() == 0);
    const Read threeQuarters = ring("270");
    requireEnds(spansOf(threeQuarters, {2.5, 0.5, 10}, {0, 0, -1}), {10, 10 + w});
    requireEnds(spansOf(threeQuarters, {-2.5, 0.5, 10}, {0, 0, -1}), {10 - w, 10 + w});
    const Read back = ring("-90");
    requireEnds(spansOf(back, {2.5, 0.5, 10}, {0, 0, -1}), {10 - w, 10});
    CHECK(spansOf(back, {-2.5, 0.5, 10}, {0, 0, -1}).size() == 0);
}

TEST_CASE("openscad/2-D multmatrix: scale, rotation, mirror") {
    SECTION("a circle scaled by [2, 1] is an ellipse") {
        const Read r = readCsg(extrude(
            "height = 1",
            "multmatrix([[2, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) circle(r = 1);"));
        // At OpenSCAD y = 0.5: x = ±2·√0.75.
        requireEnds(spansOf(r, {-10, 0.5, -0.5}, {1, 0, 0}),
                    {10 - std::sqrt(3.0), 10 + std::sqrt(3.0)});
    }
    SECTION("a centred square turned by 45° is a diamond") {
        const double c = std::sqrt(0.5);
        const Read r = readCsg(extrude(
            "height = 1", "multmatrix([[" + std::to_string(c) + ", " + std::to_string(-c) +
                              ", 0, 0], [" + std::to_string(c) + ", " + std::to_string(c) +
                              ", 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) square(2, center = true);"));
        const double h = 2 * std::stod(std::to_string(c));  // the half-diagonal as written
        requireEnds(spansOf(r, {-10, 0.5, 0}, {1, 0, 0}), {10 - h, 10 + h});
    }
    SECTION("a mirror in x") {
        const Read r =
            readCsg(extrude("height = 1",
                            "multmatrix([[-1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) "
                            "square(size = [2, 1]);"));
        requireEnds(spansOf(r, {-10, 0.5, -0.5}, {1, 0, 0}), {8, 10});
    }
    SECTION("2-D Booleans") {
        const Read r = readCsg(
            extrude("height = 1", "difference() { square(4, center = true); circle(r = 1); }"));
        requireEnds(spansOf(r, {-10, 0.5, 0}, {1, 0, 0}), {8, 9, 11, 12});
        const Read i = readCsg(
            extrude("height = 1", "intersection() { square(4, center = true); circle(r = 3); }"));
        requireEnds(spansOf(i, {-10, 0.5, 0}, {1, 0, 0}), {8, 12});
    }
}

TEST_CASE("openscad/color on a 2-D shape colours the extrusion") {
    const Read r = readCsg(extrude("height = 1", "color([1, 0, 0, 1]) square(2);"));
    const SpanList s = spansOf(r, {1, 0.5, -10}, {0, 0, 1});
    REQUIRE(s.size() == 1);
    CHECK(r.scene->materials.at(s[0].in.material).color == Vec3(1, 0, 0));
}

TEST_CASE("openscad/text is the font's exact outline at OpenSCAD's size") {
    // 'H' of DejaVu Sans has only straight edges, so OpenSCAD's own export of it is exact up
    // to its own rounding (within 1e-4 of the size): linear_extrude(1) text("H", size = 10) spans x
    // 1.36299 … 9.08009 and y 0 … 10.1248 in its STL. kerf takes the font's units exactly:
    // 201, 1339 and 1493 of 2048 per em, the em being size / 0.72. OpenSCAD's y is kerf's −z.
    const Read r =
        readCsg(extrude("height = 1", "text(text = \"H\", size = 10, font = \"DejaVu Sans\");"));
    const double em = 10 / 0.72 / 2048;
    const SpanList across = spansOf(r, {-10, 0.5, -2}, {1, 0, 0});
    REQUIRE(across.size() == 2);  // the two stems
    CHECK(across[0].in.t - 10 == Approx(201 * em).margin(1e-9));
    CHECK(across[1].out.t - 10 == Approx(1339 * em).margin(1e-9));
    CHECK(across[0].in.t - 10 == Approx(1.36299).margin(1e-3));
    CHECK(across[1].out.t - 10 == Approx(9.08009).margin(1e-3));
    const SpanList up = spansOf(r, {2, 0.5, 10}, {0, 0, -1});
    REQUIRE(up.size() == 1);
    CHECK(up[0].in.t == Approx(10).margin(1e-9));
    CHECK(up[0].out.t - 10 == Approx(1493 * em).margin(1e-9));
    CHECK(up[0].out.t - 10 == Approx(10.1248).margin(1e-3));
}

TEST_CASE("openscad/offset(r) rounds a square exactly") {
    // square(2) grown by 1: x from −1 to 3 along the middle, and the corner a quarter circle
    // of radius 1 about (2, 2): along the diagonal it ends at 2 + 1/√2.
    const Read r = readCsg(extrude("height = 1", "offset(r = 1) square(2);"));
    requireEnds(spansOf(r, {-10, 0.5, -1}, {1, 0, 0}), {9, 13});
    const SpanList diagonal = spansOf(r, {0, 0.5, 0}, {std::sqrt(0.5), 0, -std::sqrt(0.5)});
    REQUIRE(diagonal.size() == 1);
    CHECK(diagonal[0].out.t == Approx(2 * std::sqrt(2.0) + 1).epsilon(1e-9));
    const Read inset = readCsg(extrude("height = 1", "offset(r = -0.5) square(2);"));
    requireEnds(spansOf(inset, {-10, 0.5, -1}, {1, 0, 0}), {10.5, 11.5});
}

TEST_CASE("openscad/2-D errors") {
    requireError(readCsg("circle(r = 1);\n"), 1, 1, "2-D shape outside linear_extrude");
    requireError(readCsg(extrude("height = 1", "cube(1);")), 2, 3,
                 "cube is a solid under an extrusion");
    requireError(readCsg(extrude("height = 1", "offset(delta = 1, chamfer = false) square(1);")), 2,
                 3, "offset(delta) is not supported");
    requireError(readCsg(extrude("height = 1", "text(text = \"A\", direction = \"ttb\");")), 2, 3,
                 "text direction 'ttb' is not supported");

    requireError(
        readCsg(extrude("height = 1",
                        "polygon(points = [[0, 0], [1, 0], [0, 1]], paths = [[0, 1, 3]]);")),
        2, 55, "indices into points");
    requireError(readCsg(extrude("height = 1",
                                 "multmatrix([[1, 0, 0, 0], [0, 0, 0, 0], [0, 0, 1, 0], [0, 0, 0, "
                                 "1]]) square(1);")),
                 2, 14, "singular");
}

TEST_CASE(
    "openscad/profileTransform: exact when rigid, a lower bound with the same sign when not") {
    // Oracle: the image of the square [0, 1]² under each map is a rectangle whose exact
    // distance profileRect gives (the rotation's in the turned frame).
    auto field = [](const Profile& p) {
        ExprGraph g;
        return Tape::compile(g, p.distance(g, g.x(), g.y()));
    };
    const Profile unit = profileRect(Vec2(0), Vec2(1));
    const double c = std::cos(0.5), s = std::sin(0.5);
    const double turn[6] = {c, -s, 3, s, c, -1};      // rotate by 0.5 rad, then move
    const double stretch[6] = {-4, 0, 1, 0, 0.5, 2};  // mirror and scale by 4 in x, 0.5 in y
    const auto turned = field(profileTransform(unit, turn));
    const auto stretched = field(profileTransform(unit, stretch));
    const auto exactStretched = field(profileRect(Vec2(-3, 2), Vec2(1, 2.5)));
    const auto exactUnit = field(unit);
    for (int i = 0; i < 41; ++i) {
        for (int j = 0; j < 41; ++j) {
            const Vec2 p(-5 + 0.25 * i, -3 + 0.25 * j);
            // The turned square's distance at p is the unit square's at the point turned back.
            const Vec2 q = p - Vec2(3, -1);
            const Vec2 back(c * q.x + s * q.y, -s * q.x + c * q.y);
            CHECK(turned->eval(Vec3(p, 0)) == Approx(exactUnit->eval(Vec3(back, 0))).margin(1e-12));
            const double f = stretched->eval(Vec3(p, 0)), d = exactStretched->eval(Vec3(p, 0));
            CHECK((f > 0) == (d > 0));
            CHECK(std::abs(f) <= std::abs(d) + 1e-12);
            CHECK(std::abs(f) >= 0.5 / 4 * std::abs(d) - 1e-12);  // within σ_min/σ_max of it
        }
    }
}
