// Full turns of polygons in closed form (csg/profiles/lathe.h, makeRevolve): a lathe gives the
// same spans as the implicit revolution it stands for, on random rays, rays through the
// vertices' circles, level rays at the vertices' heights, rays along and through the axis;
// hand-solved cases at huge and tiny scales; circles become tori.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "csg/profiles/profile.h"
#include "tests/csg/implicit_comparison.h"

using namespace kerf;

namespace {

/// POV-Ray's lathe1a outline (12 points, the last repeating the first) in (r, y).
const std::vector<Vec2> kVase = {{2, 1},   {2, -1},    {3, -1},  {3.4, -2}, {4, -1.1}, {3.6, -0.9},
                                 {2.6, 0}, {3.6, 0.9}, {4, 1.1}, {3.4, 2},  {3, 1},    {2, 1}};

/// An outline reaching across the axis (only r ≥ 0 counts) with a hole, vertices on round
/// coordinates and an edge on the axis after clamping.
Profile acrossAxis() {
    return profilePolygon({{-1, -2}, {3, -2}, {3, 0}, {1.5, 0.5}, {3, 2}, {-1, 2}},
                          {{{1, -1}, {2, -1}, {1.5, -0.25}}});
}

Ray aimed(Vec3 from, Vec3 to) { return {from, glm::normalize(to - from)}; }

void requireLikeImplicit(const NodePtr& lathe, const std::vector<Vec2>& vertices, double reach,
                         double low, double high, uint64_t seed) {
    const NodePtr implicit = implicitOf(lathe);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), turn(0.0, 2.0 * 3.14159265358979323846);
    std::uniform_int_distribution<size_t> pick(0, vertices.size() - 1);
    const double mid = 0.5 * (low + high), half = 0.5 * (high - low);
    for (int i = 0; i < 3000; ++i) {
        Ray ray;
        const int kind = i % 5;
        const Vec3 random(reach * unit(rng), mid + half * unit(rng), reach * unit(rng));
        const Vec3 from =
            random + 3.0 * reach * glm::normalize(Vec3(unit(rng), unit(rng), unit(rng)));
        if (kind == 0) {  // through a vertex's circle
            const Vec2 v = vertices[pick(rng)];
            const double a = turn(rng);
            ray = aimed(from, Vec3(v.x * std::cos(a), v.y, v.x * std::sin(a)));
        } else if (kind == 1) {  // level (in a cap's plane: by hand, the isolation crawls)
            const double a = turn(rng);
            ray = {Vec3(from.x, random.y, from.z), Vec3(std::cos(a), 0.0, std::sin(a))};
        } else if (kind == 2) {  // parallel to the axis (on it: by hand, the isolation crawls)
            ray = {Vec3(random.x, high + 1.0, random.z), Vec3(0.0, -1.0, 0.0)};
        } else if (kind == 3) {  // through the axis
            ray = aimed(from, Vec3(0.0, random.y, 0.0));
        } else {
            ray = aimed(from, random);
        }
        const Traced exact = traced(lathe, ray);
        CHECK(exact.stats.rootSteps == 0);
        const Traced isolated = traced(implicit, ray, 1e-10);
        // At a vertex the implicit's gradient picks either edge's normal.
        requireSameSpans(exact.spans, isolated.spans, ray, kind != 0 && kind != 1);
    }
}

}  // namespace

TEST_CASE("lathe: a polygon's full turn has the implicit's spans, without root isolation") {
    SECTION("POV-Ray's lathe1a vase") {
        const NodePtr lathe = makeRevolve(profilePolygon(kVase, {}));
        REQUIRE(lathe->kind() == NodeKind::Implicit);  // the implicit's kind, traced closed
        requireLikeImplicit(lathe, kVase, 4.0, -2.0, 2.0, 25);
    }
    SECTION("an outline across the axis, with a hole") {
        const NodePtr lathe = makeRevolve(acrossAxis());
        requireLikeImplicit(
            lathe,
            {{0, -2}, {3, -2}, {3, 0}, {1.5, 0.5}, {3, 2}, {0, 2}, {1, -1}, {2, -1}, {1.5, -0.25}},
            3.0, -2.0, 2.0, 26);
    }
    SECTION("a rectangle (a tube) and a rotated rectangle (a polygon)") {
        requireLikeImplicit(makeRevolve(profileRect({1, -1}, {2, 1})), {{1, -1}, {2, 1}}, 2.0, -1.0,
                            1.0, 27);
        const double c = std::cos(0.5), s = std::sin(0.5);
        const double turn[6] = {c, -s, 2.5, s, c, 0};
        requireLikeImplicit(makeRevolve(profileTransform(profileRect({-1, -1}, {1, 1}), turn)),
                            {{2.5, 0}}, 4.0, -1.5, 1.5, 28);
    }
}

