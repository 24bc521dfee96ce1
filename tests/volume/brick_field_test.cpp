// The baked field (volume/grids/bricked_field.h) against closed forms: a linear function comes back
// exactly, range() holds every value of random boxes, the Lipschitz bound holds between random
// points, the bake is the same on one thread as on many, and bad input is refused.
#include <tbb/task_arena.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "volume/grids/bricked_field.h"

using namespace kerf;

namespace {

/// A smooth field with several scales, some negative values.
double wavy(const Vec3& p) {
    return std::sin(3.1 * p.x + 0.3) * std::cos(2.3 * p.y - 0.7) +
           0.5 * std::sin(5.7 * p.z + 1.1 * p.x) + 0.2;
}

Vec3 randomIn(std::mt19937& rng, const Bounds3& b) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    return b.lo + Vec3(u(rng), u(rng), u(rng)) * b.extent();
}

}  // namespace

TEST_CASE("BrickedField::value") {
    SECTION("a linear function on a dyadic grid comes back exactly") {
        // Spacing 1/4, samples and coefficients dyadic: the samples are exact in float and
        // every lerp at a point on a 2⁻¹⁰ lattice is exact in double, so no rounding at all.
        auto f = [](const Vec3& p) { return 3.0 * p.x - 2.0 * p.y + 5.0 * p.z + 1.0; };
        const auto field = bakeField(f, {Vec3(-1.0, 0.0, 0.5), Vec3(3.0, 2.0, 3.5)}, 17);
        REQUIRE(field->spacing() == 0.25);
        REQUIRE(field->grid().size() == glm::ivec3(17, 9, 13));
        std::mt19937 rng(3);
        std::uniform_int_distribution<int> k(0, 4096);
        for (int i = 0; i < 20000; ++i) {
            const Vec3 p(-1.0 + k(rng) * 0x1p-10, k(rng) * 0x1p-11, 0.5 + k(rng) * 0x1p-10 * 0.75);
            CAPTURE(p.x, p.y, p.z);
            REQUIRE(field->value(p) == f(p));
            Vec3 g;
            REQUIRE(field->valueGradient(p, g) == f(p));
            REQUIRE(g == Vec3(3.0, -2.0, 5.0));
            REQUIRE(field->valueExtended(glm::tvec3<long double>(p)) == (long double)f(p));
        }
    }
    SECTION("a general linear function within float rounding of its samples") {
        auto f = [](const Vec3& p) { return 0.3 * p.x + 1.7 * p.y - 0.9 * p.z + 0.1; };
        const Bounds3 box{Vec3(-0.3, 0.2, -1.1), Vec3(0.9, 0.7, 0.4)};
        const auto field = bakeField(f, box, 33);
        std::mt19937 rng(4);
        for (int i = 0; i < 20000; ++i) {
            const Vec3 p = randomIn(rng, box);
            // Each sample rounds to float (2⁻²⁴ relative, |f| < 3 here) and the interpolation is
            // a convex combination of them.
            REQUIRE(std::fabs(field->value(p) - f(p)) <= 3.0 * 0x1p-24 + 1e-14);
        }
    }
    SECTION("beyond the grid the value is the nearest edge's") {
        const auto field = bakeField(wavy, {Vec3(0.0), Vec3(1.0)}, 20);
        CHECK(field->value(Vec3(-5.0, 0.3, 0.4)) == field->value(Vec3(0.0, 0.3, 0.4)));
        CHECK(field->value(Vec3(0.2, 7.0, 0.4)) == field->value(Vec3(0.2, 1.0, 0.4)));
        CHECK(std::isnan(field->value(Vec3(std::nan(""), 0.3, 0.4))));
    }
}

TEST_CASE("BrickedField::range") {
    // 40 samples per side, bricks of 8³: boxes from a fraction of a cell to the whole grid, some
    // reaching beyond it; every value at random points of the box must lie in range(box).
    const Bounds3 domain{Vec3(-1.0, -0.5, 0.0), Vec3(1.0, 1.0, 1.3)};
    const auto field = bakeField(wavy, domain, 40);
    const auto density =
        bakeField([](const Vec3& p) { return std::max(0.0, wavy(p)); }, domain, 40);
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> scale(-6.0, 1.0);
    const Bounds3 around{domain.lo - 0.3, domain.hi + 0.3};
    for (int b = 0; b < 400; ++b) {
        const Vec3 c = randomIn(rng, around);
        const Vec3 half = Vec3(std::exp2(scale(rng)), std::exp2(scale(rng)), std::exp2(scale(rng)));
        const Bounds3 box{c - half, c + half};
        const Interval r =
            field->range({box.lo.x, box.hi.x}, {box.lo.y, box.hi.y}, {box.lo.z, box.hi.z});
        const Interval d =
            density->range({box.lo.x, box.hi.x}, {box.lo.y, box.hi.y}, {box.lo.z, box.hi.z});
        CHECK(d.lo >= 0.0);  // a density's minorant stays non-negative
        for (int i = 0; i < 200; ++i) {
            const Vec3 p = randomIn(rng, box);
            CAPTURE(box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z, p.x, p.y, p.z);
            REQUIRE(r.contains(field->value(p)));
            REQUIRE(d.contains(density->value(p)));
        }
        // The corners exactly (where a sample uses the edge of the index range).
        for (int k = 0; k < 8; ++k) {
            const Vec3 p(k & 1 ? box.hi.x : box.lo.x, k & 2 ? box.hi.y : box.lo.y,
                         k & 4 ? box.hi.z : box.lo.z);
            REQUIRE(r.contains(field->value(p)));
        }
    }
    // Not vacuous: the range of the whole grid is within the function's own bounds
    // (|wavy| ≤ 1.7) plus the rounding margin, and a small box is much narrower.
    const Interval all = field->range({-10.0, 10.0}, {-10.0, 10.0}, {-10.0, 10.0});
    CHECK(all.lo >= -1.3 - 1e-12);
    CHECK(all.hi <= 1.7 + 1e-12);
    const Interval small = field->range({0.1, 0.11}, {0.2, 0.21}, {0.3, 0.31});
    CHECK(small.width() < 0.5 * all.width());
}

