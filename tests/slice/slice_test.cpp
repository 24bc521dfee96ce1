// Sections against closed forms: areas, orientation, closure, no self-intersection, thin
// features, sharp corners, stacks equal to single slices.
#include "slice/slice.h"

#include "util/compiled_scene.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <set>

using namespace kerf;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Cut {
    Scene scene;
    SliceResult result;
    double tolerance = 0.0;  // absolute
};

Cut cut(const std::string& model, const SlicePlane& plane, double relTolerance) {
    Cut c{test::compiledScene(model), {}, 0.0};
    SliceOptions o;
    o.tolerance = relTolerance;
    SceneSlicer slicer(c.scene, plane, o);
    c.result = slicer.slice(plane.w);
    c.tolerance = slicer.absoluteTolerance();
    return c;
}

std::vector<const SectionLoop*> allLoops(const SectionDrawing& d) {
    std::vector<const SectionLoop*> out;
    for (const auto& layer : d.layers)
        for (const auto& loop : layer.loops) out.push_back(&loop);
    return out;
}

/// Whether segments ab and cd cross at a point interior to both (shared ends excluded).
bool properCross(const std::array<double, 2>& a, const std::array<double, 2>& b,
                 const std::array<double, 2>& c, const std::array<double, 2>& d) {
    auto orient = [](const std::array<double, 2>& p, const std::array<double, 2>& q,
                     const std::array<double, 2>& r) {
        const double v = (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
        return (v > 0) - (v < 0);
    };
    return orient(a, b, c) * orient(a, b, d) < 0 && orient(c, d, a) * orient(c, d, b) < 0;
}

/// Pairs of segments that cross, over all loops of the drawing: segments are bucketed on a
/// grid by their boxes and only pairs sharing a bucket are tested.
size_t selfIntersections(const SectionDrawing& d) {
    std::vector<std::array<std::array<double, 2>, 2>> segs;
    for (const SectionLoop* loop : allLoops(d))
        for (size_t i = 0; i < loop->points.size(); ++i)
            segs.push_back({loop->points[i], loop->points[(i + 1) % loop->points.size()]});
    const int n = 256;
    const double w = (d.maxU - d.minU) / n, h = (d.maxV - d.minV) / n;
    auto bucket = [&](double x, double lo, double step) {
        return std::min(n - 1, std::max(0, static_cast<int>((x - lo) / step)));
    };
    std::map<int, std::vector<size_t>> grid;
    for (size_t i = 0; i < segs.size(); ++i) {
        const auto& s = segs[i];
        const int u0 = bucket(std::min(s[0][0], s[1][0]), d.minU, w),
                  u1 = bucket(std::max(s[0][0], s[1][0]), d.minU, w);
        const int v0 = bucket(std::min(s[0][1], s[1][1]), d.minV, h),
                  v1 = bucket(std::max(s[0][1], s[1][1]), d.minV, h);
        for (int u = u0; u <= u1; ++u)
            for (int v = v0; v <= v1; ++v) grid[u * n + v].push_back(i);
    }
    std::set<std::pair<size_t, size_t>> crossing;
    for (const auto& [cell, list] : grid)
        for (size_t a = 0; a < list.size(); ++a)
            for (size_t b = a + 1; b < list.size(); ++b) {
                const auto& s = segs[list[a]];
                const auto& t = segs[list[b]];
                if (properCross(s[0], s[1], t[0], t[1])) crossing.insert({list[a], list[b]});
            }
    return crossing.size();
}

const char* kCupBody = R"(
let R = 1.2;
let wall = R / 10;
object difference {
    cylinder { from <0, 0, 0> to <0, 2.4, 0> radius R }
    cylinder { from <0, wall, 0> to <0, 2.5, 0> radius R - wall }
};
)";

}  // namespace

