/// @file render/integrator.h
/// @brief The light-transport interface the render loop calls once per camera sample, the
/// per-thread context it traces with, and the factory that picks an implementation.
///
/// The render loop (render/render.cpp: tiles, film, passes, AOVs) knows only `Integrator`;
/// an implementation (render/whitted_integrator.h today) owns how radiance is gathered. As in
/// pbrt-v4's `Integrator`/`RayIntegrator`, the loop hands over a camera ray and gets radiance
/// back; unlike pbrt, the integrator also reports the ray's first hit (for the depth and
/// normal outputs) so those cost no extra ray where one sample serves the pixel.
#pragma once

#include "csg/bvh/scene_geometry.h"
#include "csg/trace_context.h"
#include "render/sampler.h"
#include "scene/scene.h"

#include <cstdint>
#include <functional>
#include <memory>
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

/// A light-transport method. Implementations are immutable after construction and called
/// from many threads at once, each with its own ShadingContext.
class Integrator {
public:
    virtual ~Integrator() = default;

    /// @brief The radiance (linear RGB) seen along a camera ray.
    /// firstHit (may be null) receives the ray's first hit, or nullopt on a miss, for the
    /// depth and normal outputs. tStart: a distance before which the ray is known to be
    /// outside every object (render/primary_beams.h).
    virtual Vec3 traceCamera(const Ray& ray, ShadingContext& ctx,
                             std::optional<Hit>* firstHit = nullptr, double tStart = 0.0) const = 0;
};

/// What an integrator is built from. All references outlive the integrator.
struct IntegratorInputs {
    const Scene& scene;
    const SceneGeometry& geometry;
    /// The objects that cast shadows (those not marked no_shadow); null: all of them.
    const SceneGeometry* shadowGeometry = nullptr;
};

/// Builds an integrator for one render (RenderOptions::integrator; empty: makeIntegrator).
using IntegratorFactory = std::function<std::unique_ptr<Integrator>(const IntegratorInputs&)>;

/// @brief The integrator the scene's render settings ask for (today always Whitted, with the
/// scene's maxDepth).
std::unique_ptr<Integrator> makeIntegrator(const IntegratorInputs& inputs);

}  // namespace kerf
