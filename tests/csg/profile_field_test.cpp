// pathField: the signed distance of polygons, arcs and Béziers against closed forms and a
// dense-sampled reference, and `range` enclosing point samples.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "csg/profiles/profile_field.h"

using namespace kerf;

namespace {

constexpr double kPi = 3.14159265358979323846;

PathSegment line(Vec2 a, Vec2 b) {
    PathSegment s;
    s.p[0] = a;
    s.p[1] = b;
    return s;
}

PathSegment arc(Vec2 from, Vec2 to, Vec2 center, bool ccw) {
    PathSegment s;
    s.kind = PathSegment::Kind::Arc;
    s.p[0] = from;
    s.p[1] = to;
    s.p[2] = center;
    s.ccw = ccw;
    return s;
}

PathLoop polygonLoop(const std::vector<Vec2>& points) {
    PathLoop loop;
    for (size_t i = 0; i < points.size(); ++i)
        loop.segments.push_back(line(points[i], points[(i + 1) % points.size()]));
    return loop;
}

double squareDistance(Vec2 p, double h) {  // the square [−h, h]², exact
    const Vec2 q = glm::abs(p) - Vec2(h);
    return glm::length(glm::max(q, Vec2(0.0))) + std::min(std::max(q.x, q.y), 0.0);
}

}  // namespace

TEST_CASE("pathField::value of a square with a square hole against the closed form") {
    PathShape shape;
    shape.loops.push_back(polygonLoop({{-2, -2}, {2, -2}, {2, 2}, {-2, 2}}));
    shape.loops.push_back(
        polygonLoop({{-1, -1}, {-1, 1}, {1, 1}, {1, -1}}));  // orientation is free
    const auto f = pathField(shape);
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> coord(-3.0, 3.0);
    for (int i = 0; i < 5000; ++i) {
        const Vec2 p(coord(rng), coord(rng));
        const double expected = std::max(squareDistance(p, 2.0), -squareDistance(p, 1.0));
        INFO("p=(" << p.x << "," << p.y << ")");
        REQUIRE(f->value(Vec3(p, 7.0)) == Approx(expected).margin(1e-12));
    }
}

TEST_CASE("pathField::value of a disc drawn as two arcs equals the circle's distance") {
    for (bool ccw : {true, false}) {
        PathShape shape;
        PathLoop loop;
        const Vec2 c(0.5, -0.25);
        loop.segments.push_back(arc(c + Vec2(1.5, 0), c + Vec2(-1.5, 0), c, ccw));
        loop.segments.push_back(arc(c + Vec2(-1.5, 0), c + Vec2(1.5, 0), c, ccw));
        shape.loops.push_back(loop);
        const auto f = pathField(shape);
        std::mt19937_64 rng(2);
        std::uniform_real_distribution<double> coord(-3.0, 3.0);
        for (int i = 0; i < 5000; ++i) {
            const Vec2 p(coord(rng), coord(rng));
            INFO("p=(" << p.x << "," << p.y << ") ccw " << ccw);
            REQUIRE(f->value(Vec3(p, 0.0)) == Approx(glm::length(p - c) - 1.5).margin(1e-12));
        }
    }
}

TEST_CASE("pathField::value of a half-disc (arc and chord) against the closed form") {
    PathShape shape;
    PathLoop loop;
    loop.segments.push_back(arc({1, 0}, {-1, 0}, {0, 0}, true));  // upper half
    loop.segments.push_back(line({-1, 0}, {1, 0}));
    shape.loops.push_back(loop);
    const auto f = pathField(shape);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> coord(-2.0, 2.0);
    for (int i = 0; i < 5000; ++i) {
        const Vec2 p(coord(rng), coord(rng));
        // Intersection of the disc and y ≥ 0: outside the disc above the axis it is the circle;
        // below it the chord segment; inside, the nearer of the two.
        double expected;
        const double dc = glm::length(p) - 1.0;
        const double dChord = glm::length(p - Vec2(std::clamp(p.x, -1.0, 1.0), 0.0));
        if (p.y >= 0.0)
            expected = dc > 0.0 ? dc : -std::min(-dc, p.y);
        else
            expected =
                std::abs(p.x) <= 1.0 ? dChord : glm::length(p - Vec2(p.x > 0 ? 1.0 : -1.0, 0.0));
        INFO("p=(" << p.x << "," << p.y << ")");
        REQUIRE(f->value(Vec3(p, 0.0)) == Approx(expected).margin(1e-12));
    }
}