TEST_CASE("BrickedField::lipschitz") {
    const Bounds3 domain{Vec3(0.0), Vec3(1.0, 0.5, 0.7)};
    const auto field = bakeField(wavy, domain, 30);
    const double l = field->lipschitz();
    // The partial derivatives of wavy are at most 3.1 + 0.55, 2.3, 2.85: the samples' bound is
    // no larger (differences of samples are means of the derivative).
    CHECK(l > 0.0);
    CHECK(l <= 3.1 + 0.5 * 1.1 + 1e-6);
    std::mt19937 rng(23);
    const Bounds3 around{domain.lo - 0.2, domain.hi + 0.2};
    for (int i = 0; i < 20000; ++i) {
        const Vec3 p = randomIn(rng, around), q = randomIn(rng, around);
        const Vec3 d = glm::abs(p - q);
        REQUIRE(std::fabs(field->value(p) - field->value(q)) <=
                l * (d.x + d.y + d.z) * (1.0 + 1e-12) + 1e-15);
        Vec3 g;
        field->valueGradient(p, g);
        REQUIRE(std::fabs(g.x) <= l * (1.0 + 1e-12));
        REQUIRE(std::fabs(g.y) <= l * (1.0 + 1e-12));
        REQUIRE(std::fabs(g.z) <= l * (1.0 + 1e-12));
    }
}

TEST_CASE("bakeField") {
    SECTION("the same samples on one thread and on many") {
        const Bounds3 box{Vec3(-1.0), Vec3(1.0, 2.0, 0.5)};
        const auto many = bakeField(wavy, box, 70);
        tbb::task_arena one(1);
        std::shared_ptr<const BrickedField> single;
        one.execute([&] { single = bakeField(wavy, box, 70); });
        const glm::ivec3 s = many->grid().size();
        REQUIRE(single->grid().size() == s);
        for (int z = 0; z < s.z; ++z)
            for (int y = 0; y < s.y; ++y)
                for (int x = 0; x < s.x; ++x)
                    REQUIRE(single->grid().get(x, y, z) == many->grid().get(x, y, z));
        CHECK(single->lipschitz() == many->lipschitz());
    }
    SECTION("the sampled box holds the box") {
        const Bounds3 box{Vec3(0.1, 0.2, 0.3), Vec3(1.1, 0.45, 0.31)};
        const auto field = bakeField(wavy, box, 21);
        const Bounds3 s = field->sampledBounds();
        CHECK(s.lo == box.lo);
        CHECK(s.hi.x == Approx(1.1));
        CHECK(s.hi.y >= box.hi.y);
        CHECK(s.hi.y < box.hi.y + field->spacing());
        CHECK(s.hi.z >= box.hi.z);
        CHECK(field->grid().size() == glm::ivec3(21, 6, 2));
    }
    SECTION("a zero field allocates no macrobrick") {
        const auto field = bakeField([](const Vec3&) { return 0.0; }, {Vec3(0.0), Vec3(1.0)}, 200);
        CHECK(field->grid().allocatedMacrobricks() == 0);
        CHECK(field->range({0.0, 1.0}, {0.0, 1.0}, {0.0, 1.0}).hi == 0.0);
    }
    SECTION("bad input") {
        const Bounds3 unit{Vec3(0.0), Vec3(1.0)};
        CHECK_THROWS_AS(bakeField(wavy, unit, 1), std::invalid_argument);
        CHECK_THROWS_AS(bakeField(wavy, unit, 5000), std::invalid_argument);
        CHECK_THROWS_AS(bakeField(wavy, Bounds3{}, 10), std::invalid_argument);
        CHECK_THROWS_AS(bakeField(wavy, {Vec3(0.0), Vec3(0.0)}, 10), std::invalid_argument);
        CHECK_THROWS_AS(bakeField(wavy, {Vec3(0.0), Vec3(kInf, 1.0, 1.0)}, 10),
                        std::invalid_argument);
        CHECK_THROWS_WITH(
            bakeField([](const Vec3& p) { return p.x > 0.5 ? std::nan("") : 1.0; }, unit, 5),
            Catch::Contains("at (0.75, 0, 0)"));
        CHECK_THROWS_WITH(bakeField([](const Vec3& p) { return p.z > 0.7 ? 1e300 : 1.0; }, unit, 5),
                          Catch::Contains("at (0, 0, 0.75)"));
    }
}
