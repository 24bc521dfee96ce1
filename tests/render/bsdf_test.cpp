/// @file tests/render/bsdf_test.cpp
/// @brief render/bsdf.h per material kind: sample() agrees with pdf() and evaluate(), the
/// Monte Carlo albedo ∫ f·cos dω = E[value/pdf] matches the closed form, Lambert's f and
/// Phong's projected value are symmetric, and the glass lobes conserve energy with Schlick's
/// reflectance.
#include "render/bsdf.h"
#include "render/light_sample.h"
#include "render_test_util.h"

#include <catch2/catch.hpp>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <random>

using namespace kerf;

namespace {

constexpr double kPi = glm::pi<double>();
const Vec3 kUp(0.0, 0.0, 1.0);

/// A unit direction at polar angle theta from +z, azimuth phi.
Vec3 dirAt(double theta, double phi) {
    return Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
}

struct Estimate {
    Vec3 mean{0.0};
    double stdErr = 0.0;  ///< of the largest channel's mean
};

/// E[value/pdf] over n samples of the BSDF (delta lobes included), checking on the way
/// that each non-delta sample's pdf and value are pdf(wo, wi) and evaluate(wo, wi).
Estimate albedo(const Bsdf& bsdf, const Vec3& wo, int n, uint32_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    Vec3 sum(0.0);
    double sum2 = 0.0;
    for (int k = 0; k < n; ++k) {
        const std::optional<BsdfSample> s = bsdf.sample(wo, uni(rng), SubPixel{uni(rng), uni(rng)});
        REQUIRE(s);
        if (!(s->kind & kKindSpecular)) {
            REQUIRE(s->pdf == bsdf.pdf(wo, s->wi));
            REQUIRE(s->value == bsdf.evaluate(wo, s->wi));
        }
        if (!(s->pdf > 0.0)) continue;
        const Vec3 w = s->value / s->pdf;
        sum += w;
        sum2 += w.x * w.x;
    }
    const Vec3 mean = sum / double(n);
    const double var = std::max(0.0, sum2 / n - mean.x * mean.x);
    return {mean, std::sqrt(var / n)};
}

/// ∫ pdf(wo, ω) dω over the sphere by uniform directions: 1 for a BSDF without deltas.
double pdfIntegral(const Bsdf& bsdf, const Vec3& wo, int n, uint32_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    double sum = 0.0;
    for (int k = 0; k < n; ++k) {
        const double z = 1.0 - 2.0 * uni(rng);
        const double phi = 2.0 * kPi * uni(rng);
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        sum += bsdf.pdf(wo, Vec3(r * std::cos(phi), r * std::sin(phi), z));
    }
    return 4.0 * kPi * sum / n;
}

}  // namespace

TEST_CASE("Bsdf: Lambert") {
    Material m = test::blackMaterial();
    m.diffuse = 0.7;
    const Vec3 colour(0.9, 0.5, 0.25);
    const Bsdf bsdf(m, colour, kUp, true);
    const Vec3 wo = dirAt(0.6, 0.3);

    SECTION("evaluate is (1 − transmit)·diffuse·albedo·cos θi, 0 below") {
        m.transmit = 0.2;
        const Bsdf tinted(m, colour, kUp, true);
        const Vec3 wi = dirAt(0.9, 2.0);
        const Vec3 expected = (1.0 - 0.2) * 0.7 * std::cos(0.9) * colour;
        CHECK(glm::length(tinted.evaluate(wo, wi) - expected) < 1e-15);
        CHECK(tinted.evaluate(wo, -wi) == Vec3(0.0));
    }
    SECTION("f is reciprocal") {
        const Vec3 a = dirAt(0.4, 1.0), b = dirAt(1.2, -2.0);
        const Vec3 fab = bsdf.evaluate(a, b) / b.z, fba = bsdf.evaluate(b, a) / a.z;
        CHECK(glm::length(fab - fba) < 1e-14);
    }
    SECTION("the Monte Carlo albedo is π·diffuse·albedo") {
        const Estimate e = albedo(bsdf, wo, 20000, 1);
        const Vec3 expected = kPi * 0.7 * colour;
        // Cosine-weighted sampling of a Lambert lobe has zero variance: every sample is exact
        // up to rounding (the error estimate itself cancels to ~1e-8).
        CHECK(e.stdErr < 1e-6);
        CHECK(glm::length(e.mean - expected) < 1e-12);
    }
    SECTION("the pdf integrates to 1") {
        // Relative standard error of the estimate ≈ 1.3/√n = 0.0013: the bound is ~7σ.
        CHECK(std::fabs(pdfIntegral(bsdf, wo, 1000000, 2) - 1.0) < 0.01);
    }
}