TEST_CASE("lathe: a path of lines and Béziers turned has the implicit's spans") {
    // A goblet's outline (as models/profiles.kerf draws it, without its arc): a foot, a stem,
    // a cubic bowl, a quadratic lip, back down the inside by a cubic to the axis.
    PathShape shape;
    PathLoop loop;
    const auto add = [&](PathSegment::Kind kind, std::array<Vec2, 4> p) {
        PathSegment s;
        s.kind = kind;
        s.p = p;
        loop.segments.push_back(s);
    };
    using K = PathSegment::Kind;
    add(K::Line, {Vec2(0, 0), Vec2(0.5, 0)});
    add(K::Quadratic, {Vec2(0.5, 0), Vec2(0.5, 0.08), Vec2(0.1, 0.1)});
    add(K::Line, {Vec2(0.1, 0.1), Vec2(0.08, 0.7)});
    add(K::Cubic, {Vec2(0.08, 0.7), Vec2(0.6, 0.75), Vec2(0.6, 1.2), Vec2(0.55, 1.4)});
    add(K::Quadratic, {Vec2(0.55, 1.4), Vec2(0.525, 1.45), Vec2(0.5, 1.4)});
    add(K::Cubic, {Vec2(0.5, 1.4), Vec2(0.5, 1.2), Vec2(0.5, 0.85), Vec2(0, 0.82)});
    add(K::Line, {Vec2(0, 0.82), Vec2(0, 0)});
    shape.loops.push_back(loop);
    const NodePtr goblet = makeRevolve(profilePath(shape));
    requireLikeImplicit(
        goblet, {{0, 0}, {0.5, 0}, {0.1, 0.1}, {0.08, 0.7}, {0.55, 1.4}, {0.5, 1.4}, {0, 0.82}},
        0.6, 0.0, 1.45, 29);
}

