/// @file tests/render/light_pdf_test.cpp
/// @brief render/light_sample.h's densities: lightPdf integrates to 1 over the sphere of
/// directions for area and sphere lights (Monte Carlo against the solid angle), a sample's
/// pdf is lightPdf's at its direction, and its radiance is emitted·G/pdf as documented.
#include "render/light_sample.h"

#include <catch2/catch.hpp>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <random>

using namespace kerf;

namespace {

constexpr double kPi = glm::pi<double>();

/// ∫ lightPdf(p, ω) dω over the sphere by n uniform directions, with its standard error.
std::pair<double, double> pdfIntegral(const Light& light, const Vec3& p, int n, uint32_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    double sum = 0.0, sum2 = 0.0;
    for (int k = 0; k < n; ++k) {
        const double z = 1.0 - 2.0 * uni(rng);
        const double phi = 2.0 * kPi * uni(rng);
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        const double v =
            4.0 * kPi * lightPdf(light, p, Vec3(r * std::cos(phi), r * std::sin(phi), z));
        sum += v;
        sum2 += v * v;
    }
    const double mean = sum / n;
    return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n)};
}

Light areaLight() {
    Light l;
    l.kind = Light::Kind::Area;
    l.position = Vec3(-0.5, 2.0, -0.25);
    l.edgeU = Vec3(1.0, 0.0, 0.0);
    l.edgeV = Vec3(0.0, 0.3, 0.5);  // slanted: cos θ_light varies over it
    l.power = 10.0;
    l.color = Vec3(1.0, 0.9, 0.8);
    return l;
}

Light sphereLight() {
    Light l;
    l.kind = Light::Kind::Sphere;
    l.position = Vec3(0.3, 1.5, 0.2);
    l.radius = 0.4;
    l.power = 10.0;
    l.color = Vec3(1.0, 0.9, 0.8);
    return l;
}

}  // namespace

TEST_CASE("lightPdf: integrates to 1 over the directions that see the light") {
    const Vec3 p(0.1, 0.0, 0.05);
    for (const Light& light : {areaLight(), sphereLight()}) {
        const auto [mean, err] = pdfIntegral(light, p, 2000000, 7);
        INFO("mean " << mean << " ± " << err);
        CHECK(std::fabs(mean - 1.0) < std::max(5.0 * err, 1e-3));
        CHECK(err < 0.02);  // the test has the power to see a wrong normalisation
    }
}

TEST_CASE("sampleLight: the sample's pdf, position and emitted radiance") {
    const Vec3 p(0.1, 0.0, 0.05);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    SECTION("area light: pdf 1/A per area, radiance = emitted·|cos θ_light|/d²/pdf") {
        const Light light = areaLight();
        const double area = glm::length(glm::cross(light.edgeU, light.edgeV));
        for (int k = 0; k < 100; ++k) {
            const LightSample s = sampleLight(light, p, p, SubPixel{uni(rng), uni(rng)});
            REQUIRE(s.measure == LightPdfMeasure::Area);
            CHECK(std::fabs(s.pdf * area - 1.0) < 1e-14);
            const Vec3 w = s.position - p;
            const double d2 = glm::dot(w, w);
            CHECK(glm::length(glm::normalize(w) - s.direction) < 1e-14);
            const double cosLight = std::fabs(glm::dot(s.normal, s.direction));
            const Vec3 expected = s.emitted * (cosLight / d2 / s.pdf);
            CHECK(glm::length(s.radiance - expected) < 1e-12 * glm::length(expected));
            // The solid-angle density of that direction is the area density times d²/cos.
            const double solid = lightPdf(light, p, s.direction);
            CHECK(std::fabs(solid - s.pdf * d2 / cosLight) < 1e-9 * solid);
        }
    }
    SECTION("sphere light: pdf 1/Ω per steradian, radiance = emitted/pdf, point on the ball") {
        const Light light = sphereLight();
        for (int k = 0; k < 100; ++k) {
            const LightSample s = sampleLight(light, p, p, SubPixel{uni(rng), uni(rng)});
            REQUIRE(s.measure == LightPdfMeasure::SolidAngle);
            CHECK(std::fabs(s.pdf - lightPdf(light, p, s.direction)) < 1e-12 * s.pdf);
            CHECK(glm::length(s.radiance - s.emitted / s.pdf) < 1e-12 * glm::length(s.radiance));
            CHECK(std::fabs(glm::length(s.position - light.position) - light.radius) < 1e-12);
            CHECK(glm::dot(s.normal, s.direction) < 0.0);  // the near side faces p
        }
    }
    SECTION("point and directional lights are deltas of pdf 1") {
        Light point;
        point.position = Vec3(0.0, 2.0, 0.0);
        const LightSample s = sampleLight(point, p, p, SubPixel{});
        CHECK(s.measure == LightPdfMeasure::Delta);
        CHECK(s.pdf == 1.0);
        CHECK(s.emitted == s.radiance);
        CHECK(s.position == point.position);
        CHECK(lightPdf(point, p, s.direction) == 0.0);
    }
}
