/// @file tests/io/coverage_raster_test.cpp
/// @brief The exact-coverage raster against closed forms: a half-plane at an arbitrary angle
/// (each pixel's area under the line, in long double), a square with a square hole, a tiny
/// triangle inside one pixel, and the total against the shoelace area; then sectionRaster's
/// compositing of layers.
#include "io/coverage_raster.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace kerf;

namespace {

using LD = long double;

/// Area of the unit square's part where a·x + b·y ≤ c (a, b ≠ 0): by inclusion–exclusion of
/// the ramps max(t, 0)² at the square's four corners, after reflecting so a, b > 0.
LD unitSquareUnderLine(LD a, LD b, LD c) {
    if (a < 0) {
        c -= a;
        a = -a;
    }
    if (b < 0) {
        c -= b;
        b = -b;
    }
    const auto F = [](LD t) { return t > 0 ? t * t : LD(0); };
    return (F(c) - F(c - a) - F(c - b) + F(c - a - b)) / (2 * a * b);
}

/// The overlap of [a0, a1] and [b0, b1].
double overlap(double a0, double a1, double b0, double b1) {
    return std::max(0.0, std::min(a1, b1) - std::max(a0, b0));
}

SectionLoop rectangle(double u0, double v0, double u1, double v1, bool counterClockwise) {
    SectionLoop loop{{{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}}};
    if (!counterClockwise) std::reverse(loop.points.begin(), loop.points.end());
    return loop;
}

double shoelace(const std::vector<SectionLoop>& loops) {
    double twice = 0;
    for (const SectionLoop& loop : loops)
        for (size_t k = 0, n = loop.points.size(); k < n; ++k) {
            const auto& a = loop.points[k];
            const auto& b = loop.points[(k + 1) % n];
            twice += a[0] * b[1] - a[1] * b[0];
        }
    return twice / 2;
}

}  // namespace

TEST_CASE("coverage of a half-plane at an arbitrary angle is each pixel's closed-form area") {
    const SectionGrid grid{40, 30, -2.0, 1.5, 0.1};
    // The half-plane a·u + b·v ≤ c cut from the square [−10, 10]², counter-clockwise: the
    // polygon's corners on the line are computed in long double so it is the line itself.
    for (const double angle : {0.37, 2.1, 4.0, 5.9}) {
        const LD a = std::cos(LD(angle)), b = std::sin(LD(angle)), c = 0.123456789L;
        SectionLoop loop;
        const LD box[4][2] = {{-10, -10}, {10, -10}, {10, 10}, {-10, 10}};
        for (int k = 0; k < 4; ++k) {  // Sutherland–Hodgman against the one line
            const LD* p = box[k];
            const LD* q = box[(k + 1) % 4];
            const LD fp = a * p[0] + b * p[1] - c, fq = a * q[0] + b * q[1] - c;
            if (fp <= 0) loop.points.push_back({double(p[0]), double(p[1])});
            if ((fp < 0) != (fq < 0) && fp != 0 && fq != 0) {
                const LD t = fp / (fp - fq);
                loop.points.push_back(
                    {double(p[0] + t * (q[0] - p[0])), double(p[1] + t * (q[1] - p[1]))});
            }
        }
        const std::vector<double> coverage = coverageGrid({loop}, grid);
        double worst = 0;
        int partial = 0;
        for (int j = 0; j < grid.height; ++j)
            for (int i = 0; i < grid.width; ++i) {
                // Pixel (i, j) in unit coordinates: u = u0 + (i + x)·pixel, v = v1 − (j + 1 −
                // y)·pixel.
                const LD ux = LD(grid.u0) + LD(i) * LD(grid.pixel);
                const LD vy = LD(grid.v1) - LD(j + 1) * LD(grid.pixel);
                const LD expected = unitSquareUnderLine(a * LD(grid.pixel), b * LD(grid.pixel),
                                                        c - a * ux - b * vy);
                worst = std::max(
                    worst, double(std::fabs(LD(coverage[size_t(j) * grid.width + i]) - expected)));
                partial += expected > 0 && expected < 1;
            }
        INFO("angle " << angle);
        CHECK(partial > 30);  // the line crosses the grid
        CHECK(worst <= 1e-12);
    }
}

TEST_CASE("coverage of a square with a square hole") {
    const SectionGrid grid{12, 12, -1.0, 11.0, 1.0};
    const double h0 = 2.3, h1 = 7.7;
    const std::vector<SectionLoop> loops = {rectangle(0, 0, 10, 10, true),
                                            rectangle(h0, h0, h1, h1, false)};
    const std::vector<double> coverage = coverageGrid(loops, grid);
    SECTION("the same at any scale: model and grid scaled by 1e-6 or 1e6") {
        for (const double scale : {1e-6, 1e6}) {
            std::vector<SectionLoop> scaled = loops;
            for (SectionLoop& loop : scaled)
                for (auto& p : loop.points) p = {p[0] * scale, p[1] * scale};
            const SectionGrid g{grid.width, grid.height, grid.u0 * scale, grid.v1 * scale,
                                grid.pixel * scale};
            const std::vector<double> c = coverageGrid(scaled, g);
            for (size_t k = 0; k < c.size(); ++k) CHECK(std::fabs(c[k] - coverage[k]) <= 1e-12);
        }
    }
    for (int j = 0; j < grid.height; ++j)
        for (int i = 0; i < grid.width; ++i) {
            const double u0 = grid.u0 + i, u1 = u0 + 1, v1 = grid.v1 - j, v0 = v1 - 1;
            const double expected = overlap(u0, u1, 0, 10) * overlap(v0, v1, 0, 10) -
                                    overlap(u0, u1, h0, h1) * overlap(v0, v1, h0, h1);
            const double got = coverage[size_t(j) * grid.width + i];
            INFO("pixel " << i << ", " << j);
            CHECK(std::fabs(got - expected) <= 1e-12);
            if (u0 >= 3 && u1 <= 7 && v0 >= 3 && v1 <= 7) CHECK(got == 0.0);  // inside the hole
        }
    SECTION("reversing every loop negates the coverage") {
        std::vector<SectionLoop> reversed = loops;
        for (SectionLoop& loop : reversed) std::reverse(loop.points.begin(), loop.points.end());
        const std::vector<double> negated = coverageGrid(reversed, grid);
        for (size_t k = 0; k < coverage.size(); ++k)
            CHECK(negated[k] == Approx(-coverage[k]).margin(1e-15));
    }
}