TEST_CASE("Bsdf: Phong lobe") {
    Material m = test::blackMaterial();
    m.specular = 0.5;
    m.shininess = 12.0;
    const Bsdf bsdf(m, Vec3(1.0), kUp, true);

    SECTION("the projected value is symmetric in wo and wi") {
        const Vec3 a = dirAt(0.3, 0.2), b = dirAt(0.5, 3.0);
        CHECK(std::fabs(bsdf.evaluate(a, b).x - bsdf.evaluate(b, a).x) < 1e-15);
    }
    SECTION("at normal incidence the albedo is specular·2π/(shininess + 1)") {
        const Estimate e = albedo(bsdf, kUp, 40000, 3);
        const double expected = 0.5 * 2.0 * kPi / 13.0;
        // Sampling ∝ cos^n about the mirror direction: exact for every sample above the
        // surface, which at normal incidence is all of them.
        CHECK(std::fabs(e.mean.x - expected) < 1e-9);
    }
    SECTION("off normal incidence the pdf still integrates to 1 over the lobe's hemisphere") {
        // Part of the lobe about the mirror direction falls below the surface, where pdf
        // is 0: the integral is the share above, in (0, 1).
        const double share = pdfIntegral(bsdf, dirAt(1.2, 0.0), 200000, 4);
        CHECK(share > 0.5);
        CHECK(share < 1.0);
        // Relative standard error ≈ 3.5/√n = 0.0025: the bound is 6σ.
        CHECK(std::fabs(pdfIntegral(bsdf, kUp, 2000000, 5) - 1.0) < 0.015);
    }
}

TEST_CASE("Bsdf: mirror and glossy reflection") {
    Material m = test::blackMaterial();
    m.reflect = 0.6;
    const Vec3 wo = dirAt(0.7, 1.1);

    SECTION("a mirror is one delta lobe of weight reflect along the mirror direction") {
        const Bsdf bsdf(m, Vec3(1.0), kUp, true);
        const std::optional<BsdfSample> s = bsdf.sample(wo, 0.5, SubPixel{0.3, 0.3});
        REQUIRE(s);
        CHECK(s->kind == (kKindReflection | kKindSpecular));
        CHECK(s->value / s->pdf == Vec3(0.6));
        CHECK(glm::length(s->wi - dirAt(0.7, 1.1 + kPi)) < 1e-12);
        CHECK(bsdf.pdf(wo, s->wi) == 0.0);
        CHECK(bsdf.evaluate(wo, s->wi) == Vec3(0.0));
    }
    SECTION("a glossy mirror spreads the weight over its cone: albedo = reflect") {
        m.glossy = 20.0;
        const Bsdf bsdf(m, Vec3(1.0), kUp, true);
        const Estimate e = albedo(bsdf, wo, 20000, 6);
        CHECK(std::fabs(e.mean.x - 0.6) < 1e-9);  // uniform cone: every sample is exact
        // The cone is 3% of the sphere: relative standard error ≈ 5.7/√n = 0.004; bound 5σ.
        CHECK(std::fabs(pdfIntegral(bsdf, wo, 2000000, 7) - 1.0) < 0.02);
    }
    SECTION("a grazing glossy cone folded back above the surface keeps its energy") {
        m.glossy = 40.0;
        const Bsdf bsdf(m, Vec3(1.0), kUp, true);
        const Vec3 grazing = dirAt(1.4, 0.0);
        CHECK(std::fabs(pdfIntegral(bsdf, grazing, 2000000, 8) - 1.0) < 0.02);
        const Estimate e = albedo(bsdf, grazing, 20000, 9);
        CHECK(std::fabs(e.mean.x - 0.6) < 5.0 * e.stdErr + 1e-9);
    }
}

