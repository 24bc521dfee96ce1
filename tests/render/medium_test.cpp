/// @file tests/render/medium_test.cpp
/// @brief Heterogeneous media against closed forms: the three transmittance estimators on a
/// constant slab, a linear ramp and an exponential fog (the mean of many estimates within a
/// few standard errors; the marcher within its own stated bound); single scattering of a
/// constant slab under a directional light; the same image whatever the thread count.
#include "render/medium.h"
#include "render/whitted_integrator.h"
#include "render_test_util.h"

#include <catch2/catch.hpp>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <vector>

using namespace kerf;
using namespace kerf::test;

namespace {

/// density(z) for z the height; its range over a box is exact up to outward rounding.
class ZField final : public ScalarField {
public:
    enum class Kind { Constant, Ramp, Exponential };
    ZField(Kind kind, double a, double b) : mKind(kind), mA(a), mB(b) {}
    double value(const Vec3& p) const override { return at(p.z); }
    long double valueExtended(const glm::tvec3<long double>& p) const override {
        return at(double(p.z));
    }
    double valueGradient(const Vec3& p, Vec3& g) const override {
        g = Vec3(0.0);
        return at(p.z);
    }
    Interval range(const Interval&, const Interval&, const Interval& z) const override {
        // Constant, increasing (ramp, b > 0) or decreasing (exponential): the ends bound it.
        const double u = at(z.lo), v = at(z.hi);
        if (mKind == Kind::Constant) return Interval(mA, mA);
        return Interval(std::nextafter(std::min(u, v), -kInf),
                        std::nextafter(std::max(u, v), kInf));
    }
    /// ∫ density dz from 0 to h.
    double integral(double h) const {
        switch (mKind) {
            case Kind::Constant: return mA * h;
            case Kind::Ramp: return mA * h + 0.5 * mB * h * h;
            case Kind::Exponential: return mA * mB * -std::expm1(-h / mB);
        }
        return 0.0;
    }

private:
    double at(double z) const {
        switch (mKind) {
            case Kind::Constant: return mA;
            case Kind::Ramp: return mA + mB * z;
            case Kind::Exponential: return mA * std::exp(-z / mB);
        }
        return 0.0;
    }
    Kind mKind;
    double mA, mB;
};

/// A slab 0 ≤ z ≤ height, wide in x and y.
Medium slab(std::shared_ptr<const ScalarField> field, double extinction, double height = 2.0) {
    Medium m;
    m.density = std::move(field);
    m.bounds = Bounds3{Vec3(-50.0, -50.0, 0.0), Vec3(50.0, 50.0, height)};
    m.extinction = extinction;
    return m;
}

struct Stats {
    double mean = 0.0, standardError = 0.0;
};

template <class F>
Stats meanOf(int n, F&& estimate) {
    std::vector<double> v(size_t(n), 0.0);
    double sum = 0.0;
    for (int i = 0; i < n; ++i) sum += v[size_t(i)] = estimate(i);
    const double mean = sum / n;
    double squares = 0.0;  // two passes: no cancellation when every estimate is the same
    for (double x : v) squares += (x - mean) * (x - mean);
    return {mean, std::sqrt(squares / (double(n) * (n - 1)))};
}

}  // namespace

