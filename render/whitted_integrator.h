/// @file render/whitted_integrator.h
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
///  - a heterogeneous medium (scene/medium.h, render/medium_transport.h) dims every segment
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
/// The material's lobes come from its Bsdf (render/bsdf.h): the diffuse and Phong terms are
/// the BSDF's evaluate() summed per light, the mirror and refracted rays its specular()
/// lobes; shadow transmittance, mist and the medium are render/transmittance.h and
/// render/medium_transport.h, shared with any integrator.
#pragma once

#include "render/integrator.h"
#include "render/medium_transport.h"
#include "render/transmittance.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace kerf {

class Bsdf;

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

class WhittedIntegrator final : public Integrator {
public:
    /// The scene and geometry must outlive the integrator. maxDepth bounds the number of
    /// reflection/refraction bounces (0: none).
    /// shadowGeometry: the objects that cast shadows (all of them where null).
    WhittedIntegrator(const Scene& scene, const SceneGeometry& geometry, int maxDepth,
                      const SceneGeometry* shadowGeometry = nullptr);

    /// @brief The radiance seen along a camera ray (Integrator::traceCamera).
    Vec3 traceCamera(const Ray& ray, ShadingContext& ctx, std::optional<Hit>* firstHit = nullptr,
                     double tStart = 0.0) const override;

private:
    /// Where a traced ray's segment stands in its path.
    struct PathState {
        Vec3 segmentStart;       ///< the un-offset point the ray left, for lengths
        int depth = 0;           ///< bounces so far
        Vec3 weight{1.0};        ///< the path's weight
        uint64_t budget = 0;     ///< secondary rays it may still spawn
        double travelled = 0.0;  ///< the path's length from the camera to segmentStart
    };

    /// Radiance arriving along `ray` (see PathState). tStart: as traceCamera's.
    Vec3 trace(const Ray& ray, const PathState& path, ShadingContext& ctx,
               std::optional<Hit>* firstHit, double tStart = 0.0) const;
    /// Adds to c the mirror and refracted rays' radiance at p (unit view direction d,
    /// face-forward shading normal n, hit error bound err), `length` past the segment start.
    void traceSecondary(const Bsdf& bsdf, const Material& m, const Vec3& p, const Vec3& d,
                        double err, double length, const PathState& path, ShadingContext& ctx,
                        Vec3& c) const;
    /// Direct light at p through the BSDF's diffuse and Phong lobes (unit view direction d).
    Vec3 directLight(const Bsdf& bsdf, const Vec3& p, const Vec3& d, double errorBound, int depth,
                     ShadingContext& ctx) const;
    /// The shift of light k's lattice of `count` unit-square points at this bounce.
    SubPixel lightShift(size_t k, int depth, uint32_t count, const ShadingContext& ctx) const;

    const Scene& mScene;
    const SceneGeometry& mGeometry;
    int mMaxDepth;
    Transmittance mShadows;
    MediumTransport mMedium;
    /// Per light: the generator of the rank-1 lattice its `samples` points follow (1 when it
    /// takes one sample).
    std::vector<uint32_t> mLightLattice;
};

}  // namespace kerf
