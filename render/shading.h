/// @file render/shading.h
/// @brief The Whitted integrator: Phong terms with shadow rays, mirror reflection, refraction
/// with Fresnel and Beer absorption, emission and homogeneous mist.
///
/// Material model (kerf's choices, documented in docs/ too):
///  - colour = emit + (1 − transmit)·(ambient·color + Σ diffuse·color·max(0, n·l)·L·T)
///            + Σ specular·max(0, r·v)^shininess·L·T + reflection + refraction,
///    n the normal turned toward the viewer, L a light's radiance, T the shadow transmittance.
///    The (1 − transmit) factor keeps a dielectric from also looking like painted plastic.
///  - reflection: weight `reflect`, untinted (as a dielectric's coat; a coloured metal is
///    not expressible yet), plus transmit·F for dielectrics (Schlick's F; all of transmit
///    under total internal reflection). Both go into one mirror ray.
///  - refraction (transmit > 0): Snell with n1 = 1, n2 = ior when entering, the reverse when
///    leaving; weight transmit·(1 − F)·color.
///  - Beer: light that reaches the viewer through a hit where the ray leaves a solid was inside
///    it for the whole segment: scaled by exp(−absorb·length), absorb of that hit's material.
///  - shadows: opaque surfaces block; a transmissive surface crossed multiplies by
///    color·transmit, and the length inside it by exp(−absorb·length). No refraction of shadow
///    rays (Whitted), and homogeneous mist does not dim lights.
///  - a heterogeneous medium (scene/medium.h, render/shading_medium.cpp) dims every segment
///    (camera, reflected, refracted and shadow rays) by its transmittance and adds the light
///    it scatters once toward the viewer (point, directional, area and sphere lights, with
///    shadows, Henyey–Greenstein phase) and its emission. No medium: none of this runs.
///  - mist: every segment of length d blends c → mist + (c − mist)·exp(−d/distance); a miss
///    takes the mist colour.
///  - recursion stops at maxDepth bounces or when a ray's weight is below kMinRayWeight in
///    every channel, and a camera ray's whole tree holds at most kRayBudget secondary rays:
///    each hit shares what is left of its budget between its reflected and refracted rays in
///    proportion to their weights (splitRayBudget), so the work per camera ray is bounded
///    whatever the weights and depth, and the cut is deterministic. With weights the language
///    accepts (reflect + transmit ≤ 1, color ≤ 1) a ray of weight w gets a budget of about
///    w·kRayBudget ≥ 65, so the budget never cuts a ray of weight ≥ kMinRayWeight in scenes
///    of ordinary depth.
#pragma once

#include "csg/bvh/scene_geometry.h"
#include "csg/trace_context.h"
#include "render/medium.h"
#include "render/sampler.h"
#include "scene/scene.h"

#include <cstdint>
#include <optional>

namespace kerf {

/// Rays traced, by kind (per thread; summed for --stats).
struct RayCounters {
    uint64_t camera = 0;
    uint64_t shadow = 0;
    uint64_t reflection = 0;
    uint64_t refraction = 0;
};

/// What one thread needs to shade: its trace context, its counters, and which sample of
/// which pixel it is tracing (for the light, gloss and translucency samples). Never shared.
struct ShadingContext {
    TraceContext trace;
    RayCounters rays;
    const PixelSampler* sampler = nullptr;  ///< null: area lights and cones take their centre
    uint64_t pixel = 0;
    int sample = 0;
    /// The angle one sample stands for (a pixel's, shared by its samples): a hit's footprint
    /// is this times the distance travelled, for filtering patterns. 0: no filtering.
    double sampleAngle = 0.0;

