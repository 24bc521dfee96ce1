/// @file render/medium_transport.h
/// @brief Light carried through the scene's heterogeneous medium (scene/medium.h) along one
/// segment: the transmittance of what is behind, plus single scattering from every light and
/// the medium's emission. Shared by integrators; built on render/medium.h's estimators.
///
/// Along a unit ray through the medium up to tEnd, with T(t) the transmittance from the origin:
///   L = T(tEnd)·behind + ∫ T(t)·σt(t)·(emission + albedo·Σ_lights phase·E·T_light) dt.
/// Ratio and Delta estimate T(tEnd) by tracking, and the integral with `samples` distances
/// drawn from the majorant's free flight (so thick media put their samples near the entry),
/// each weighted by T(t)·σt(t)/pdf(t) with T(t) tracked again: unbiased. The first distance
/// comes from the pixel sample's own stratified point, so spp samples cover the segment
/// evenly. March steps deterministically: each step of constant σt adds T·(1 − e^(−σt·h))·S.
#pragma once

#include "render/integrator.h"
#include "render/medium.h"
#include "render/transmittance.h"

namespace kerf {

/// The sampler dimension a bounce's medium scattering distance draws from.
inline uint32_t mediumSampleDim(int depth) { return (1u << 29) + uint32_t(depth); }

/// The seed of a medium estimate's random numbers: the pixel sample and the ray's bits, so
/// the estimate does not depend on the thread. purpose: 1 segments, 2 shadow rays.
uint64_t mediumSeed(const ShadingContext& ctx, const Ray& ray, uint32_t purpose);

class MediumTransport {
public:
    /// scene and shadows (used for the scattered light's shadow rays) must outlive this.
    MediumTransport(const Scene& scene, const Transmittance& shadows);

    /// Whether the scene has a medium (else through() returns `behind`, and need not be called).
    bool enabled() const { return mEnabled; }

    /// @brief `behind` seen through the medium along the unit ray up to tEnd (inf: through
    /// its whole box), plus the light the medium scatters and emits toward the ray's origin.
    /// depth: the bounce, for the sampler dimension of the first scattering distance.
    Vec3 through(const Ray& ray, double tEnd, const Vec3& behind, int depth,
                 ShadingContext& ctx) const;

private:
    /// through() by the March method: deterministic steps.
    Vec3 march(const Ray& ray, double tEnd, const Vec3& behind, ShadingContext& ctx,
               MediumRandom& rng) const;
    /// Σ over lights of phase · irradiance · shadow transmittance at x in the medium, for
    /// light leaving along −d (d the unit ray direction).
    Vec3 scatteredLight(const Vec3& x, const Vec3& d, ShadingContext& ctx, MediumRandom& rng) const;

    const Scene& mScene;
    const Transmittance& mShadows;
    bool mEnabled = false;
};

}  // namespace kerf