TEST_CASE("medium/transmittance estimators against closed forms") {
    const Vec3 dir = glm::normalize(Vec3(0.2, 0.1, 1.0));
    const Ray ray{Vec3(0.1, 0.2, -1.0) - dir * 0.0, dir};
    const double extinction = 0.7;
    struct Case {
        const char* name;
        ZField::Kind kind;
        double a, b;
    };
    const Case cases[] = {{"constant slab", ZField::Kind::Constant, 0.6, 0.0},
                          {"linear ramp", ZField::Kind::Ramp, 0.1, 0.5},
                          {"exponential fog", ZField::Kind::Exponential, 1.2, 0.6}};
    for (const Case& c : cases) {
        const auto field = std::make_shared<ZField>(c.kind, c.a, c.b);
        const Medium m = slab(field, extinction);
        // The ray enters at z = 0 and leaves at z = 2: its length in the slab is 2 / dir.z.
        const double exact = std::exp(-extinction * field->integral(2.0) / dir.z);
        const MediumPath path(m, ray, 0.0, kInf);
        REQUIRE(!path.empty());
        INFO(c.name << ": exact T = " << exact);
        const int n = 20000;
        const Stats ratio = meanOf(n, [&](int i) {
            MediumRandom rng(uint64_t(i) * 7919 + 1);
            return ratioTracking(m, ray, path, kInf, rng);
        });
        const Stats delta = meanOf(n, [&](int i) {
            MediumRandom rng(uint64_t(i) * 104729 + 3);
            return deltaTracking(m, ray, path, kInf, rng);
        });
        CHECK(std::fabs(ratio.mean - exact) <= 4 * ratio.standardError + 1e-12 * exact);
        CHECK(std::fabs(delta.mean - exact) <= 4 * delta.standardError);
        // Ratio tracking is never noisier than delta tracking here, and exact on a constant.
        CHECK(ratio.standardError <= delta.standardError);
        if (c.kind == ZField::Kind::Constant) CHECK(ratio.standardError <= 1e-12 * exact);
        for (double h : {0.2, 0.05, 0.01}) {
            double tauError = 0.0;
            const double marched = marchTransmittance(m, ray, path, kInf, h, &tauError);
            INFO("march step " << h << ": " << marched << ", tau error bound " << tauError);
            CHECK(std::fabs(marched - exact) <= marched * std::expm1(tauError) + 1e-15);
            if (c.kind == ZField::Kind::Constant) CHECK(marched == Approx(exact).epsilon(1e-12));
        }
    }
}

TEST_CASE("medium/empty space is skipped and a zero density passes everything") {
    Medium m = slab(std::make_shared<ZField>(ZField::Kind::Constant, 0.0, 0.0), 1.0);
    const Ray ray{Vec3(0.0, 0.0, -1.0), Vec3(0.0, 0.0, 1.0)};
    const MediumPath path(m, ray, 0.0, kInf);
    CHECK(path.empty());
    CHECK(path.rangeCalls() == 1);
    MediumRandom rng(1);
    CHECK(mediumTransmittance(m, ray, kInf, rng) == 1.0);
    // A ray that misses the box costs nothing.
    m.density = std::make_shared<ZField>(ZField::Kind::Constant, 1.0, 0.0);
    const MediumPath miss(m, Ray{Vec3(0.0, 0.0, -1.0), Vec3(0.0, 0.0, -1.0)}, 0.0, kInf);
    CHECK(miss.empty());
    CHECK(miss.rangeCalls() == 0);
}

TEST_CASE("medium/majorant distance sampling has the density it reports") {
    // ∫ f(t)·pdf(t)⁻¹·pdf(t) dt: the mean of g(t)/pdf(t) is ∫ g over the path, for g = 1 the
    // path's length inside the pieces.
    const auto field = std::make_shared<ZField>(ZField::Kind::Ramp, 0.1, 0.5);
    const Medium m = slab(field, 0.7);
    const Ray ray{Vec3(0.0, 0.0, -1.0), glm::normalize(Vec3(0.3, 0.0, 1.0))};
    const MediumPath path(m, ray, 0.0, kInf);
    double length = 0.0;
    for (int i = 0; i < path.size(); ++i) length += path[i].t1 - path[i].t0;
    const int n = 100000;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        double t = 0.0, pdf = 0.0;
        REQUIRE(sampleMajorantDistance(path, (i + 0.5) / n, t, pdf));
        sum += 1.0 / pdf;
    }
    CHECK(sum / n == Approx(length).epsilon(1e-3));
}