TEST_CASE("pathField::value of a Bézier outline against a dense-sampled reference") {
    // A closed loop of a cubic and a quadratic with strong curvature.
    PathShape shape;
    PathLoop loop;
    PathSegment cubic;
    cubic.kind = PathSegment::Kind::Cubic;
    cubic.p = {Vec2(-1, 0), Vec2(-1, 2), Vec2(1, -1), Vec2(1, 1)};
    PathSegment quad;
    quad.kind = PathSegment::Kind::Quadratic;
    quad.p = {Vec2(1, 1), Vec2(0, -2), Vec2(-1, 0), Vec2(0, 0)};
    loop.segments = {cubic, quad};
    shape.loops.push_back(loop);
    const auto f = pathField(shape);

    // Reference: the curves sampled at 2·10⁵ parameters each, refined by golden-section search
    // around the best sample; the sign from the sampled polygon's crossing parity.
    const auto cubicAt = [&](double t) {
        const double u = 1 - t;
        return u * u * u * cubic.p[0] + 3 * u * u * t * cubic.p[1] + 3 * u * t * t * cubic.p[2] +
               t * t * t * cubic.p[3];
    };
    const auto quadAt = [&](double t) {
        const double u = 1 - t;
        return u * u * quad.p[0] + 2 * u * t * quad.p[1] + t * t * quad.p[2];
    };
    constexpr int kSamples = 200000;
    std::vector<Vec2> polyline;
    for (int i = 0; i < kSamples; ++i) polyline.push_back(cubicAt(double(i) / kSamples));
    for (int i = 0; i < kSamples; ++i) polyline.push_back(quadAt(double(i) / kSamples));
    const auto reference = [&](Vec2 p) {
        double best = 1e300;
        for (const auto& curve :
             {std::function<Vec2(double)>(cubicAt), std::function<Vec2(double)>(quadAt)}) {
            int bi = 0;
            double bd = 1e300;
            for (int i = 0; i <= 2000; ++i) {
                const double d = glm::length(curve(i / 2000.0) - p);
                if (d < bd) bd = d, bi = i;
            }
            double lo = std::max(0.0, (bi - 1) / 2000.0), hi = std::min(1.0, (bi + 1) / 2000.0);
            for (int k = 0; k < 200; ++k) {
                const double m1 = lo + (hi - lo) * 0.382, m2 = lo + (hi - lo) * 0.618;
                if (glm::length(curve(m1) - p) < glm::length(curve(m2) - p))
                    hi = m2;
                else
                    lo = m1;
            }
            best = std::min({best, bd, glm::length(curve(0.5 * (lo + hi)) - p)});
        }
        bool odd = false;
        for (size_t i = 0; i < polyline.size(); ++i) {
            const Vec2 a = polyline[i], b = polyline[(i + 1) % polyline.size()];
            if ((a.y <= p.y) != (b.y <= p.y) && a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x) > p.x)
                odd = !odd;
        }
        return odd ? -best : best;
    };
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> coord(-1.5, 1.5);
    for (int i = 0; i < 300; ++i) {
        const Vec2 p(coord(rng), coord(rng));
        const double expected = reference(p);
        INFO("p=(" << p.x << "," << p.y << ")");
        // The sampled parity can only disagree within a sample spacing of the curve.
        if (std::abs(expected) < 1e-4) continue;
        REQUIRE(f->value(Vec3(p, 0.0)) == Approx(expected).margin(1e-9));
    }
}

