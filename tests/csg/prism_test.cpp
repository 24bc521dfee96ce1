// Straight extrusions of plain outlines in closed form (csg/profiles/prism.h, makeExtrude): a
// polygon's prism gives the same spans as the implicit extrusion it stands for, including rays
// through vertices, along edges, vertical and in the cap planes; circles and rectangles become
// cylinders and boxes.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "csg/profiles/profile.h"
#include "csg/trace_context.h"
#include "csg/tree/solids.h"
#include "csg/tree/span.h"
#include "tests/csg/implicit_comparison.h"

using namespace kerf;

namespace {

/// A concave outline with a hole, with vertices on round coordinates (rays through them).
Profile notchedPlate() {
    return profilePolygon({{0, 0}, {4, 0}, {4, 3}, {2, 1}, {0, 3}},
                          {{{0.5, 0.5}, {1.5, 0.5}, {1, 1.5}}});
}

}  // namespace

TEST_CASE(
    "prism: a polygon's straight extrusion has the implicit's spans, without root isolation") {
    ExtrudeOptions o;
    o.height = 2.0;
    const NodePtr prism = makeExtrude(notchedPlate(), o);
    const NodePtr implicit = implicitOf(prism);
    std::mt19937_64 rng(21);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> pick(0, 4);
    const double vx[5] = {0, 4, 4, 2, 0}, vz[5] = {0, 0, 3, 1, 3};
    for (int i = 0; i < 3000; ++i) {
        Ray ray;
        // Aimed at a vertex (rays through vertices), a random point, or along y.
        const int kind = i % 3;
        const Vec3 target =
            kind == 0 ? Vec3(vx[pick(rng)], 1.0 + unit(rng), vz[pick(rng) % 1 ? 0 : pick(rng)])
                      : Vec3(2 + 2.5 * unit(rng), 1 + 1.5 * unit(rng), 1.5 + 2 * unit(rng));
        if (kind == 0) {
            const int v = pick(rng);
            ray.origin = Vec3(vx[v], 1.0, vz[v]) + 5.0 * Vec3(unit(rng), unit(rng), unit(rng));
            ray.dir = glm::normalize(Vec3(vx[v], 1.0 + 0.5 * unit(rng), vz[v]) - ray.origin);
        } else if (kind == 1) {
            ray.origin = target + 6.0 * glm::normalize(Vec3(unit(rng), unit(rng), unit(rng)));
            ray.dir = glm::normalize(target - ray.origin);
        } else {
            ray.origin = Vec3(target.x, 5.0, target.z);
            ray.dir = Vec3(0.0, -1.0, 0.0);
        }
        const Traced exact = traced(prism, ray);
        CHECK(exact.stats.rootSteps == 0);
        requireSameSpans(exact.spans, traced(implicit, ray).spans, ray, kind != 0);
    }
}

TEST_CASE("prism: hard rays against the closed form by hand") {
    ExtrudeOptions o;
    o.height = 2.0;
    const NodePtr prism = makeExtrude(notchedPlate(), o);
    SECTION("along the bottom edge z = 0 in the cap plane y = 0: on the boundary only") {
        // The line runs along an edge and a cap: it is on the closed solid's boundary from
        // x = 0 to 4 (t = 1 to 5), and no span may reach beyond that.
        const Traced r = traced(prism, {Vec3(-1, 0, 0), Vec3(1, 0, 0)});
        for (const Span& s : r.spans) {
            CHECK(s.in.t >= 1.0);
            CHECK(s.out.t <= 5.0);
        }
    }
    SECTION("through the reflex vertex (2, 1) across the notch") {
        // At z = 1 the line enters at x = 0, meets the hole's edges at x = 0.75 and 1.25,
        // passes the notch's vertex (2, 1) (a touch: inside on both sides, one span) and
        // leaves at 4.
        const Traced r = traced(prism, {Vec3(-1, 1, 1), Vec3(1, 0, 0)});
        REQUIRE(r.spans.size() == 2);
        CHECK(r.spans[0].in.t == Approx(1.0));
        CHECK(r.spans[0].out.t == Approx(1.75));
        CHECK(r.spans[1].in.t == Approx(2.25));
        CHECK(r.spans[1].out.t == Approx(5.0));
        CHECK(r.spans[1].out.normal.x == Approx(1.0));
    }
    SECTION("a vertical ray enters and leaves through the caps") {
        const Traced r = traced(prism, {Vec3(3, 5, 0.5), Vec3(0, -1, -0.0)});
        REQUIRE(r.spans.size() == 1);
        CHECK(r.spans[0].in.t == Approx(3.0));
        CHECK(r.spans[0].out.t == Approx(5.0));
        CHECK(r.spans[0].in.normal.y == 1.0);
        CHECK(r.spans[0].out.normal.y == -1.0);
        CHECK(traced(prism, {Vec3(1, 5, 0.8), Vec3(0, -1, 0)}).spans.empty());  // in the hole
    }
}

