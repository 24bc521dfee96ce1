/// @file tests/render/sampler_test.cpp
#include "render/sampler.h"
#include "render/sample_permutation.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <set>
#include <vector>

using namespace kerf;

TEST_CASE("PixelSampler::gridSide") {
    CHECK(PixelSampler::gridSide(0) == 1);
    CHECK(PixelSampler::gridSide(1) == 1);
    CHECK(PixelSampler::gridSide(2) == 2);
    CHECK(PixelSampler::gridSide(4) == 2);
    CHECK(PixelSampler::gridSide(5) == 3);
    CHECK(PixelSampler::gridSide(9) == 3);
    CHECK(PixelSampler::gridSide(10) == 4);
    // spp means what it says: exactly that many samples, on a grid of ⌈√N⌉ columns.
    CHECK(PixelSampler(16).sampleCount() == 16);
    CHECK(PixelSampler(17).sampleCount() == 17);
    CHECK(PixelSampler(5).sampleCount() == 5);
    CHECK(PixelSampler(5).columns() == 3);
    CHECK(PixelSampler(5).rows() == 2);
    CHECK(PixelSampler(0).sampleCount() == 1);
}

TEST_CASE("PixelSampler::position") {
    SECTION("one sample is the pixel centre") {
        const PixelSampler one(1);
        for (uint64_t p : {0ull, 17ull, 123456789ull}) {
            CHECK(one.position(p, 0).x == 0.5);
            CHECK(one.position(p, 0).y == 0.5);
        }
    }

    SECTION("every jittered sample lies in its own stratum") {
        const PixelSampler sampler(9);
        for (uint64_t p = 0; p < 500; ++p)
            for (int s = 0; s < 9; ++s) {
                const SubPixel sp = sampler.position(p, s);
                const int sx = s % 3, sy = s / 3;
                INFO("pixel " << p << " sample " << s);
                CHECK(sp.x >= sx / 3.0);
                CHECK(sp.x <= (sx + 1) / 3.0);
                CHECK(sp.y >= sy / 3.0);
                CHECK(sp.y <= (sy + 1) / 3.0);
            }
    }

    SECTION("values depend on the pixel and sample only, not on the call order") {
        const PixelSampler sampler(4);
        std::vector<SubPixel> forward;
        for (uint64_t p = 0; p < 64; ++p)
            for (int s = 0; s < 4; ++s) forward.push_back(sampler.position(p, s));
        const PixelSampler other(4);
        for (int k = int(forward.size()) - 1; k >= 0; --k) {
            const SubPixel sp = other.position(uint64_t(k / 4), k % 4);
            CHECK(sp.x == forward[size_t(k)].x);
            CHECK(sp.y == forward[size_t(k)].y);
        }
    }
}

TEST_CASE("hashUniform") {
    // Uniform on [0, 1): mean 1/2 and variance 1/12 within a few standard errors.
    const int n = 200000;
    double sum = 0, sum2 = 0;
    for (int k = 0; k < n; ++k) {
        const double u = hashUniform(uint64_t(k / 16), uint32_t(k % 16), uint32_t(k % 2));
        REQUIRE(u >= 0.0);
        REQUIRE(u < 1.0);
        sum += u;
        sum2 += u * u;
    }
    const double mean = sum / n;
    CHECK(std::abs(mean - 0.5) < 5 * std::sqrt(1.0 / 12 / n));
    CHECK(std::abs(sum2 / n - mean * mean - 1.0 / 12) < 2e-3);
    // Neighbouring dimensions of one sample differ.
    CHECK(hashUniform(7, 3, 0) != hashUniform(7, 3, 1));
}

TEST_CASE("permuteIndex is a permutation of 0 … n−1 for every n and seed") {
    for (uint32_t n = 1; n <= 300; ++n)
        for (uint64_t seed : {0ull, 1ull, 0x9e3779b97f4a7c15ull, 123456789ull}) {
            std::vector<int> seen(n, 0);
            for (uint32_t i = 0; i < n; ++i) {
                const uint32_t j = permuteIndex(i, n, seed);
                REQUIRE(j < n);
                ++seen[j];
            }
            for (uint32_t j = 0; j < n; ++j) REQUIRE(seen[j] == 1);
        }
    // Different seeds give different shuffles.
    int moved = 0;
    for (uint32_t i = 0; i < 64; ++i) moved += permuteIndex(i, 64, 1) != permuteIndex(i, 64, 2);
    CHECK(moved > 32);
}

