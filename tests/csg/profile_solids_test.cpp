// Profiles (csg/profiles/profile.h) as 2-D distances, and extrude / revolve traced against closed
// forms.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "csg/profiles/profile.h"
#include "csg/tape/tape.h"
#include "csg/trace_context.h"
#include "csg/tree/span.h"

using namespace kerf;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// The profile's d at (u, v), through a compiled tape (u = x, v = y).
double profileAt(const Profile& p, Vec2 q) {
    ExprGraph g;
    const ExprId root = p.distance(g, g.x(), g.y());
    return Tape::compile(g, root)->eval(Vec3(q, 0.0));
}

/// Entry and exit of the first span along the ray, or nothing.
SpanList traced(const NodePtr& node, const Ray& ray, double tolerance = 1e-10) {
    TraceContext ctx;
    ctx.relTolerance = tolerance;
    SpanList s;
    node->spans(ray, 0.0, kInf, ctx, s);
    return s;
}

}  // namespace

TEST_CASE("Profile::offset of a square has exactly rounded corners") {
    const Profile square = profileRect({-1, -1}, {1, 1});
    const Profile grown = profileOffset(square, 0.5);
    const Profile shrunk =
        profileOffset(profilePolygon({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}, {}), -0.25);
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> coord(-2.5, 2.5);
    for (int i = 0; i < 3000; ++i) {
        const Vec2 p(coord(rng), coord(rng));
        const Vec2 q = glm::abs(p) - Vec2(1.0);
        const double exact =
            glm::length(glm::max(q, Vec2(0.0))) + std::min(std::max(q.x, q.y), 0.0);
        INFO("p=(" << p.x << "," << p.y << ")");
        REQUIRE(profileAt(square, p) == Approx(exact).margin(1e-12));
        // Grown by 0.5: the corner at (1, 1) becomes a quarter circle of radius 0.5 around it.
        REQUIRE(profileAt(grown, p) == Approx(exact - 0.5).margin(1e-12));
        REQUIRE(profileAt(shrunk, p) == Approx(exact + 0.25).margin(1e-12));
    }
}

TEST_CASE("Profile::Booleans are min and max of their operands") {
    const Profile a = profileCircle({-0.5, 0}, 1.0), b = profileCircle({0.5, 0}, 1.0);
    const Profile u = profileUnion({a, b}), n = profileIntersection({a, b}),
                  d = profileDifference({a, b});
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> coord(-2.0, 2.0);
    for (int i = 0; i < 2000; ++i) {
        const Vec2 p(coord(rng), coord(rng));
        const double da = glm::length(p - Vec2(-0.5, 0)) - 1.0,
                     db = glm::length(p - Vec2(0.5, 0)) - 1.0;
        REQUIRE(profileAt(u, p) == Approx(std::min(da, db)).margin(1e-12));
        REQUIRE(profileAt(n, p) == Approx(std::max(da, db)).margin(1e-12));
        REQUIRE(profileAt(d, p) == Approx(std::max(da, -db)).margin(1e-12));
    }
    REQUIRE(n.bounds.lo.x == Approx(-0.5));
    REQUIRE(n.bounds.hi.x == Approx(0.5));
    REQUIRE(u.bounds.hi.x == Approx(1.5));
}

TEST_CASE("makeExtrude of a circle is a cylinder") {
    const NodePtr cylinder = makeExtrude(profileCircle({0.25, 0}, 1.0), {/*height*/ 2.0});
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 300; ++i) {
        // Horizontal rays across the side: enter and leave the circle x = 0.25 ± √(1 − z²).
        const double y = 0.05 + 1.9 * unit(rng), z = -0.95 + 1.9 * unit(rng);
        const Ray ray{Vec3(-5.0, y, z), Vec3(1.0, 0.0, 0.0)};
        const SpanList s = traced(cylinder, ray);
        REQUIRE(s.size() == 1);
        const double half = std::sqrt(1.0 - z * z);
        REQUIRE(s[0].in.t == Approx(5.25 - half).epsilon(1e-9));
        REQUIRE(s[0].out.t == Approx(5.25 + half).epsilon(1e-9));
    }
    // Down the axis: the caps at y = 2 and y = 0.
    const SpanList s = traced(cylinder, {Vec3(0.25, 5.0, 0.0), Vec3(0.0, -1.0, 0.0)});
    REQUIRE(s.size() == 1);
    REQUIRE(s[0].in.t == Approx(3.0).epsilon(1e-9));
    REQUIRE(s[0].out.t == Approx(5.0).epsilon(1e-9));
}

TEST_CASE("makeExtrude with scale tapers linearly and center puts it about y = 0") {
    ExtrudeOptions o;
    o.height = 2.0;
    o.scale = Vec2(0.5);
    o.center = true;
    const NodePtr cone = makeExtrude(profileCircle({0, 0}, 1.0), o);
    for (double y : {-0.9, -0.3, 0.4, 0.95}) {
        const double radius = 1.0 + (0.5 - 1.0) * (y + 1.0) / 2.0;
        const SpanList s = traced(cone, {Vec3(-3.0, y, 0.0), Vec3(1.0, 0.0, 0.0)});
        REQUIRE(s.size() == 1);
        REQUIRE(s[0].in.t == Approx(3.0 - radius).epsilon(1e-9));
        REQUIRE(s[0].out.t == Approx(3.0 + radius).epsilon(1e-9));
    }
}

