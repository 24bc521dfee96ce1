// Slices of curved profiles at a fine tolerance: text and Bézier paths extruded, against the
// outline's area by Green's theorem (exact for polynomial curves), with the quadtree proving
// curved boundaries simple rather than splitting along them to the finest level.
#include "slice/slice.h"

#include "io/font_outline.h"
#include "util/compiled_scene.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace kerf;

namespace {

/// ∮ x dy of one segment: the integrand is a polynomial of degree ≤ 5 in t for Béziers, so
/// 3-point Gauss–Legendre is exact (up to rounding). Lines are Béziers of degree 1.
double greenTerm(const PathSegment& s) {
    const auto point = [&](double t) -> std::pair<Vec2, Vec2> {  // position, derivative
        const double u = 1.0 - t;
        switch (s.kind) {
            case PathSegment::Kind::Line: return {s.p[0] + t * (s.p[1] - s.p[0]), s.p[1] - s.p[0]};
            case PathSegment::Kind::Quadratic:
                return {u * u * s.p[0] + 2 * u * t * s.p[1] + t * t * s.p[2],
                        2.0 * (u * (s.p[1] - s.p[0]) + t * (s.p[2] - s.p[1]))};
            default:
                return {u * u * u * s.p[0] + 3 * u * u * t * s.p[1] + 3 * u * t * t * s.p[2] +
                            t * t * t * s.p[3],
                        3.0 * (u * u * (s.p[1] - s.p[0]) + 2 * u * t * (s.p[2] - s.p[1]) +
                               t * t * (s.p[3] - s.p[2]))};
        }
    };
    const double nodes[3] = {0.5 - 0.5 * std::sqrt(0.6), 0.5, 0.5 + 0.5 * std::sqrt(0.6)};
    const double weights[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
    double sum = 0.0;
    for (int i = 0; i < 3; ++i) {
        const auto [p, d] = point(nodes[i]);
        sum += weights[i] * p.x * d.y;
    }
    return sum;
}

/// The even-odd area of loops that do not cross (a font's contours: holes run against their
/// outer loops, so the signed areas add up to the filled area).
double outlineArea(const PathShape& shape) {
    double area = 0.0;
    for (const PathLoop& loop : shape.loops)
        for (const PathSegment& s : loop.segments) area += greenTerm(s);
    return std::abs(area);
}

}  // namespace

TEST_CASE("text extruded slices to its outline's area at a fine tolerance, curves proved simple") {
    TextSpec spec;
    spec.text = "kerf&9";
    spec.font = "DejaVu Sans";
    const TextOutline text = layoutText(spec);
    REQUIRE_FALSE(text.glyphsOverlap);
    const double exact = outlineArea(text.shape);
    // extrude puts the profile's (x, y) on the solid's (x, z) and extrudes along y.
    const Scene scene = test::compiledScene(
        "object extrude { profile text { string \"kerf&9\" font \"DejaVu Sans\" size 1 } height 1 "
        "};");
    const SlicePlane plane = SlicePlane::axisAligned(1, 0.5);
    SliceOptions options;
    options.tolerance = 1e-7;
    SceneSlicer slicer(scene, plane, options);
    const SliceResult result = slicer.slice(plane.w);
    const ContourStats& stats = result.stats.contour;
    INFO("area " << result.stats.area << " exact " << exact << " cells " << stats.cells
                 << " simple " << stats.simpleLeaves << " of " << stats.boundaryLeaves);
    REQUIRE_FALSE(stats.budgetExceeded);
    // Every vertex is within the tolerance of the outline: the area is off by at most about
    // perimeter × tolerance.
    CHECK(std::abs(result.stats.area - exact) <=
          result.stats.perimeter * slicer.absoluteTolerance());
    // Curved and straight boundaries are proved simple: most leaves stop before the finest
    // level (splitting to it along the curves took 1.7 million cells for "kerf" before).
    CHECK(stats.simpleLeaves > stats.boundaryLeaves * 3 / 4);
    CHECK(stats.cells < 200000);
}
