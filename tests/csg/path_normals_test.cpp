// pathField::rangeGradient near curves: where a Bézier or an arc is the only outline near a
// box, the gradient enclosure is its normal sector — it must hold every difference quotient
// of the field in the box, and be narrow often enough that slices prove curved edges simple.
#include <catch2/catch.hpp>
#include <random>

#include "csg/profiles/profile_field.h"
#include "io/font_outline.h"

using namespace kerf;

namespace {

PathSegment line(Vec2 a, Vec2 b) {
    PathSegment s;
    s.p[0] = a;
    s.p[1] = b;
    return s;
}

PathSegment curve(PathSegment::Kind kind, std::array<Vec2, 4> p) {
    PathSegment s;
    s.kind = kind;
    s.p = p;
    return s;
}

PathSegment arc(Vec2 from, Vec2 to, Vec2 center, bool ccw) {
    PathSegment s;
    s.kind = PathSegment::Kind::Arc;
    s.p = {from, to, center, Vec2(0.0)};
    s.ccw = ccw;
    return s;
}

/// A shape of curves: a cubic lens, a quadratic bump, a clockwise arc hole, and a cubic that
/// loops over itself (where nothing may be proven near the crossing).
PathShape curvedShape() {
    PathShape shape;
    PathLoop outer;
    outer.segments.push_back(
        curve(PathSegment::Kind::Cubic, {Vec2(0, 0), Vec2(1, -1), Vec2(3, -1), Vec2(4, 0)}));
    outer.segments.push_back(
        curve(PathSegment::Kind::Quadratic, {Vec2(4, 0), Vec2(5, 2), Vec2(4, 4), Vec2(0)}));
    outer.segments.push_back(line({4, 4}, {0, 4}));
    outer.segments.push_back(
        curve(PathSegment::Kind::Cubic, {Vec2(0, 4), Vec2(-1, 3), Vec2(-1, 1), Vec2(0, 0)}));
    shape.loops.push_back(outer);
    PathLoop hole;
    hole.segments.push_back(arc({2.5, 2}, {1.5, 2}, {2, 2}, false));
    hole.segments.push_back(arc({1.5, 2}, {2.5, 2}, {2, 2}, false));
    shape.loops.push_back(hole);
    PathLoop knot;
    knot.segments.push_back(
        curve(PathSegment::Kind::Cubic, {Vec2(6, 0), Vec2(9, 2), Vec2(5, 2), Vec2(8, 0)}));
    knot.segments.push_back(line({8, 0}, {6, 0}));
    shape.loops.push_back(knot);
    return shape;
}

/// Checks f(p) − f(q) ∈ g·(p − q) at random pairs of random boxes; returns how many boxes had
/// a gradient component of one sign (proven monotone).
int checkEnclosures(const ScalarField& f, Vec2 lo0, Vec2 hi0, double maxSize, uint64_t seed,
                    double slack) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> ux(lo0.x, hi0.x), uy(lo0.y, hi0.y), unit(0.0, 1.0);
    int monotone = 0;
    for (int i = 0; i < 4000; ++i) {
        const double size = maxSize * std::pow(2.0, -12.0 * unit(rng));
        const Vec2 lo(ux(rng), uy(rng));
        const Vec2 hi = lo + Vec2(size, size * (0.5 + unit(rng)));
        Interval g[3];
        const Interval r =
            f.rangeGradient(Interval(lo.x, hi.x), Interval(lo.y, hi.y), Interval(0.0), g);
        monotone += g[0].lo > 0.0 || g[0].hi < 0.0 || g[1].lo > 0.0 || g[1].hi < 0.0;
        for (int k = 0; k < 20; ++k) {
            const Vec2 p = lo + Vec2(unit(rng), unit(rng)) * (hi - lo);
            const Vec2 q = lo + Vec2(unit(rng), unit(rng)) * (hi - lo);
            const double fp = f.value(Vec3(p, 0.0)), fq = f.value(Vec3(q, 0.0));
            REQUIRE(r.contains(fp));
            const Vec2 d = p - q;
            const double dlo =
                std::min(g[0].lo * d.x, g[0].hi * d.x) + std::min(g[1].lo * d.y, g[1].hi * d.y);
            const double dhi =
                std::max(g[0].lo * d.x, g[0].hi * d.x) + std::max(g[1].lo * d.y, g[1].hi * d.y);
            INFO("box (" << lo.x << "," << lo.y << ")-(" << hi.x << "," << hi.y << ") g=["
                         << g[0].lo << "," << g[0].hi << "]x[" << g[1].lo << "," << g[1].hi
                         << "] diff " << fp - fq);
            REQUIRE(fp - fq >= dlo - slack);
            REQUIRE(fp - fq <= dhi + slack);
        }
    }
    return monotone;
}

}  // namespace

TEST_CASE("pathField gradient enclosures near Béziers and arcs hold every difference quotient") {
    const auto f = pathField(curvedShape());
    // The Bézier distance is refined to 2⁻³⁴ of the segment's size (csg/profiles/profile_field.h):
    // two such errors, on segments about 5 long.
    const double slack = 2.0 * 0x1p-34 * 6.0 + 1e-14;
    const int monotone = checkEnclosures(*f, Vec2(-1.5, -1.5), Vec2(9.5, 4.5), 0.4, 11, slack);
    CHECK(monotone > 800);  // most small boxes on the curves are proven monotone
}

TEST_CASE("pathField gradient enclosures hold on a glyph's outline") {
    // A real outline: 'g' of DejaVu Sans, quadratic Béziers joined smoothly.
    TextSpec spec;
    spec.text = "g";
    const TextOutline text = layoutText(spec);
    REQUIRE(!text.shape.loops.empty());
    const auto f = pathField(text.shape);
    const int monotone =
        checkEnclosures(*f, text.ink.lo - 0.05, text.ink.hi, 0.05, 12, 2.0 * 0x1p-34 * 2.0 + 1e-14);
    CHECK(monotone > 300);
}

TEST_CASE("pathField gradient on the outline points out, at corners too") {
    // At a vertex the probe along one edge's normal lands on the other edge; the gradient must
    // still be a finite unit vector that leads out of the shape.
    PathShape shape;
    PathLoop loop;
    const Vec2 corners[5] = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 2), Vec2(0.5, 1),
                             Vec2(0, 2)};  // one reflex
    for (int i = 0; i < 5; ++i) loop.segments.push_back(line(corners[i], corners[(i + 1) % 5]));
    shape.loops.push_back(loop);
    const auto f = pathField(shape);
    for (const Vec2 q : corners) {
        Vec3 g;
        f->valueGradient(Vec3(q, 0.0), g);
        INFO("corner (" << q.x << "," << q.y << ") g=(" << g.x << "," << g.y << ")");
        REQUIRE(std::isfinite(g.x));
        REQUIRE(std::isfinite(g.y));
        CHECK(glm::length(Vec2(g)) == Approx(1.0));
        // A step along g leaves the shape; a step against it enters (or stays on) it.
        CHECK(f->value(Vec3(q + 1e-6 * Vec2(g), 0.0)) > 0.0);
    }
}
