/// @file render/medium_transport.cpp
/// @brief Transport through the heterogeneous medium (see medium_transport.h).
#include "render/medium_transport.h"

#include "render/light_sample.h"

#include <cstring>

namespace kerf {

uint64_t mediumSeed(const ShadingContext& ctx, const Ray& ray, uint32_t purpose) {
    uint64_t h = mixBits(ctx.pixel) ^ (uint64_t(uint32_t(ctx.sample)) << 32 | purpose);
    const double v[6] = {ray.origin.x, ray.origin.y, ray.origin.z, ray.dir.x, ray.dir.y, ray.dir.z};
    for (double x : v) {
        uint64_t bits;
        std::memcpy(&bits, &x, sizeof bits);
        h = mixBits(h ^ bits);
    }
    return h;
}

MediumTransport::MediumTransport(const Scene& scene, const Transmittance& shadows)
    : mScene(scene), mShadows(shadows), mEnabled(scene.medium.enabled()) {}

Vec3 MediumTransport::scatteredLight(const Vec3& x, const Vec3& d, ShadingContext& ctx,
                                     MediumRandom& rng) const {
    Vec3 sum(0.0);
    for (const Light& light : mScene.lights) {
        const SubPixel u{rng.next(), rng.next()};
        LightSample ls = sampleLight(light, x, x, u);
        ls.radiance *= falloffScale(light, x);
        if (!(std::max({ls.radiance.x, ls.radiance.y, ls.radiance.z}) > 0.0)) continue;
        Vec3 pass(1.0);
        if (light.shadows) {
            ++ctx.rays.shadow;
            pass = mShadows.along(Ray{x, ls.direction}, ls.distance, ctx);
        }
        // Light travels along −l and leaves along −d: the scattering angle's cosine is l·d.
        sum += pass * ls.radiance * henyeyGreenstein(glm::dot(ls.direction, d), mScene.medium.g);
    }
    return sum;
}

Vec3 MediumTransport::through(const Ray& ray, double tEnd, const Vec3& behind, int depth,
                              ShadingContext& ctx) const {
    const Medium& m = mScene.medium;
    const MediumPath path(m, ray, 0.0, tEnd);
    if (path.empty()) return behind;
    MediumRandom rng(mediumSeed(ctx, ray, 1));
    if (m.method == MediumMethod::March) return march(ray, tEnd, behind, ctx, rng);
    const auto track = [&](double end) {
        return m.method == MediumMethod::Ratio ? ratioTracking(m, ray, path, end, rng)
                                               : deltaTracking(m, ray, path, end, rng);
    };
    Vec3 L = behind * track(tEnd);
    const int n = std::max(1, m.samples);
    const double u0 = ctx.sample2D(mediumSampleDim(depth)).x;
    for (int s = 0; s < n; ++s) {
        double t = 0.0, pdf = 0.0;
        if (!sampleMajorantDistance(path, (s + u0) / n, t, pdf) || !(pdf > 0.0)) break;
        const Vec3 x = ray.at(t);
        const double sigma = extinctionAt(m, x);
        if (!(sigma > 0.0)) continue;
        const double T = track(t);
        if (!(T > 0.0)) continue;
        const Vec3 source = m.emission + m.albedo * scatteredLight(x, ray.dir, ctx, rng);
        L += (T * sigma / (pdf * n)) * source;
    }
    return L;
}

Vec3 MediumTransport::march(const Ray& ray, double tEnd, const Vec3& behind, ShadingContext& ctx,
                            MediumRandom& rng) const {
    const Medium& m = mScene.medium;
    const MediumPath path(m, ray, 0.0, tEnd);
    const double step = marchStep(m);
    double T = 1.0;
    Vec3 L(0.0);
    for (int i = 0; i < path.size(); ++i) {
        const MediumPiece& p = path[i];
        const double len = std::min(p.t1, tEnd) - p.t0;
        const int steps = std::max(1, int(std::ceil(len / step)));
        const double h = len / steps;
        for (int k = 0; k < steps; ++k) {
            const Vec3 x = ray.at(p.t0 + (k + 0.5) * h);
            const double sigma = extinctionAt(m, x);
            if (!(sigma > 0.0)) continue;
            // ∫ T σ dt over a step of constant σ is T·(1 − e^(−σh)), exactly.
            const double absorbed = -std::expm1(-sigma * h);
            L += (T * absorbed) * (m.emission + m.albedo * scatteredLight(x, ray.dir, ctx, rng));
            T *= 1.0 - absorbed;
            if (T < std::exp(-kMarchOpaqueDepth)) return L;  // what is behind adds < 1e-6
        }
    }
    return L + T * behind;
}

}  // namespace kerf