TEST_CASE("every sampler: exactly N points in the unit square, stratified where it says") {
    for (SamplerKind kind :
         {SamplerKind::Regular, SamplerKind::Random, SamplerKind::Jittered, SamplerKind::Lattice})
        for (int n : {1, 2, 5, 16, 17, 64}) {
            const PixelSampler sampler(n, kind);
            INFO(samplerName(kind) << " N=" << n);
            REQUIRE(sampler.sampleCount() == n);
            for (uint64_t pixel : {0ull, 7ull, 99991ull})
                for (uint32_t dim : {0u, 1u, 4u, 77u}) {
                    std::set<std::pair<int, int>> cells;
                    for (int s = 0; s < n; ++s) {
                        const SubPixel p = sampler.get2D(pixel, s, dim);
                        REQUIRE(p.x >= 0.0);
                        REQUIRE(p.x <= 1.0);
                        REQUIRE(p.y >= 0.0);
                        REQUIRE(p.y <= 1.0);
                        cells.insert({int(p.x * sampler.columns()), int(p.y * sampler.rows())});
                    }
                    // The grid kinds put each sample in a cell of its own.
                    if (kind == SamplerKind::Jittered || kind == SamplerKind::Regular)
                        CHECK(int(cells.size()) == n);
                }
        }
}

TEST_CASE("the lattice: the Fibonacci generator, and one point per row and column") {
    // For N = 89 (a Fibonacci number) the best generator is the Fibonacci lattice's, 34 or
    // its mirror 55.
    CHECK(PixelSampler::latticeGenerator(89) == 34);
    // A rank-1 lattice with a generator prime to N has one point in each of N columns and,
    // shifted, in each of N rows.
    const PixelSampler sampler(89, SamplerKind::Lattice);
    std::set<int> columns, rows;
    for (int s = 0; s < 89; ++s) {
        const SubPixel p = sampler.get2D(5, s, 3);
        columns.insert(int(p.x * 89));
        rows.insert(int(p.y * 89));
    }
    CHECK(columns.size() == 89);
    CHECK(rows.size() == 89);
}

TEST_CASE("dimensions do not correlate: film position against lens and light") {
    // Over many pixels, the correlation of sample s's film x with its lens x (and light y)
    // must be near 0 (|r| < 4/√count); without the shuffle, jittered grids would give r ≈ 1.
    for (SamplerKind kind : {SamplerKind::Jittered, SamplerKind::Lattice, SamplerKind::Regular}) {
        const PixelSampler sampler(16, kind);
        double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
        int count = 0;
        for (uint64_t pixel = 0; pixel < 2000; ++pixel)
            for (int s = 0; s < 16; ++s) {
                const double a = sampler.get2D(pixel, s, sample_dim::kFilm).x;
                const double b = sampler.get2D(pixel, s, sample_dim::kLens).x;
                sx += a, sy += b, sxx += a * a, syy += b * b, sxy += a * b;
                ++count;
            }
        const double cov = sxy / count - (sx / count) * (sy / count);
        const double r = cov / std::sqrt((sxx / count - std::pow(sx / count, 2)) *
                                         (syy / count - std::pow(sy / count, 2)));
        INFO(samplerName(kind) << ": r = " << r);
        CHECK(std::fabs(r) < 4.0 / std::sqrt(double(count)));
    }
}

TEST_CASE("stratified and lattice samples integrate with less error than random ones") {
    // The area of the unit square under the quarter disc x² + y² ≤ 0.8 (an edge, as a soft
    // shadow's occluder is): estimated per pixel from N samples, RMSE over 4000 pixels
    // against the closed form. Jittered and lattice must beat random at every N, and the
    // gap must widen with N (random's error falls as N^-1/2, theirs faster).
    const double r2 = 0.8;
    const double exact = 0.25 * 3.14159265358979323846 * r2;  // r < 1: the whole quarter
    auto rmse = [&](SamplerKind kind, int n) {
        const PixelSampler sampler(n, kind);
        double sum2 = 0;
        const int pixels = 4000;
        for (uint64_t pixel = 0; pixel < uint64_t(pixels); ++pixel) {
            int inside = 0;
            for (int s = 0; s < n; ++s) {
                const SubPixel p = sampler.get2D(pixel, s, sample_dim::light(0));
                inside += p.x * p.x + p.y * p.y <= r2;
            }
            const double e = double(inside) / n - exact;
            sum2 += e * e;
        }
        return std::sqrt(sum2 / pixels);
    };
    double previousRatio = 0;
    for (int n : {4, 16, 64, 256}) {
        const double random = rmse(SamplerKind::Random, n);
        const double jittered = rmse(SamplerKind::Jittered, n);
        const double lattice = rmse(SamplerKind::Lattice, n);
        INFO("N=" << n << ": random " << random << ", jittered " << jittered << ", lattice "
                  << lattice);
        CHECK(jittered < random);
        CHECK(lattice < random);
        // Random's error follows the N^-1/2 law within 20 %.
        CHECK(random * std::sqrt(double(n)) == Approx(std::sqrt(exact * (1 - exact))).epsilon(0.2));
        const double ratio = random / jittered;
        CHECK(ratio > previousRatio);
        previousRatio = ratio;
    }
}
