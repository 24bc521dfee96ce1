/// @file tests/render/sampler_test.cpp
#include "render/sampler.h"

#include <catch2/catch.hpp>

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
    CHECK(PixelSampler(16).sampleCount() == 16);
    CHECK(PixelSampler(17).sampleCount() == 25);
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
