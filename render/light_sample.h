/// @file render/light_sample.h
/// @brief Where a shading point sees a light from, and how much arrives: one sample of the
/// light per call, exact for point and directional lights, an unbiased estimate for area and
/// sphere lights (whose shadows are therefore soft), and the cone sampling that glossy and
/// translucent rays use.
#pragma once

#include "render/sampler.h"
#include "scene/scene.h"

namespace kerf {

struct LightSample {
    Vec3 direction{0.0};  ///< unit, from the shading point toward the light
    /// How far a shadow ray from `origin` must run to reach the sampled light point (inf for
    /// directional lights).
    double distance = 0.0;
    /// The light arriving along `direction`, divided by the sample's density: the term the
    /// surface's cosine and BRDF multiply. Zero where the sample sees no light.
    Vec3 radiance{0.0};
};

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