TEST_CASE("prism: extruded circles and rectangles are cylinders and boxes, also after a map") {
    ExtrudeOptions o;
    o.height = 3.0;
    const NodePtr cylinder = makeExtrude(profileCircle({1, 2}, 0.5), o);
    CHECK(cylinder->kind() == NodeKind::Cylinder);
    const NodePtr box = makeExtrude(profileRect({0, 0}, {1, 2}), o);
    CHECK(box->kind() == NodeKind::Box);
    const double c = std::cos(0.3), s = std::sin(0.3);
    const double turn[6] = {2 * c, -2 * s, 1, 2 * s, 2 * c, 0};  // a similarity: rotate, scale 2
    const NodePtr turned = makeExtrude(profileTransform(profileCircle({1, 0}, 0.5), turn), o);
    REQUIRE(turned->kind() == NodeKind::Cylinder);
    const auto p = std::get<CylinderParams>(turned->params());
    CHECK(p.radius == Approx(1.0));
    CHECK(p.a.x == Approx(1 + 2 * c));
    CHECK(p.a.z == Approx(2 * s));
    const double shear[6] = {1, 0.5, 0, 0, 1, 0};  // a circle sheared is an ellipse: implicit
    CHECK(makeExtrude(profileTransform(profileCircle({0, 0}, 1), shear), o)->kind() ==
          NodeKind::Implicit);
    // A rotated rectangle is a polygon prism, traced in closed form.
    const NodePtr rotated = makeExtrude(profileTransform(profileRect({0, 0}, {1, 2}), turn), o);
    const Ray ray{Vec3(1.2, 1.5, -10), Vec3(0, 0, 1)};
    const Traced r = traced(rotated, ray);
    CHECK(r.stats.rootSteps == 0);
    requireSameSpans(r.spans, traced(implicitOf(rotated), ray).spans, ray);
    o.twist = 30;  // not straight: implicit
    CHECK(makeExtrude(notchedPlate(), o)->kind() == NodeKind::Implicit);
}

TEST_CASE("prism: an outline of Béziers (a glyph, a path) has the implicit's spans") {
    // A quadratic and a cubic path with a hole, and text: the closed form crosses Béziers by
    // bisection on their monotone pieces; the implicit isolates the same roots on intervals.
    PathShape shape;
    PathLoop outer;
    PathSegment q;
    q.kind = PathSegment::Kind::Quadratic;
    q.p = {Vec2(0, 0), Vec2(2, -1.5), Vec2(4, 0), Vec2(0)};
    outer.segments.push_back(q);
    PathSegment c;
    c.kind = PathSegment::Kind::Cubic;
    c.p = {Vec2(4, 0), Vec2(5, 2), Vec2(-1, 5), Vec2(0, 0)};  // an S back to the start
    outer.segments.push_back(c);
    shape.loops.push_back(outer);
    PathLoop hole;
    for (auto [a, b] :
         {std::pair{Vec2(1, 0.5), Vec2(2, 0.5)}, std::pair{Vec2(2, 0.5), Vec2(1.5, 1.2)},
          std::pair{Vec2(1.5, 1.2), Vec2(1, 0.5)}}) {
        PathSegment l;
        l.p[0] = a;
        l.p[1] = b;
        hole.segments.push_back(l);
    }
    shape.loops.push_back(hole);
    ExtrudeOptions o;
    o.height = 1.0;
    const NodePtr prism = makeExtrude(profilePath(shape), o);
    const NodePtr implicit = implicitOf(prism);
    std::mt19937_64 rng(22);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < 3000; ++i) {
        const Vec3 target(2 + 2.5 * unit(rng), 0.5 + 0.7 * unit(rng), 1.5 + 2.5 * unit(rng));
        Ray ray;
        ray.origin = target + 8.0 * glm::normalize(Vec3(unit(rng), unit(rng), unit(rng)));
        ray.dir = glm::normalize(target - ray.origin);
        const Traced exact = traced(prism, ray);
        CHECK(exact.stats.rootSteps == 0);
        requireSameSpans(exact.spans, traced(implicit, ray).spans, ray);
    }
}

TEST_CASE("prism: skipping the loops the ray's shadow misses in the slab changes no span") {
    // Nine squares with square holes, one inside another's hole: a ray meets a few of them
    // within the slab, and starts inside others' boxes (far-away origins: the cull's slack).
    std::vector<Vec2> outline;
    std::vector<std::vector<Vec2>> holes;
    PathShape shape;
    const auto square = [&](Vec2 c, double h) {
        PathLoop loop;
        const Vec2 corner[4] = {c + Vec2(-h, -h), c + Vec2(h, -h), c + Vec2(h, h), c + Vec2(-h, h)};
        for (int k = 0; k < 4; ++k) {
            PathSegment s;
            s.p = {corner[k], corner[(k + 1) % 4], Vec2(0), Vec2(0)};
            loop.segments.push_back(s);
        }
        shape.loops.push_back(loop);
    };
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            square(Vec2(3.0 * i, 3.0 * j), 1.2);
            square(Vec2(3.0 * i, 3.0 * j), 0.7);
        }
    square(Vec2(3.0, 3.0), 0.3);
    ExtrudeOptions o;
    o.height = 0.5;
    const NodePtr prism = makeExtrude(profilePath(shape), o);
    const NodePtr implicit = implicitOf(prism);
    std::mt19937_64 rng(23);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 target(3 + 4 * unit(rng), 0.25 + 0.4 * unit(rng), 3 + 4 * unit(rng));
        const double far = i % 2 ? 10.0 : 1e5;
        Ray ray;
        ray.origin = target + far * glm::normalize(Vec3(unit(rng), unit(rng), unit(rng)));
        ray.dir = glm::normalize(target - ray.origin);
        requireSameSpans(traced(prism, ray).spans, traced(implicit, ray).spans, ray, false);
    }
}