TEST_CASE("cup wall is the annulus pi (R^2 - r^2)") {
    const double R = 1.2, r = 1.08;
    const double exact = kPi * (R * R - r * r);
    for (const double rel : {1e-4, 1e-7, 1e-10}) {
        const Cut c = cut(kCupBody, SlicePlane::axisAligned(1, 1.2), rel);
        const SliceStats& s = c.result.stats;
        INFO("tolerance " << rel << " area " << s.area << " exact " << exact);
        CHECK(s.contours == 2);
        CHECK(s.holes == 1);
        CHECK(s.contour.repairedLoops == 0);
        // Every vertex within the tolerance of the circles and every chord within it of its
        // arc: the region lies within the tolerance of the annulus, so the area does too.
        CHECK(std::fabs(s.area - exact) <= c.tolerance * s.perimeter);
        // Chords lie inside a convex arc: the outer area is short, the hole's too (so the
        // annulus is within chord error of both circles), and each vertex is on its circle.
        for (const SectionLoop* loop : allLoops(c.result.drawing)) {
            const double radius = loopArea(*loop) > 0 ? R : r;
            for (const auto& p : loop->points)
                CHECK(std::fabs(std::hypot(p[0], p[1]) - radius) <= c.tolerance);
            // Each chord's middle, its farthest point from the arc, within the tolerance too.
            double worst = 0.0;
            const auto& pts = loop->points;
            for (size_t i = 0; i < pts.size(); ++i) {
                const auto& a = pts[i];
                const auto& b = pts[(i + 1) % pts.size()];
                worst = std::max(
                    worst,
                    std::fabs(std::hypot(0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])) - radius));
            }
            CHECK(worst <= c.tolerance);
        }
    }
}

TEST_CASE("box minus circles") {
    const Cut c = cut(R"(
object difference {
    box { min <0, 0, -1> max <4, 2, 1> }
    cylinder { from <1, 1, -2> to <1, 1, 2> radius 0.5 }
    cylinder { from <3, 1, -2> to <3, 1, 2> radius 0.3 }
};
)",
                      SlicePlane::axisAligned(2, 0.25), 1e-9);
    const SliceStats& s = c.result.stats;
    const double exact = 8.0 - kPi * (0.25 + 0.09);
    CHECK(s.contours == 3);
    CHECK(s.holes == 2);
    CHECK(std::fabs(s.area - exact) <= c.tolerance * s.perimeter);
    CHECK(std::fabs(s.perimeter - (12.0 + 2 * kPi * 0.8)) <= 1e-6);
}

TEST_CASE("torus through its axis is two circles") {
    // Around the y axis: the plane x = 0 (u = y, v = z) meets it in circles at z = ±2.
    const Cut c = cut("object torus { major 2 minor 0.5 };", SlicePlane::axisAligned(0, 0.0), 1e-9);
    const SliceStats& s = c.result.stats;
    CHECK(s.contours == 2);
    CHECK(s.holes == 0);
    CHECK(std::fabs(s.area - 2 * kPi * 0.25) <= c.tolerance * s.perimeter);
    for (const SectionLoop* loop : allLoops(c.result.drawing))
        for (const auto& p : loop->points)
            CHECK(std::fabs(std::hypot(p[0], std::fabs(p[1]) - 2.0) - 0.5) <= c.tolerance);
}

TEST_CASE("cone cut obliquely is an ellipse") {
    // Cone of apex height H = 2 and base radius 1 (t = 1/2), plane z = 0.8 + 0.5 x: the
    // ellipse's area is π t² c² √(1 + s²) / (1 − t² s²)^{3/2}, c = H − 0.8, s = 0.5.
    const double t = 0.5, cc = 1.2, sl = 0.5;
    const double exact =
        kPi * t * t * cc * cc * std::sqrt(1 + sl * sl) / std::pow(1 - t * t * sl * sl, 1.5);
    const Cut c = cut("object cone { from <0, 0, 0> to <0, 0, 2> radius1 1 radius2 0 };",
                      SlicePlane::throughPoint(Vec3(0, 0, 0.8), Vec3(-0.5, 0, 1)), 1e-9);
    const SliceStats& s = c.result.stats;
    CHECK(s.contours == 1);
    INFO("area " << s.area << " exact " << exact);
    CHECK(std::fabs(s.area - exact) <= c.tolerance * s.perimeter);
}

TEST_CASE("sphere near its pole is a tiny circle") {
    const double z = 1.0 - 1e-6;
    const double exact = kPi * (1.0 - z * z);
    const Cut c =
        cut("object sphere { center <0, 0, 0> radius 1 };", SlicePlane::axisAligned(2, z), 1e-10);
    const SliceStats& s = c.result.stats;
    REQUIRE(s.contours == 1);
    INFO("area " << s.area << " exact " << exact);
    CHECK(std::fabs(s.area - exact) <= c.tolerance * s.perimeter);
}