    /// The current sample's point in dimension `dim` (render/sampler.h).
    SubPixel sample2D(uint32_t dim) const {
        return sampler ? sampler->get2D(pixel, sample, dim) : SubPixel{};
    }
};

/// The light's falloff against the inverse square that sampleLight applies, at p.
double falloffScale(const Light& light, const Vec3& p);

/// The sampler dimension a bounce's medium scattering distance draws from.
inline uint32_t mediumSampleDim(int depth) { return (1u << 29) + uint32_t(depth); }

/// Secondary rays whose weight is below this in every channel are not traced.
constexpr double kMinRayWeight = 1e-3;

/// The most secondary (reflection and refraction) rays one camera ray may lead to.
constexpr uint64_t kRayBudget = uint64_t(1) << 16;

/// How a hit's remaining budget is shared: each child ray costs one and passes on the rest.
struct RayBudgetSplit {
    uint64_t reflect = 0;  ///< 0: not traced
    uint64_t refract = 0;
};

/// Splits `budget` between the reflected and refracted rays of path weights (largest
/// channel) reflectWeight and refractWeight, in proportion to them; a ray below
/// kMinRayWeight gets nothing. The two parts never sum to more than `budget`.
RayBudgetSplit splitRayBudget(uint64_t budget, double reflectWeight, double refractWeight);

class WhittedIntegrator {
public:
    /// The scene and geometry must outlive the integrator. maxDepth bounds the number of
    /// reflection/refraction bounces (0: none).
    /// shadowGeometry: the objects that cast shadows (all of them where null).
    WhittedIntegrator(const Scene& scene, const SceneGeometry& geometry, int maxDepth,
                      const SceneGeometry* shadowGeometry = nullptr);

    /// The radiance seen along a camera ray. When firstHit is given, it receives the ray's
    /// first hit (or nullopt on a miss), for the depth and normal outputs. tStart: a distance
    /// before which the ray is known to be outside every object (render/primary_beams.h).
    Vec3 traceCamera(const Ray& ray, ShadingContext& ctx, std::optional<Hit>* firstHit = nullptr,
                     double tStart = 0.0) const;

private:
    /// Radiance arriving along `ray`, whose segment starts at `segmentStart` (the un-offset
    /// point the ray left, for lengths), after `depth` bounces, with path weight `weight`,
    /// allowed to spawn at most `budget` secondary rays below it.
    /// travelled: the path's length from the camera to segmentStart (for footprints).
    Vec3 trace(const Ray& ray, const Vec3& segmentStart, int depth, const Vec3& weight,
               uint64_t budget, ShadingContext& ctx, std::optional<Hit>* firstHit,
               double tStart = 0.0, double travelled = 0.0) const;
    /// Direct light at p (normal n toward the viewer, unit view direction d).
    /// albedo: the material's colour at p (its pattern's, or its flat colour).
    Vec3 directLight(const Material& m, const Vec3& albedo, const Vec3& p, const Vec3& n,
                     const Vec3& d, double errorBound, int depth, ShadingContext& ctx) const;
    /// The fraction of light that passes from ray.origin along ray.dir (unit) up to tmax.
    Vec3 transmittance(const Ray& ray, double tmax, ShadingContext& ctx) const;
    /// Only the surfaces' part of transmittance().
    Vec3 surfaceTransmittance(const Ray& ray, double tmax, ShadingContext& ctx) const;
    /// `behind` seen through the medium along the unit ray up to tEnd (inf: through its whole
    /// box), plus the light the medium scatters and emits toward the ray's origin on the way.
    Vec3 throughMedium(const Ray& ray, double tEnd, const Vec3& behind, int depth,
                       ShadingContext& ctx) const;
    /// The same by the March method: deterministic steps.
    Vec3 marchMedium(const Ray& ray, double tEnd, const Vec3& behind, ShadingContext& ctx,
                     MediumRandom& rng) const;
    /// Σ over lights of phase · irradiance · shadow transmittance at x in the medium, for
    /// light leaving along −d (d the unit ray direction).
    Vec3 scatteredLight(const Vec3& x, const Vec3& d, ShadingContext& ctx, MediumRandom& rng) const;
    /// The seed of a medium estimate's random numbers: the pixel sample and the ray's bits.
    uint64_t mediumSeed(const ShadingContext& ctx, const Ray& ray, uint32_t purpose) const;
    /// What a ray along the unit direction d that hits nothing sees.
    Vec3 missColor(const Vec3& d) const;
    Vec3 applyMist(const Vec3& c, double distance) const;
    const Material& material(int32_t index) const;

    const Scene& mScene;
    const SceneGeometry& mGeometry;
    const SceneGeometry& mShadowGeometry;
    int mMaxDepth;
    bool mAnyTransmissive = false;  ///< else shadow rays only ask for any hit
    bool mMedium = false;           ///< the scene has a heterogeneous medium
    /// Per light: the generator of the rank-1 lattice its `samples` points follow (1 when it
    /// takes one sample).
    std::vector<uint32_t> mLightLattice;
};

}  // namespace kerf