TEST_CASE("lathe: hard rays against hand-solved spans, at scales 1e-6 to 1e6") {
    for (const double scale : {1e-6, 1.0, 1e6}) {
        INFO("scale " << scale);
        // The tube 1 ≤ r ≤ 2, |y| ≤ 1, scaled.
        const NodePtr tube = makeRevolve(profileRect(Vec2(1, -1) * scale, Vec2(2, 1) * scale));
        const double tol = 1e-14 * scale;
        SECTION("a level ray through the axis meets the wall twice") {
            const Traced r = traced(tube, {Vec3(-3, 0.5, 0) * scale, Vec3(1, 0, 0)});
            REQUIRE(r.spans.size() == 2);
            CHECK(r.spans[0].in.t == Approx(1 * scale).margin(tol));
            CHECK(r.spans[0].out.t == Approx(2 * scale).margin(tol));
            CHECK(r.spans[1].in.t == Approx(4 * scale).margin(tol));
            CHECK(r.spans[1].out.t == Approx(5 * scale).margin(tol));
            CHECK(r.spans[0].in.normal.x == Approx(-1.0));
            CHECK(r.spans[0].out.normal.x == Approx(1.0));
        }
        SECTION("a ray down the axis and down the wall, with -0 in its direction") {
            CHECK(traced(tube, {Vec3(0, 3, 0) * scale, Vec3(-0.0, -1, -0.0)}).spans.empty());
            const Traced r = traced(tube, {Vec3(0, 3 * scale, -1.5 * scale), Vec3(-0.0, -1, 0)});
            REQUIRE(r.spans.size() == 1);
            CHECK(r.spans[0].in.t == Approx(2 * scale).margin(tol));
            CHECK(r.spans[0].out.t == Approx(4 * scale).margin(tol));
            CHECK(r.spans[0].in.normal.y == 1.0);
            CHECK(r.spans[0].out.normal.y == -1.0);
        }
        SECTION("sloped rays: through the hole, and through a cap and the inner wall") {
            // From (0, 3, −1.5) along (0, −6, 3): |y| ≤ 1 only where |z| ≤ 0.5, in the hole.
            CHECK(traced(tube, aimed(Vec3(0, 3, -1.5) * scale, Vec3(0, -3, 1.5) * scale))
                      .spans.empty());
            // From (−3, 2, 0) along (6, −4, 0): y = −2x/3, in the tube where 1 ≤ |x| ≤ 1.5; t is
            // (x + 3)·√52/6.
            const Ray ray = aimed(Vec3(-3, 2, 0) * scale, Vec3(3, -2, 0) * scale);
            const Traced r = traced(tube, ray);
            const double k = std::sqrt(52.0) / 6.0 * scale;
            REQUIRE(r.spans.size() == 2);
            CHECK(r.spans[0].in.t == Approx(1.5 * k).margin(tol));
            CHECK(r.spans[0].out.t == Approx(2.0 * k).margin(tol));
            CHECK(r.spans[1].in.t == Approx(4.0 * k).margin(tol));
            CHECK(r.spans[1].out.t == Approx(4.5 * k).margin(tol));
            CHECK(r.spans[0].in.normal.y == Approx(1.0));   // the top cap
            CHECK(r.spans[0].out.normal.x == Approx(1.0));  // the inner wall, facing the axis
            CHECK(r.spans[1].in.normal.x == Approx(-1.0));
            CHECK(r.spans[1].out.normal.y == Approx(-1.0));
        }
        SECTION("level rays in the top cap's plane and down the axis of a solid of revolution") {
            // In the plane y = 1 the line is on the tube's boundary for 1 ≤ r ≤ 2 only.
            for (const Span& s : traced(tube, {Vec3(-3, 1, 0.5) * scale, Vec3(1, 0, 0)}).spans) {
                const double x = -3 * scale + s.in.t, x1 = -3 * scale + s.out.t;
                CHECK(std::hypot(0.5 * scale, x) >= 1 * scale * (1 - 1e-12));
                CHECK(std::hypot(0.5 * scale, x1) <= 2 * scale * (1 + 1e-12));
            }
            // The outline across the axis is solid on it from y = 2 down to −2.
            const double m[6] = {scale, 0, 0, 0, scale, 0};
            const NodePtr solid = makeRevolve(profileTransform(acrossAxis(), m));
            const Traced r = traced(solid, {Vec3(0, 3, 0) * scale, Vec3(0, -1, -0.0)});
            REQUIRE(r.spans.size() == 1);
            CHECK(r.spans[0].in.t == Approx(1 * scale).margin(tol));
            CHECK(r.spans[0].out.t == Approx(5 * scale).margin(tol));
            CHECK(r.spans[0].in.normal.y == 1.0);
        }
        SECTION("a level ray grazing the outer wall: a touch, no span or a zero one") {
            const Traced r =
                traced(tube, {Vec3(-3 * scale, 0.25 * scale, 2 * scale), Vec3(1, 0, 0)});
            for (const Span& s : r.spans) CHECK(s.out.t - s.in.t <= 1e-7 * scale);
            // Just inside the wall: a chord of length 2·√(4 − 3.99²)·scale.
            const Traced in =
                traced(tube, {Vec3(-3 * scale, 0.25 * scale, 1.99 * scale), Vec3(1, 0, 0)});
            REQUIRE(in.spans.size() == 1);
            CHECK(in.spans[0].out.t - in.spans[0].in.t ==
                  Approx(2 * std::sqrt(4 - 1.99 * 1.99) * scale).epsilon(1e-12));
        }
    }
}

TEST_CASE("lathe: circles clear of the axis are tori; arcs and part turns stay implicit") {
    const NodePtr torus = makeRevolve(profileCircle({3, 0.5}, 1));
    REQUIRE(torus->kind() == NodeKind::Transform);
    const Traced r = traced(torus, {Vec3(-5, 0.5, 0), Vec3(1, 0, 0)});
    REQUIRE(r.spans.size() == 2);
    CHECK(r.spans[0].in.t == Approx(1.0));
    CHECK(r.spans[1].out.t == Approx(9.0));
    CHECK(makeRevolve(profileCircle({0.5, 0}, 1))->kind() == NodeKind::Implicit);
    const NodePtr part = makeRevolve(profilePolygon(kVase, {}), 90.0);
    CHECK(traced(part, {Vec3(3, 5, 0.2), Vec3(0, -1, 0)}).stats.rootSteps > 0);
}