TEST_CASE("pathField::range encloses the values sampled in the box") {
    PathShape shape;
    shape.loops.push_back(polygonLoop({{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}}));
    PathLoop round;
    round.segments.push_back(arc({5, 1}, {5, 1}, {4, 1}, true));  // a full circle
    shape.loops.push_back(round);
    const auto f = pathField(shape);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> coord(-1.0, 6.0), size(0.0, 2.0), unit(0.0, 1.0);
    for (int i = 0; i < 500; ++i) {
        const Vec2 lo(coord(rng), coord(rng));
        const Vec2 hi = lo + Vec2(size(rng), size(rng));
        const Interval r = f->range(Interval(lo.x, hi.x), Interval(lo.y, hi.y), Interval(0.0));
        for (int k = 0; k < 50; ++k) {
            const Vec2 p = lo + Vec2(unit(rng), unit(rng)) * (hi - lo);
            const double v = f->value(Vec3(p, 0.0));
            INFO("box (" << lo.x << "," << lo.y << ")-(" << hi.x << "," << hi.y << ") p=(" << p.x
                         << "," << p.y << ") v=" << v << " range [" << r.lo << "," << r.hi << "]");
            REQUIRE(r.contains(v));
        }
    }
}

TEST_CASE("pathField::valueGradient points away from the outline with unit length") {
    PathShape shape;
    PathLoop loop;
    loop.segments.push_back(arc({1, 0}, {1, 0}, {0, 0}, true));
    shape.loops.push_back(loop);
    const auto f = pathField(shape);
    for (double a = 0.1; a < 2 * kPi; a += 0.5) {
        for (double r : {0.3, 2.0}) {
            Vec3 g;
            const double v = f->valueGradient(Vec3(r * std::cos(a), r * std::sin(a), 0.0), g);
            REQUIRE(v == Approx(r - 1.0).margin(1e-12));
            REQUIRE(g.x == Approx(std::cos(a)).margin(1e-12));
            REQUIRE(g.y == Approx(std::sin(a)).margin(1e-12));
        }
    }
}

TEST_CASE("pathField::valueGradient on the outline is the outward normal of the edge") {
    // A triangle with a slanted edge from (2, 0) to (0, 1): points exactly on it (p − q is
    // rounding noise there) must still get the edge's outward normal (1, 2)/√5.
    PathShape shape;
    shape.loops.push_back(polygonLoop({{0, 0}, {2, 0}, {0, 1}}));
    const auto f = pathField(shape);
    const Vec2 outward = glm::normalize(Vec2(1, 2));
    for (double t = 0.05; t < 1.0; t += 0.05) {
        const Vec2 p = glm::mix(Vec2(2, 0), Vec2(0, 1), t);
        Vec3 g;
        const double v = f->valueGradient(Vec3(p, 0.0), g);
        INFO("t=" << t << " v=" << v);
        REQUIRE(std::abs(v) <= 1e-15);
        REQUIRE(g.x == Approx(outward.x).margin(1e-12));
        REQUIRE(g.y == Approx(outward.y).margin(1e-12));
    }
}

TEST_CASE(
    "pathField::value with hundreds of segments (through the BVH) equals the brute-force minimum") {
    // A star-shaped outline of 600 vertices at random radii, and a Bézier loop inside it.
    std::mt19937_64 rng(6);
    std::uniform_real_distribution<double> radius(1.0, 2.0), coord(-2.5, 2.5);
    std::vector<Vec2> points;
    for (int i = 0; i < 600; ++i) {
        const double a = 2 * kPi * i / 600.0, r = radius(rng);
        points.emplace_back(r * std::cos(a), r * std::sin(a));
    }
    PathShape shape;
    shape.loops.push_back(polygonLoop(points));
    const auto f = pathField(shape);
    for (int i = 0; i < 1000; ++i) {
        const Vec2 p(coord(rng), coord(rng));
        double best = 1e300;
        bool odd = false;
        for (size_t k = 0; k < points.size(); ++k) {
            const Vec2 a = points[k], b = points[(k + 1) % points.size()];
            const double s = std::clamp(glm::dot(p - a, b - a) / glm::dot(b - a, b - a), 0.0, 1.0);
            best = std::min(best, glm::length(p - (a + s * (b - a))));
            if ((a.y <= p.y) != (b.y <= p.y) && a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x) > p.x)
                odd = !odd;
        }
        INFO("p=(" << p.x << "," << p.y << ")");
        REQUIRE(f->value(Vec3(p, 0.0)) == Approx(odd ? -best : best).margin(1e-12));
    }
}

