/// @file render/transmittance.h
/// @brief What any integrator needs to carry light along a segment: shadow transmittance
/// through tinted transmissive surfaces and absorbing solids (and the heterogeneous medium,
/// when the scene has one), Beer absorption, homogeneous mist and the colour of a miss.
///
/// Shadow rays follow kerf's Whitted convention: opaque surfaces block; a transmissive
/// surface crossed multiplies by color·transmit, and the length inside a solid by
/// exp(−absorb·length). Shadow rays are not refracted, and homogeneous mist does not dim
/// lights.
#pragma once

#include "render/integrator.h"

#include <algorithm>

namespace kerf {

/// The largest channel of v.
inline double maxComponent(const Vec3& v) { return std::max({v.x, v.y, v.z}); }

/// The material of index `index`, the scene's default (its first) when out of range.
inline const Material& materialOf(const Scene& scene, int32_t index) {
    if (index < 0 || size_t(index) >= scene.materials.size()) return scene.materials.front();
    return scene.materials[size_t(index)];
}

/// exp(−absorb·length) per channel; a channel that does not absorb passes everything, even
/// over an infinite length (where 0·inf would be NaN).
Vec3 beer(const Vec3& absorb, double length);

/// What a ray along the unit direction d that hits nothing sees: the mist colour with mist,
/// else the sky gradient or the background.
Vec3 missColor(const Scene& scene, const Vec3& d);

/// Radiance c seen through `distance` of the scene's homogeneous mist (c itself without).
Vec3 applyMist(const Scene& scene, const Vec3& c, double distance);

/// The fraction of light that passes along a shadow ray (surfaces, solids, and the medium).
class Transmittance {
public:
    /// scene and shadowGeometry (the objects that cast shadows) must outlive this.
    Transmittance(const Scene& scene, const SceneGeometry& shadowGeometry);

    /// @brief The fraction passing from ray.origin along ray.dir up to tmax (in units of
    /// ray.dir): surfaces' and solids' part times the medium's estimate.
    Vec3 along(const Ray& ray, double tmax, ShadingContext& ctx) const;
    /// @brief Only the surfaces' and solids' part of along().
    Vec3 surfaces(const Ray& ray, double tmax, ShadingContext& ctx) const;

private:
    const Scene& mScene;
    const SceneGeometry& mShadowGeometry;
    bool mAnyTransmissive = false;  ///< else shadow rays only ask for any hit
    bool mMedium = false;           ///< the scene has a heterogeneous medium
};

}  // namespace kerf
