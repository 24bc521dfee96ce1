// Profiles in the language: circle, rect, polygon, path, offset and 2-D Booleans inside
// extrude and revolve, their values against closed forms, and the errors bad input gives.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "csg/profiles/profile_path.h"
#include "lang_test_util.h"

using namespace kerf;
using kerf::test::compileText;
using kerf::test::firstObject;
using kerf::test::requireOneError;

TEST_CASE("profiles: an extruded circle has the cylinder's distance on its side") {
    const NodePtr n =
        firstObject("object extrude { profile circle { center [0.5, 0] radius 1 } height 4 };");
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> coord(-2.0, 2.0), height(1.5, 2.5);
    for (int i = 0; i < 500; ++i) {
        const Vec3 p(coord(rng), height(rng), coord(rng));
        const double side = std::hypot(p.x - 0.5, p.z) - 1.0;
        const double expected = std::max(side, std::abs(p.y - 2.0) - 2.0);
        REQUIRE(n->value(p) == Approx(expected).margin(1e-12));
    }
}

TEST_CASE("profiles: polygon with a hole, offset rect and 2-D Booleans against closed forms") {
    const NodePtr frame = firstObject(
        "object extrude { profile polygon { points [[-2, -2], [2, -2], [2, 2], [-2, 2]] "
        "holes [[[-1, -1], [1, -1], [1, 1], [-1, 1]]] } height 10 center true };");
    const NodePtr rounded = firstObject(
        "object extrude { profile offset { distance 0.5 profile rect { min [-1, -1] max [1, 1] } } "
        "height 10 "
        "center true };");
    const NodePtr lens = firstObject(
        "object extrude { profile intersection { circle { center [-0.5, 0] } circle { center [0.5, "
        "0] } } "
        "height 10 center true };");
    const auto square = [](Vec2 p, double h) {
        const Vec2 q = glm::abs(p) - Vec2(h);
        return glm::length(glm::max(q, Vec2(0.0))) + std::min(std::max(q.x, q.y), 0.0);
    };
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> coord(-3.0, 3.0);
    for (int i = 0; i < 1000; ++i) {
        const Vec2 p(coord(rng), coord(rng));
        const Vec3 at(p.x, 0.3, p.y);  // profiles are drawn in (x, z)
        INFO("p=(" << p.x << "," << p.y << ")");
        REQUIRE(frame->value(at) ==
                Approx(std::max(square(p, 2.0), -square(p, 1.0))).margin(1e-12));
        REQUIRE(rounded->value(at) == Approx(square(p, 1.0) - 0.5).margin(1e-12));
        const double a = glm::length(p - Vec2(-0.5, 0)) - 1.0,
                     b = glm::length(p - Vec2(0.5, 0)) - 1.0;
        REQUIRE(lens->value(at) == Approx(std::max(a, b)).margin(1e-12));
    }
}

TEST_CASE("profiles: a circle drawn as a path of arcs and a revolved circle (torus)") {
    const NodePtr disc = firstObject(
        "object extrude { profile path { start [1, 0] arc [[-1, 0], [0, 0]] arc [[1, 0], [0, 0]] } "
        "height 10 "
        "center true };");
    const NodePtr torus =
        firstObject("object revolve { profile circle { center [3, 0] radius 1 } };");
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> coord(-4.0, 4.0), small(-0.9, 0.9);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 p(coord(rng), small(rng), coord(rng));
        INFO("p=(" << p.x << "," << p.y << "," << p.z << ")");
        REQUIRE(disc->value(p) == Approx(std::hypot(p.x, p.z) - 1.0).margin(1e-12));
        REQUIRE(torus->value(p) ==
                Approx(std::hypot(std::hypot(p.x, p.z) - 3.0, p.y) - 1.0).margin(1e-12));
    }
}