TEST_CASE("a slot 1e-6 wide is found") {
    const Cut c = cut(R"(
object difference {
    box { min <0, 0, -1> max <1, 1, 1> }
    box { min <0.5, 0.3, -2> max <0.500001, 0.301, 2> }
};
)",
                      SlicePlane::axisAligned(2, 0.0), 1e-8);
    const SliceStats& s = c.result.stats;
    REQUIRE(s.contours == 2);
    CHECK(s.holes == 1);
    // The hole's area is 1e-6 · 1e-3 within the tolerance times its perimeter.
    CHECK(std::fabs((1.0 - s.area) - 1e-9) <= c.tolerance * 2.002e-3);
}

TEST_CASE("sharp corner of a box minus a cylinder") {
    // The cylinder around (2, 2) of radius 1 cuts the box's corner: the section's corners are
    // at (1, 2) and (2, 1) exactly.
    const Cut c = cut(R"(
object difference {
    box { min <0, 0, -1> max <2, 2, 1> }
    cylinder { from <2, 2, -2> to <2, 2, 2> radius 1 }
};
)",
                      SlicePlane::axisAligned(2, 0.0), 1e-9);
    for (const auto& corner : {std::array<double, 2>{1, 2}, std::array<double, 2>{2, 1}}) {
        double nearest = INFINITY;
        for (const SectionLoop* loop : allLoops(c.result.drawing))
            for (const auto& p : loop->points)
                nearest = std::min(nearest, std::hypot(p[0] - corner[0], p[1] - corner[1]));
        INFO("corner " << corner[0] << ", " << corner[1]);
        CHECK(nearest <= c.tolerance);
    }
    // The corner vertex is the tangents' meeting point, far closer than the tolerance: the
    // face is straight and the circle bends by h²/2 over a finest cell h ≈ 1e-6.
    const Cut coarse = cut(R"(
object difference {
    box { min <0, 0, -1> max <2, 2, 1> }
    cylinder { from <2, 2, -2> to <2, 2, 2> radius 1 }
};
)",
                           SlicePlane::axisAligned(2, 0.0), 1e-6);
    for (const auto& corner : {std::array<double, 2>{1, 2}, std::array<double, 2>{2, 1}}) {
        double nearest = INFINITY;
        for (const SectionLoop* loop : allLoops(coarse.result.drawing))
            for (const auto& p : loop->points)
                nearest = std::min(nearest, std::hypot(p[0] - corner[0], p[1] - corner[1]));
        INFO("corner " << corner[0] << ", " << corner[1]);
        CHECK(nearest <= 1e-9);
    }
    const double exact = 4.0 - kPi / 4;
    CHECK(std::fabs(c.result.stats.area - exact) <= c.tolerance * c.result.stats.perimeter);
}

TEST_CASE("loops are closed, oriented and never self-intersect") {
    // A mixed model at a coarse tolerance (few vertices, so every pair can be checked).
    const Cut c = cut(R"(
object union {
    difference {
        box { min <-2, -2, -1> max <2, 2, 1> }
        sphere { center <0, 0, 0> radius 1.5 }
    }
    sphere { center <0, 0, 0> radius 0.7 }
    torus { major 1.2 minor 0.2 } rotate <90, 0, 0>
};
)",
                      SlicePlane::axisAligned(2, 0.1), 1e-4);
    const SliceStats& s = c.result.stats;
    CHECK(s.contour.repairedLoops == 0);
    CHECK(selfIntersections(c.result.drawing) == 0);
    // Each region's area is its outer loop's (positive) plus its holes' (negative).
    for (const RegionStats& r : s.regions) CHECK(r.area > 0.0);
    CHECK(s.holes >= 1);
}

TEST_CASE("a stack equals single slices") {
    Scene scene = test::compiledScene(kCupBody);
    const SlicePlane family = SlicePlane::axisAligned(1, 0.0);
    SliceOptions o;
    o.tolerance = 1e-6;
    SceneSlicer slicer(scene, family, o);
    const std::vector<double> offsets{0.05, 0.5, 1.2, 2.3, 3.0};
    const std::vector<SliceResult> stack = slicer.sliceMany(offsets);
    for (size_t i = 0; i < offsets.size(); ++i) {
        const SliceResult one = slicer.slice(offsets[i]);
        REQUIRE(one.drawing.layers.size() == stack[i].drawing.layers.size());
        for (size_t l = 0; l < one.drawing.layers.size(); ++l) {
            const auto& a = one.drawing.layers[l].loops;
            const auto& b = stack[i].drawing.layers[l].loops;
            REQUIRE(a.size() == b.size());
            for (size_t k = 0; k < a.size(); ++k) CHECK(a[k].points == b[k].points);
        }
    }
    CHECK(stack[4].drawing.layers.empty());  // past the top: nothing, and no error
    CHECK(std::fabs(stack[0].stats.area - kPi * 1.44) <= 1e-6 * 2.5 * stack[0].stats.perimeter);
}