TEST_CASE("coverage of a tiny triangle inside one pixel is its area fraction") {
    const SectionGrid grid{5, 4, 0.0, 0.4, 0.1};  // pixel 0.1: (2, 1) is [0.2, 0.3] × [0.2, 0.3]
    const SectionLoop triangle{{{0.2137, 0.2512}, {0.2139, 0.2513}, {0.2138, 0.2519}}};
    const double fraction = shoelace({triangle}) / (0.1 * 0.1);
    REQUIRE(fraction > 0);
    const std::vector<double> coverage = coverageGrid({triangle}, grid);
    for (int j = 0; j < grid.height; ++j)
        for (int i = 0; i < grid.width; ++i) {
            const double expected = (i == 2 && j == 1) ? fraction : 0.0;
            CHECK(coverage[size_t(j) * grid.width + i] ==
                  Approx(expected).epsilon(1e-9).margin(1e-18));
        }
}

TEST_CASE("the raster's total coverage times the pixel area is the shoelace area") {
    // A non-convex star with a hole, off the pixel lattice, wholly inside the grid.
    std::vector<SectionLoop> loops(2);
    for (int k = 0; k < 14; ++k) {
        const double t = 2 * M_PI * k / 14, r = k % 2 ? 1.1 : 3.7;
        loops[0].points.push_back({0.31 + r * std::cos(t), -0.17 + r * std::sin(t)});
        const double s = -2 * M_PI * k / 14;  // clockwise
        loops[1].points.push_back({0.2 + 0.5 * std::cos(s), -0.1 + 0.4 * std::sin(s)});
    }
    const SectionGrid grid{97, 83, -4.5, 4.3, 0.1};
    double total = 0;
    coverageRows(loops, grid, [&](int, const double* c) {
        for (int i = 0; i < grid.width; ++i) {
            CHECK(c[i] >= -1e-14);
            CHECK(c[i] <= 1 + 1e-14);
            total += c[i];
        }
    });
    CHECK(total * grid.pixel * grid.pixel == Approx(shoelace(loops)).epsilon(1e-13));
}

TEST_CASE("coverage refuses a bad grid or a non-finite point") {
    const SectionLoop square = rectangle(0, 0, 1, 1, true);
    CHECK_THROWS_AS(coverageGrid({square}, SectionGrid{2, 2, 0, 1, 0.0}), std::invalid_argument);
    CHECK_THROWS_AS(coverageGrid({square}, SectionGrid{-1, 2, 0, 1, 0.5}), std::invalid_argument);
    SectionLoop bad = square;
    bad.points[2][1] = INFINITY;
    CHECK_THROWS_AS(coverageGrid({bad}, SectionGrid{2, 2, 0, 1, 0.5}), std::invalid_argument);
    CHECK(coverageGrid({square}, SectionGrid{0, 0, 0, 1, 0.5}).empty());
}

TEST_CASE("sectionRaster composites the layers by coverage") {
    SectionDrawing d;
    d.layers.push_back({"left", {1.0, 0.0, 0.0}, {rectangle(0, 0, 2.5, 4, true)}});
    d.layers.push_back({"right", {0.0, 0.0, 1.0}, {rectangle(2.5, 0, 5, 4, true)}});
    // A layer given clockwise only is still drawn (its total area says which way it runs).
    d.layers.push_back({"backwards", {0.0, 1.0, 0.0}, {rectangle(0, 4.25, 5, 5, false)}});
    const SectionGrid grid{5, 6, 0.0, 5.5, 1.0};
    const Image image = sectionRaster(d, grid);
    REQUIRE(image.width == 5);
    REQUIRE(image.height == 6);
    REQUIRE(image.channels == 4);
    // Row 0 is [4.5, 5.5]: half covered by "backwards"; row 1 [3.5, 4.5]: a quarter of it and
    // half of the left/right layers; the column [2, 3] straddles left and right.
    CHECK(image.at(0, 0, 3) == Approx(0.5));
    CHECK(image.at(0, 0, 1) == Approx(1.0));
    CHECK(image.at(0, 1, 3) == Approx(0.75));
    CHECK(image.at(0, 1, 0) == Approx(0.5 / 0.75));
    CHECK(image.at(0, 1, 1) == Approx(0.25 / 0.75));
    CHECK(image.at(2, 3, 3) == Approx(1.0));
    CHECK(image.at(2, 3, 0) == Approx(0.5));
    CHECK(image.at(2, 3, 2) == Approx(0.5));
    CHECK(image.at(4, 5, 3) == Approx(0.5).margin(1e-7));  // row 5 is [−0.5, 0.5]
    CHECK(image.at(4, 5, 2) == Approx(1.0));
    CHECK(image.at(1, 3, 0) == Approx(1.0));
    CHECK(image.at(1, 3, 2) == 0.0f);
}