TEST_CASE("makeExtrude with twist turns a square within its bounding cylinder") {
    ExtrudeOptions o;
    o.height = 3.0;
    o.twist = 90.0;
    const NodePtr twisted = makeExtrude(profileRect({-1, -1}, {1, 1}), o);
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 200; ++i) {
        // Along a ray at height y toward the axis from the angle φ = atan2(z, x): the square,
        // turned about +y by θ = 90°·y/3 (right-handed, so φ decreases by θ), is entered at
        // the distance 1/max(|cos(φ+θ)|, |sin(φ+θ)|) from the axis.
        const double y = 0.05 + 2.9 * unit(rng), phi = 2.0 * kPi * unit(rng);
        const Vec3 dir(-std::cos(phi), 0.0, -std::sin(phi));
        const SpanList s = traced(twisted, {Vec3(0.0, y, 0.0) - 4.0 * dir, dir});
        REQUIRE(!s.empty());
        const double theta = 0.5 * kPi * y / 3.0;
        const double entry =
            1.0 / std::max(std::abs(std::cos(phi + theta)), std::abs(std::sin(phi + theta)));
        INFO("y=" << y << " phi=" << phi);
        REQUIRE(s[0].in.t == Approx(4.0 - entry).epsilon(1e-9));
        REQUIRE(4.0 - s[0].in.t <= std::sqrt(2.0) * (1 + 1e-12));
    }
}

TEST_CASE("makeRevolve of a rectangle is a tube and of a circle a torus") {
    const NodePtr tube = makeRevolve(profileRect({1.0, -0.5}, {2.0, 0.5}));
    const NodePtr torus = makeRevolve(profileCircle({3.0, 0.0}, 1.0));
    for (double phi : {0.0, 0.7, 2.0, 4.5}) {
        const Vec3 dir(-std::cos(phi), 0.0, -std::sin(phi));
        for (double y : {-0.3, 0.0, 0.45}) {
            // Through the axis: the tube is crossed twice, at radii 2 → 1 and 1 → 2.
            const SpanList s = traced(tube, {Vec3(0.0, y, 0.0) - 5.0 * dir, dir});
            REQUIRE(s.size() == 2);
            REQUIRE(s[0].in.t == Approx(3.0).epsilon(1e-9));
            REQUIRE(s[0].out.t == Approx(4.0).epsilon(1e-9));
            REQUIRE(s[1].in.t == Approx(6.0).epsilon(1e-9));
            REQUIRE(s[1].out.t == Approx(7.0).epsilon(1e-9));
            // The torus at height y: radii 3 ± √(1 − y²).
            const SpanList t = traced(torus, {Vec3(0.0, y, 0.0) - 5.0 * dir, dir});
            const double half = std::sqrt(1.0 - y * y);
            REQUIRE(t.size() == 2);
            REQUIRE(t[0].in.t == Approx(5.0 - 3.0 - half).epsilon(1e-9));
            REQUIRE(t[0].out.t == Approx(5.0 - 3.0 + half).epsilon(1e-9));
        }
    }
}

TEST_CASE("makeRevolve by a partial angle keeps the wedge from +x toward +z") {
    for (double degrees : {90.0, 135.0, 270.0}) {
        const NodePtr part = makeRevolve(profileRect({1.0, -0.5}, {2.0, 0.5}), degrees);
        for (double phi = 0.05; phi < 2 * kPi; phi += 0.1) {
            const Vec3 p(1.5 * std::cos(phi), 0.0, 1.5 * std::sin(phi));
            const bool inWedge = phi * 180.0 / kPi < degrees;
            INFO("degrees " << degrees << " phi " << phi);
            REQUIRE((part->value(p) <= 0.0) == inWedge);
        }
    }
}

TEST_CASE("makeExtrude of a polygon with a hole against the 2-D crossings") {
    // A 4×4 square with a 2×2 hole: a ray along x at z = 0 crosses [−2, −1] and [1, 2].
    const Profile frame = profilePolygon({{-2, -2}, {2, -2}, {2, 2}, {-2, 2}},
                                         {{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}});
    const NodePtr solid = makeExtrude(frame, {1.0});
    for (double z : {-1.5, 0.0, 0.3}) {
        const SpanList s = traced(solid, {Vec3(-3.0, 0.5, z), Vec3(1.0, 0.0, 0.0)});
        if (std::abs(z) < 1.0) {
            REQUIRE(s.size() == 2);
            REQUIRE(s[0].in.t == Approx(1.0).epsilon(1e-9));
            REQUIRE(s[0].out.t == Approx(2.0).epsilon(1e-9));
            REQUIRE(s[1].in.t == Approx(4.0).epsilon(1e-9));
            REQUIRE(s[1].out.t == Approx(5.0).epsilon(1e-9));
        } else {
            REQUIRE(s.size() == 1);
            REQUIRE(s[0].in.t == Approx(1.0).epsilon(1e-9));
            REQUIRE(s[0].out.t == Approx(5.0).epsilon(1e-9));
        }
    }
}