TEST_CASE("plane axes are right-handed") {
    for (int axis = 0; axis < 3; ++axis) {
        const SlicePlane p = SlicePlane::axisAligned(axis, 0.0);
        CHECK(glm::length(glm::cross(p.u, p.v) - p.normal) == 0.0);
    }
    const SlicePlane g = SlicePlane::throughPoint(Vec3(1, 2, 3), Vec3(0.3, -2, 0.5));
    CHECK(glm::length(glm::cross(g.u, g.v) - g.normal) < 1e-15);
    CHECK(std::fabs(glm::dot(g.u, g.v)) < 1e-15);
}

TEST_CASE("regions go to the layer of their material") {
    const Cut c = cut(R"(
material red { color <1, 0, 0> }
material blue { color <0, 0, 1> }
object union {
    sphere { center <-2, 0, 0> radius 1 } material red
    box { min <1, -1, -1> max <3, 1, 1> } material blue
};
object sphere { center <0, 5, 0> radius 0.5 };
)",
                      SlicePlane::axisAligned(2, 0.0), 1e-9);
    const SectionDrawing& d = c.result.drawing;
    REQUIRE(d.layers.size() == 3);
    std::map<std::string, double> area;
    for (const SectionLayer& layer : d.layers)
        for (const SectionLoop& loop : layer.loops) area[layer.name] += loopArea(loop);
    CHECK(std::fabs(area["red"] - kPi) <= c.tolerance * 2 * kPi);
    CHECK(std::fabs(area["blue"] - 4.0) <= c.tolerance * 8);
    CHECK(std::fabs(area["default"] - kPi * 0.25) <= c.tolerance * kPi);
    for (const SectionLayer& layer : d.layers)
        if (layer.name == "red") CHECK(layer.color == std::array<double, 3>{1, 0, 0});
}

TEST_CASE("boxes sharing a face make one region without a seam") {
    const Cut c = cut(R"(
object union {
    box { min <0, 0, -1> max <1, 1, 1> }
    box { min <1, 0, -1> max <2, 1, 1> }
};
)",
                      SlicePlane::axisAligned(2, 0.0), 1e-4);
    const SliceStats& s = c.result.stats;
    CHECK(s.contours == 1);
    CHECK(s.contour.repairedLoops == 0);
    CHECK(std::fabs(s.area - 2.0) <= c.tolerance * s.perimeter);
    CHECK(std::fabs(s.perimeter - 6.0) <= 8 * c.tolerance);
}

TEST_CASE("a plane holding a face ends quickly with a closed section") {
    // The plane z = 1 holds the box's top face, where f is 0 up to rounding and intervals
    // cannot prove a sign: the section is either the face or nothing (here nothing: f ≥ 0 on
    // the whole plane), but it is closed and found without splitting the face to the finest
    // level.
    const Cut c =
        cut("object box { min <0, 0, 0> max <1, 1, 1> };", SlicePlane::axisAligned(2, 1.0), 1e-9);
    const SliceStats& s = c.result.stats;
    CHECK(!s.contour.budgetExceeded);
    CHECK(s.contour.repairedLoops == 0);
    CHECK(s.contour.cells < 1000);
    CHECK(std::min(std::fabs(s.area), std::fabs(s.area - 1.0)) <= c.tolerance * 4);
}

TEST_CASE("the gears' sections have sharp closed loops that never self-intersect") {
    // models/gear.kerf: three gears, each a union of teeth (boxes cut by half-spaces) on a disc,
    // minus a bore and holes: hundreds of CSG corners.
    Scene scene = test::compiledSceneFile(std::string(KERF_SOURCE_DIR) + "/models/gear.kerf");
    SliceOptions o;
    o.tolerance = 1e-5;
    SceneSlicer slicer(scene, SlicePlane::axisAligned(1, 0.1), o);
    const SliceResult r = slicer.slice(0.1);
    CHECK(r.stats.contour.repairedLoops == 0);
    CHECK(r.stats.holes >= 9);
    CHECK(selfIntersections(r.drawing) == 0);
}