TEST_CASE("pathField::range encloses samples near Bézier curves") {
    PathShape shape;
    PathLoop loop;
    PathSegment cubic;
    cubic.kind = PathSegment::Kind::Cubic;
    cubic.p = {Vec2(0, 0), Vec2(3, 2), Vec2(-1, 2), Vec2(2, 0)};  // a loop that crosses itself
    loop.segments.push_back(cubic);
    loop.segments.push_back(line({2, 0}, {0, 0}));
    shape.loops.push_back(loop);
    const auto f = pathField(shape);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> coord(-0.5, 2.5), size(0.0, 0.5), unit(0.0, 1.0);
    for (int i = 0; i < 500; ++i) {
        const Vec2 lo(coord(rng), coord(rng) * 0.7);
        const Vec2 hi = lo + Vec2(size(rng), size(rng));
        const Interval r = f->range(Interval(lo.x, hi.x), Interval(lo.y, hi.y), Interval(0.0));
        for (int k = 0; k < 50; ++k) {
            const Vec2 p = lo + Vec2(unit(rng), unit(rng)) * (hi - lo);
            const double v = f->value(Vec3(p, 0.0));
            INFO("p=(" << p.x << "," << p.y << ") v=" << v << " range [" << r.lo << "," << r.hi
                       << "]");
            REQUIRE(r.contains(v));
        }
    }
}

TEST_CASE("pathField::rangeGradient encloses every difference quotient in the box") {
    // The mean-value form root isolation relies on: f(p) − f(q) ∈ g·(p − q) for p, q in the
    // box, where g is the enclosure (the edge's normal when proven, else [−1, 1]).
    PathShape shape;
    shape.loops.push_back(polygonLoop({{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}}));
    shape.loops.push_back(polygonLoop({{0.3, 0.3}, {0.7, 0.3}, {0.5, 0.7}}));
    const auto f = pathField(shape);
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> coord(-0.5, 3.5), size(0.0, 0.3), unit(0.0, 1.0);
    int proven = 0;
    for (int i = 0; i < 3000; ++i) {
        const Vec2 lo(coord(rng), coord(rng));
        const Vec2 hi = lo + Vec2(size(rng), size(rng)) * (unit(rng) < 0.5 ? 0.05 : 1.0);
        Interval g[3];
        const Interval r =
            f->rangeGradient(Interval(lo.x, hi.x), Interval(lo.y, hi.y), Interval(0.0), g);
        REQUIRE(g[2].lo == 0.0);
        REQUIRE(g[2].hi == 0.0);
        proven += g[0].width() < 1e-6;
        for (int k = 0; k < 20; ++k) {
            const Vec2 p = lo + Vec2(unit(rng), unit(rng)) * (hi - lo);
            const Vec2 q = lo + Vec2(unit(rng), unit(rng)) * (hi - lo);
            const double fp = f->value(Vec3(p, 0.0)), fq = f->value(Vec3(q, 0.0));
            REQUIRE(r.contains(fp));
            const Vec2 d = p - q;
            const double dlo =
                std::min(g[0].lo * d.x, g[0].hi * d.x) + std::min(g[1].lo * d.y, g[1].hi * d.y);
            const double dhi =
                std::max(g[0].lo * d.x, g[0].hi * d.x) + std::max(g[1].lo * d.y, g[1].hi * d.y);
            const double slack = 1e-14;  // rounding in the two distances
            INFO("box (" << lo.x << "," << lo.y << ")-(" << hi.x << "," << hi.y << ") g=["
                         << g[0].lo << "," << g[0].hi << "]x[" << g[1].lo << "," << g[1].hi
                         << "] diff " << fp - fq);
            REQUIRE(fp - fq >= dlo - slack);
            REQUIRE(fp - fq <= dhi + slack);
        }
    }
    CHECK(proven > 100);  // the edges' interiors are proven affine often enough to matter
}
