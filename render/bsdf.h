/// @file render/bsdf.h
/// @brief A material's scattering at one hit, behind evaluate / sample / pdf (as pbrt-v4's
/// `BSDF`), so an integrator needs to know nothing of kerf's Material fields.
///
/// kerf's material (scene/scene.h) is a sum of lobes, all in world space about the shading
/// normal n (turned toward the viewer):
///  - Diffuse: Lambert, (1 − transmit)·diffuse·albedo·cos θi.
///  - Phong: specular·max(0, r·wo)^shininess, r the light direction mirrored about n.
///  - Mirror: the reflection of weight reflect + transmit·F (Schlick; all of transmit under
///    total internal reflection); a delta lobe, or, with glossy > 0, spread uniformly over
///    the cone of `glossy` degrees about the mirror direction (sampleConeAbove).
///  - Refraction: weight transmit·(1 − F)·albedo along Snell's direction; a delta lobe, or,
///    with translucent > 0, spread over the cone of `translucent` degrees.
///
/// Conventions. Directions are unit and point away from the surface (wo toward the viewer,
/// wi toward the light). evaluate() returns f(wo, wi)·|cos θi| — the projected BSDF, as
/// Mitsuba's `eval` — because kerf's Whitted model is written in that form (a Lambert term
/// diffuse·albedo·cos θi, with the 1/π folded into the light's units, and a Phong lobe
/// without a cosine); dividing and re-multiplying by the cosine would change its images' bits.
/// The diffuse lobe's albedo is therefore π·(1 − transmit)·diffuse·albedo over the hemisphere.
/// pdf() is a solid-angle density over the non-delta lobes. A sample's throughput is
/// value / pdf; for a delta lobe, value is its weight and pdf the probability of choosing
/// it, and evaluate()/pdf() never see it. Phong's projected value is symmetric in wo and wi
/// (its f is not: kerf's Phong has no cosine), Lambert's f is.
#pragma once

#include "render/sampler.h"
#include "scene/scene.h"

#include <cstdint>
#include <optional>

namespace kerf {

/// Which lobes a call covers (bit mask).
enum BsdfLobe : uint32_t {
    kLobeDiffuse = 1u << 0,
    kLobePhong = 1u << 1,
    kLobeMirror = 1u << 2,      ///< delta, or glossy with Material::glossy > 0
    kLobeRefraction = 1u << 3,  ///< delta, or glossy with Material::translucent > 0
    kLobesAll = 0xfu,
};

/// What a sampled lobe is (bit mask, as pbrt-v4's BxDFFlags).
enum BsdfKind : uint32_t {
    kKindReflection = 1u << 0,
    kKindTransmission = 1u << 1,
    kKindDiffuse = 1u << 2,
    kKindGlossy = 1u << 3,
    kKindSpecular = 1u << 4,  ///< a delta lobe: pdf is a probability, not a density
};

struct BsdfSample {
    Vec3 wi{0.0};       ///< unit, away from the surface
    Vec3 value{0.0};    ///< f·|cos θi| (a delta lobe: its weight)
    double pdf = 0.0;   ///< solid-angle density (a delta lobe: the probability of choosing it)
    uint32_t kind = 0;  ///< BsdfKind bits
    uint32_t lobe = 0;  ///< the BsdfLobe it came from
};

/// The mirror and refraction lobes' directions and weights for one wo (Fresnel included).
struct SpecularLobes {
    Vec3 reflectDir{0.0};     ///< the mirror direction (not normalised: unit up to rounding)
    Vec3 reflectWeight{0.0};  ///< reflect + transmit·F, or reflect + transmit under TIR
    Vec3 refractDir{0.0};     ///< unit; zero without refraction
    Vec3 refractWeight{0.0};  ///< transmit·(1 − F)·albedo; zero without refraction
};

class Bsdf {
public:
    /// m: the hit's material; albedo its colour there (pattern or flat colour); n the unit
    /// shading normal facing wo; entering: the ray enters the solid (n1 = 1, n2 = ior).
    Bsdf(const Material& m, const Vec3& albedo, const Vec3& n, bool entering);

    /// @brief f(wo, wi)·|cos θi| summed over the non-delta lobes in `lobes`; 0 for wi below
    /// the surface for reflection lobes.
    Vec3 evaluate(const Vec3& wo, const Vec3& wi, uint32_t lobes = kLobesAll) const;
    /// @brief One direction from the lobes, chosen in proportion to their albedo bounds by
    /// uLobe ∈ [0, 1), then within the lobe by u. nullopt: nothing scatters.
    std::optional<BsdfSample> sample(const Vec3& wo, double uLobe, const SubPixel& u) const;
    /// @brief The solid-angle density with which sample() returns wi from a non-delta lobe.
    double pdf(const Vec3& wo, const Vec3& wi) const;
    /// @brief The mirror and refraction lobes for wo (what Whitted traces as rays).
    SpecularLobes specular(const Vec3& wo) const;

    const Vec3& normal() const { return mNormal; }

private:
    /// The lobes' selection weights (albedo bounds) given wo's specular lobes s, in BsdfLobe
    /// order (sum > 0 unless nothing scatters).
    void lobeWeights(const SpecularLobes& s, double w[4]) const;
    /// The non-delta density of lobe `lobe` (one bit) at wi.
    double lobePdf(uint32_t lobe, const Vec3& wo, const Vec3& wi, const SpecularLobes& s) const;

    const Material& mMaterial;
    Vec3 mAlbedo;
    Vec3 mNormal;
    bool mEntering;
};

/// The density of sampleConeAbove(axis, side, halfAngleDegrees, ·) at the unit direction wi.
double coneAbovePdf(const Vec3& axis, const Vec3& side, double halfAngleDegrees, const Vec3& wi);

}  // namespace kerf