TEST_CASE("Bsdf: glass") {
    Material m = test::blackMaterial();
    m.transmit = 1.0;
    m.ior = 1.5;
    const Bsdf entering(m, Vec3(1.0), kUp, true);

    SECTION("at normal incidence F is ((n1 − n2)/(n1 + n2))² and the lobes sum to transmit") {
        const SpecularLobes s = entering.specular(kUp);
        CHECK(std::fabs(s.reflectWeight.x - 0.04) < 1e-15);
        CHECK(std::fabs(s.reflectWeight.x + s.refractWeight.x - 1.0) < 1e-15);
        CHECK(glm::length(s.refractDir + kUp) < 1e-15);
    }
    SECTION("Snell's law holds for the refracted direction") {
        const double theta = 0.8;
        const SpecularLobes s = entering.specular(dirAt(theta, 0.0));
        const double sinOut =
            std::sqrt(s.refractDir.x * s.refractDir.x + s.refractDir.y * s.refractDir.y);
        CHECK(std::fabs(std::sin(theta) - 1.5 * sinOut) < 1e-14);
        CHECK(s.refractDir.z < 0.0);
    }
    SECTION("sample picks reflection or refraction; E[value/pdf] = transmit") {
        const Vec3 wo = dirAt(0.5, 0.0);
        const SpecularLobes lobes = entering.specular(wo);
        const std::optional<BsdfSample> r = entering.sample(wo, 0.01, SubPixel{0.5, 0.5});
        const std::optional<BsdfSample> t = entering.sample(wo, 0.99, SubPixel{0.5, 0.5});
        REQUIRE(r);
        REQUIRE(t);
        CHECK(r->kind == (kKindReflection | kKindSpecular));
        CHECK(t->kind == (kKindTransmission | kKindSpecular));
        CHECK(r->value == lobes.reflectWeight);
        CHECK(t->value == lobes.refractWeight);
        CHECK(std::fabs(r->pdf + t->pdf - 1.0) < 1e-15);
        // The expectation over the lobe choice: Σ P·(value/P) = Σ weights = transmit.
        const double expectation = r->pdf * (r->value.x / r->pdf) + t->pdf * (t->value.x / t->pdf);
        CHECK(std::fabs(expectation - 1.0) < 1e-15);
    }
    SECTION("past the critical angle inside, everything reflects") {
        const Bsdf leaving(m, Vec3(1.0), kUp, false);
        const SpecularLobes s = leaving.specular(dirAt(std::asin(1.0 / 1.5) + 0.05, 0.0));
        CHECK(s.reflectWeight.x == 1.0);
        CHECK(s.refractWeight == Vec3(0.0));
    }
    SECTION("translucent glass: the refracted cone's albedo is transmit·(1 − F)·albedo") {
        m.translucent = 15.0;
        const Bsdf bsdf(m, Vec3(1.0), kUp, true);
        const Vec3 wo = dirAt(0.3, 0.0);
        const SpecularLobes lobes = bsdf.specular(wo);
        // Lobes are chosen in proportion to their weights, so every sample's throughput is
        // the total weight: the estimate is exact, and equals transmit.
        const Estimate e = albedo(bsdf, wo, 20000, 10);
        CHECK(std::fabs(e.mean.x - (lobes.reflectWeight.x + lobes.refractWeight.x)) < 1e-9);
        CHECK(std::fabs(e.mean.x - 1.0) < 1e-9);
        CHECK(std::fabs(pdfIntegral(bsdf, wo, 2000000, 11) - lobes.refractWeight.x) < 0.02);
    }
}