TEST_CASE("medium/single scattering of a constant slab under a directional light") {
    // Camera ray along +z through the slab 0 ≤ z ≤ L of extinction σ; the light travels along
    // w (w.z = c > 0), so it crosses s/c of the slab to reach depth s. No occluders:
    //   L = albedo·E·p(−c)·σ ∫₀ᴸ e^(−σs) e^(−σs/c) ds + background·e^(−σL)
    //     = albedo·E·p(−c)·(1 − e^(−σL(1+1/c))) / (1 + 1/c) + background·e^(−σL).
    const double sigma = 0.5, L = 2.0, g = 0.3;
    const Vec3 w = glm::normalize(Vec3(0.3, 0.0, 1.0));
    Scene scene;
    scene.background = Vec3(0.1, 0.2, 0.3);
    Light sun;
    sun.kind = Light::Kind::Directional;
    sun.direction = w;
    sun.color = Vec3(2.0, 1.5, 1.0);
    scene.lights.push_back(sun);
    scene.medium = slab(std::make_shared<ZField>(ZField::Kind::Constant, 1.0, 0.0), sigma, L);
    scene.medium.albedo = Vec3(0.8, 0.6, 0.4);
    scene.medium.g = g;
    const double c = w.z;
    const double phase = henyeyGreenstein(-c, g);
    const double k = 1.0 + 1.0 / c;
    const Vec3 exact = scene.medium.albedo * sun.color * phase * (-std::expm1(-sigma * L * k)) / k +
                       scene.background * std::exp(-sigma * L);
    const SceneGeometry geometry({});
    const Ray ray{Vec3(0.0, 0.0, -1.0), Vec3(0.0, 0.0, 1.0)};
    for (MediumMethod method : {MediumMethod::Ratio, MediumMethod::Delta, MediumMethod::March}) {
        scene.medium.method = method;
        scene.medium.step = 0.005;
        const WhittedIntegrator integrator(scene, geometry, 0);
        const PixelSampler sampler(64);
        ShadingContext ctx;
        ctx.sampler = &sampler;
        const int pixels = method == MediumMethod::March ? 1 : 64;
        Vec3 sum(0.0), sum2(0.0);
        for (int p = 0; p < pixels; ++p)
            for (int s = 0; s < 64; ++s) {
                ctx.pixel = uint64_t(p);
                ctx.sample = s;
                const Vec3 v = integrator.traceCamera(ray, ctx);
                sum += v;
                sum2 += v * v;
            }
        const double n = pixels * 64.0;
        const Vec3 mean = sum / n;
        INFO(mediumMethodName(method) << ": exact " << exact.x << " " << exact.y << " " << exact.z
                                      << ", got " << mean.x << " " << mean.y << " " << mean.z);
        for (int ch = 0; ch < 3; ++ch) {
            const double se =
                std::sqrt(std::max(0.0, sum2[ch] / n - mean[ch] * mean[ch]) / (n - 1));
            if (method == MediumMethod::March)  // deterministic: midpoint error O(h²)
                CHECK(mean[ch] == Approx(exact[ch]).epsilon(1e-4));
            else
                CHECK(std::fabs(mean[ch] - exact[ch]) <= 4 * se + 1e-4 * exact[ch]);
        }
    }
}

TEST_CASE("medium/the image is the same whatever the thread count") {
    Scene scene;
    Material m = blackMaterial();
    m.diffuse = 0.8;
    m.ambient = 0.05;
    addObject(scene, makeSphere(Vec3(0.0, 0.0, 1.0), 0.8), addMaterial(scene, m));
    addObject(scene, makeHalfSpace(Vec3(0, 1, 0), -1.0), addMaterial(scene, m));
    Light light;
    light.position = Vec3(1.5, 3.0, -0.5);
    light.power = 60.0;
    scene.lights.push_back(light);
    scene.medium = slab(std::make_shared<ZField>(ZField::Kind::Ramp, 0.2, 0.3), 0.8);
    scene.medium.bounds = Bounds3{Vec3(-3.0, -1.0, -2.0), Vec3(3.0, 3.0, 3.0)};
    scene.medium.g = 0.4;
    for (MediumMethod method : {MediumMethod::Ratio, MediumMethod::Delta, MediumMethod::March}) {
        scene.medium.method = method;
        RenderOptions one = smallImage(24, 16, 1), two = smallImage(24, 16, 2);
        one.spp = two.spp = 2;
        const RenderResult a = render(scene, one), b = render(scene, two);
        INFO(mediumMethodName(method));
        bool same = true, lit = false;
        for (int j = 0; j < 16; ++j)
            for (int i = 0; i < 24; ++i)
                for (int ch = 0; ch < 3; ++ch) {
                    same &= a.color.at(i, j, ch) == b.color.at(i, j, ch);
                    lit |= a.color.at(i, j, ch) > 0.0f;
                }
        CHECK(same);
        CHECK(lit);
    }
}
