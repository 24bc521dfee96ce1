/// @file render/render.h
/// @brief The front door of render/: a Scene and options in, images and statistics out.
#pragma once

#include "scene/scene.h"
#include "csg/trace_context.h"
#include "io/image.h"
#include "render/primary_beams.h"
#include "volume/accelerate.h"

#include <functional>
#include <optional>

namespace kerf {

struct RenderOptions {
    int width = 0;        ///< 0: take the scene's render settings
    int height = 0;       ///< 0: take the scene's render settings
    int spp = 0;          ///< 0: take the scene's render settings
    std::optional<SamplerKind> sampler;  ///< unset: take the scene's render settings
    std::optional<FilterKind> filter;    ///< unset: take the scene's render settings
    double noise = -1.0;  ///< adaptive sampling's target; < 0: take the scene's render settings
    int threads = 0;      ///< 0: all hardware threads
    double tolerance = 0; ///< relative hit-distance tolerance; 0: derived from the pixel footprint
    TraceMethod method = TraceMethod::Closed;  ///< how primitives find crossings
    Accel accel = Accel::Auto;  ///< acceleration structures (volume/accelerate.h)
    int accelDepth = 0;         ///< the octree's finest level; 0: from the pixel footprint
    BeamMode beams = BeamMode::Auto;  ///< coherent camera rays (render/primary_beams.h)
    bool wantDepth = false;   ///< fill RenderResult::depth
    bool wantNormal = false;  ///< fill RenderResult::normal
    /// Called now and then with the fraction done (0..1); may be empty.
    std::function<void(double)> progress;
};

struct RenderStats {
    uint64_t cameraRays = 0;
    uint64_t shadowRays = 0;
    uint64_t reflectionRays = 0;
    uint64_t refractionRays = 0;
    TraceStats trace;
    OctreeStats octree;       ///< what the octrees cost and hold (none: all zero)
    bool beamsUsed = false;   ///< whether camera rays started where their beams said
    BeamStats beams;
    double secondsSetup = 0;  ///< parse excluded: camera, acceleration structures
    double secondsAccel = 0;  ///< of secondsSetup, building the octrees
    double secondsTrace = 0;
    double tolerance = 0;  ///< the relative tolerance in force
    int samplesPerPixel = 0;  ///< traced per pixel (the requested spp, clamped to the limit)
    SamplerKind sampler = SamplerKind::Jittered;
    FilterKind filter = FilterKind::Box;
    uint64_t samplesTaken = 0;  ///< camera samples traced (fewer than pixels × spp with --noise)
};

struct RenderResult {
    Image color;   ///< 3 channels, linear RGB
    Image depth;   ///< 1 channel: eye-to-first-hit distance of the pixel-centre ray, +inf on a miss
    Image normal;  ///< 3 channels: world unit normal at that hit (0 on a miss)
    RenderStats stats;
};

/// The default relative tolerance for an image of `height` rows and vertical field of view
/// `fovDegrees`: a fraction of the angle one pixel spans (see docs/accuracy.md).
double defaultTolerance(int height, double fovDegrees);

/// Adaptive sampling takes at least this many samples of a pixel (or all, if fewer) before it
/// trusts the estimate of the noise.
constexpr int kMinAdaptiveSamples = 16;

RenderResult render(const Scene& scene, const RenderOptions& options);

}  // namespace kerf