TEST_CASE("profiles: extrude scale [sx, sy] tapers each profile axis on its own") {
    // A unit circle, 2 high, scaled by 0.5 along u (x) and 3 along v (z) at the top: at height
    // y it is an ellipse of half-axes 1 − 0.25·y and 1 + y, the field's sign its inside test.
    const NodePtr e =
        firstObject("object extrude { profile circle { radius 1 } height 2 scale [0.5, 3] };");
    for (double y : {0.2, 1.0, 1.7}) {
        const double a = 1.0 - 0.25 * y, b = 1.0 + y;
        INFO("y=" << y);
        CHECK(e->value(Vec3(0.999 * a, y, 0.0)) < 0.0);
        CHECK(e->value(Vec3(1.001 * a, y, 0.0)) > 0.0);
        CHECK(e->value(Vec3(0.0, y, 0.999 * b)) < 0.0);
        CHECK(e->value(Vec3(0.0, y, -1.001 * b)) > 0.0);
        CHECK(e->value(Vec3(0.7 * a, y, 0.7 * b)) < 0.0);    // 0.98 of the way out
        CHECK(e->value(Vec3(0.72 * a, y, 0.72 * b)) > 0.0);  // 1.04
    }
}

TEST_CASE("profiles: a self-touching polygon is filled even-odd") {
    // A bow tie: two triangles meeting at the origin.
    const NodePtr tie = firstObject(
        "object extrude { profile polygon { points [[-1, -1], [1, 1], [1, -1], [-1, 1]] } height 1 "
        "};");
    CHECK(tie->value(Vec3(0.7, 0.5, 0.0)) < 0.0);
    CHECK(tie->value(Vec3(-0.7, 0.5, 0.0)) < 0.0);
    CHECK(tie->value(Vec3(0.0, 0.5, 0.7)) > 0.0);
}

TEST_CASE("profiles: errors") {
    requireOneError("object extrude { profile polygon { points [[0, 0], [1, 0]] } height 1 };", 1,
                    43, "points of polygon needs at least 3 points, got 2");
    requireOneError("object extrude { profile rect { min [1, 0] max [0, 1] } height 1 };", 1, 26,
                    "empty rect");
    requireOneError("object extrude { profile circle { radius -1 } height 1 };", 1, 42,
                    "circle radius must be positive");
    requireOneError("object extrude { profile circle { center [1, 2, 3] } height 1 };", 1, 42,
                    "expects a 2-D point [x, y], got a list of 3 values");
    requireOneError("object extrude { profile circle { radius 1 } height 0 };", 1, 53,
                    "extrude height must be positive");
    requireOneError("object extrude { profile circle { radius 1 } height 1 scale 0 };", 1, 61,
                    "extrude scale must be positive");
    requireOneError("object extrude { profile circle { radius 1 } height 1 scale [1, 0] };", 1, 61,
                    "extrude scale must be positive, got [1, 0]");
    requireOneError("object extrude { profile circle { radius 1 } height 1 scale [1, 2, 3] };", 1,
                    61, "expects a 2-D point [x, y], got a list of 3 values");
    requireOneError("object revolve { profile circle { center [2, 0] } angle 400 };", 1, 57,
                    "revolve angle must be in (0, 360]");
    requireOneError("object revolve { profile circle { center [-2, 0] } };", 1, 26,
                    "the profile lies at u ≤ 0");
    requireOneError("object circle { radius 1 };", 1, 8, "'circle' is a 2-D profile, not a solid");
    requireOneError("object extrude { profile sphere { } height 1 };", 1, 26,
                    "expected a 2-D profile");
    requireOneError("object extrude { profile 3 height 1 };", 1, 26,
                    "property 'profile' of extrude expects a 2-D profile");
    requireOneError("object extrude { profile path { line [1, 0] } height 1 };", 1, 33,
                    "'line' before 'start'");
    requireOneError(
        "object extrude { profile path { start [1, 0] arc [[-2, 0], [0, 0]] } height 1 };", 1, 50,
        "start and end must be at the same distance from the center");
    requireOneError(
        "object extrude { profile polygon { points [[0, 0], [1, 0], [0, 1e308 * 10]] } height 1 };",
        1, 70, "value is not finite");
    requireOneError(
        "object extrude { profile union { circle { } circle { } translate <1, 0, 0> } height 1 };",
        1, 56, "a 2-D profile takes no modifiers");
    requireOneError("object extrude { profile path { start [0, 0] loop [1, 0] } height 1 };", 1, 46,
                    "unknown step 'loop' in path");
}
