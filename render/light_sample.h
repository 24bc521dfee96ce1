/// @file render/light_sample.h
/// @brief Where a shading point sees a light from, and how much arrives: one sample of the
/// light per call, exact for point and directional lights, an unbiased estimate for area and
/// sphere lights (whose shadows are therefore soft), and the cone sampling that glossy and
/// translucent rays use.
#pragma once

#include "render/sampler.h"
#include "scene/scene.h"

namespace kerf {

/// The measure a LightSample's pdf is a density in.
enum class LightPdfMeasure {
    Delta,       ///< point and directional lights: one direction, pdf = 1
    Area,        ///< area lights: per unit area of the light (uniform: 1/A)
    SolidAngle,  ///< sphere lights: per steradian seen from the shading point (uniform: 1/Ω)
};

/// One point of a light seen from a shading point p. `radiance` is the ready-made estimate
/// (what Whitted multiplies by the BSDF); position, normal, emitted and pdf are its parts, for
/// integrators that weigh light samples themselves (multiple importance sampling):
///   Area:       radiance = emitted·|cos θ_light|/d² / pdf  (pdf per area, d = |position − p|)
///   SolidAngle: radiance = emitted / pdf                   (pdf per steradian)
///   Delta:      radiance = emitted (the irradiance-like term; pdf = 1)
/// before the falloff (falloffScale), which the caller applies.
struct LightSample {
    Vec3 direction{0.0};  ///< unit, from the shading point toward the light
    /// How far a shadow ray from `origin` must run to reach the sampled light point (inf for
    /// directional lights).
    double distance = 0.0;
    /// The light arriving along `direction`, divided by the sample's density: the term the
    /// surface's cosine and BRDF multiply. Zero where the sample sees no light.
    Vec3 radiance{0.0};
    Vec3 position{
        0.0};  ///< the sampled point on the light (point lights: the light; directional: 0)
    Vec3 normal{
        0.0};  ///< the light's unit normal there (area: edgeU × edgeV; sphere: outward; else 0)
    Vec3 emitted{0.0};  ///< radiance leaving the light (Delta: as `radiance`)
    double pdf = 0.0;   ///< density of the sample in `measure`; 0: no sample
    LightPdfMeasure measure = LightPdfMeasure::Delta;
};

/// The light's falloff against the inverse square that sampleLight applies, at p.
double falloffScale(const Light& light, const Vec3& p);

/// @brief The solid-angle density at p with which sampleLight picks the unit direction wi:
/// area lights 1/A·d²/|cos θ_light| where wi meets the parallelogram, sphere lights 1/Ω
/// inside the cone the ball fills; 0 elsewhere and for point and directional lights (deltas).
double lightPdf(const Light& light, const Vec3& p, const Vec3& wi);

/// One sample of `light` seen from p (shadow rays start at `origin`, p offset off the
/// surface); u: a point of the unit square for the area and sphere lights.
LightSample sampleLight(const Light& light, const Vec3& p, const Vec3& origin, const SubPixel& u);

/// A direction uniformly distributed over the cone of half-angle `halfAngle` (radians) about
/// the unit vector `axis`, from the unit-square point u.
Vec3 sampleCone(const Vec3& axis, double halfAngle, const SubPixel& u);

/// A direction spread uniformly over the cone of `halfAngleDegrees` about `axis` (glossy and
/// translucent rays), kept on the side of the surface (normal `side`) the axis is on: one
/// that falls below is mirrored back above, so no energy is lost and none leaks through.
Vec3 sampleConeAbove(const Vec3& axis, const Vec3& side, double halfAngleDegrees,
                     const SubPixel& u);

/// A unit vector perpendicular to the unit vector a (for frames about a).
Vec3 perpendicularTo(const Vec3& a);

}  // namespace kerf
