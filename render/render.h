/// @file render/render.h
/// @brief The front door of render/: a Scene and options in, images and statistics out.
#pragma once

#include "csg/trace_context.h"
#include "io/image.h"
#include "render/film.h"
#include "render/integrator.h"
#include "render/primary_beams.h"
#include "scene/scene.h"
#include "volume/octree/accelerate.h"

#include <functional>
#include <optional>

namespace kerf {

/// A half-open rectangle of pixels [x0, x1) × [y0, y1) of the full image (x right, y down).
struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
    bool operator==(const PixelRect& o) const {
        return x0 == o.x0 && y0 == o.y0 && x1 == o.x1 && y1 == o.y1;
    }
};

/// The overlap of two rectangles (empty() when they do not overlap).
PixelRect intersect(const PixelRect& a, const PixelRect& b);

/// Tiles are squares of this many pixels on a fixed grid from the full image's top-left
/// corner, numbered row by row; a region render uses the same grid.
constexpr int kTileSize = 16;

/// The pixels of `tile` in a width × height image.
PixelRect tileRect(int tile, int width, int height);

/// The tiles a render of `region` traces, in increasing order (the order in which their films
/// are summed): those with a pixel within `margin` pixels of the region (margin: the filter's
/// reach, 0 for the box filter, whose pixels only see their own samples).
std::vector<int> regionTiles(int width, int height, const PixelRect& region, int margin);

/// How far a filter's samples reach into neighbouring pixels: 0 for the box filter.
int filterMargin(FilterKind kind);

struct RenderOptions {
    int width = 0;                       ///< 0: take the scene's render settings
    int height = 0;                      ///< 0: take the scene's render settings
    int spp = 0;                         ///< 0: take the scene's render settings
    std::optional<SamplerKind> sampler;  ///< unset: take the scene's render settings
    std::optional<FilterKind> filter;    ///< unset: take the scene's render settings
    double noise = -1.0;   ///< adaptive sampling's target; < 0: take the scene's render settings
    int threads = 0;       ///< 0: all hardware threads
    double tolerance = 0;  ///< relative hit-distance tolerance; 0: derived from the pixel footprint
    TraceMethod method = TraceMethod::Closed;  ///< how primitives find crossings
    Accel accel = Accel::Auto;        ///< acceleration structures (volume/octree/accelerate.h)
    int accelDepth = 0;               ///< the octree's finest level; 0: from the pixel footprint
    BeamMode beams = BeamMode::Auto;  ///< coherent camera rays (render/primary_beams.h)
    bool wantDepth = false;           ///< fill RenderResult::depth
    bool wantNormal = false;          ///< fill RenderResult::normal
    /// Called now and then with the fraction done (0..1); may be empty.
    std::function<void(double)> progress;
    /// Only these pixels of the full image (`--region`); each equal, bit for bit, to the same
    /// pixel of a full render, whatever the sampler, filter, --noise and AOVs (a wider filter
    /// traces the pixels within its reach too, and sums the tiles in the full render's order).
    /// Unset: the whole image.
    std::optional<PixelRect> region;
    /// For drivers that share the tiles of one image between processes (app/mpi): returns
    /// the next job number n (0, 1, 2, … counted across all the processes); this call renders
    /// tile regionTiles(…)[n] while n is below their count, and stops at the first n past it.
    /// Called from several threads, one at a time. Empty: this call renders every tile.
    std::function<int()> nextTile;
    /// Builds the light-transport method (render/integrator.h); empty: makeIntegrator, the
    /// one the scene's settings ask for. Tests and new integrators plug in here.
    IntegratorFactory integrator;
};

struct RenderStats {
    uint64_t cameraRays = 0;
    uint64_t shadowRays = 0;
    uint64_t reflectionRays = 0;
    uint64_t refractionRays = 0;
    TraceStats trace;
    OctreeStats octree;      ///< what the octrees cost and hold (none: all zero)
    bool beamsUsed = false;  ///< whether camera rays started where their beams said
    BeamStats beams;
    double secondsSetup = 0;  ///< parse excluded: camera, acceleration structures
    double secondsAccel = 0;  ///< of secondsSetup, building the octrees
    double secondsTrace = 0;
    double tolerance = 0;     ///< the relative tolerance in force
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
    /// The pixels the images hold, in the full image: pixel (x, y) of `color` is pixel
    /// (region.x0 + x, region.y0 + y) of the fullWidth × fullHeight image. The whole image
    /// unless RenderOptions::region was set.
    PixelRect region;
    int fullWidth = 0, fullHeight = 0;
    /// Only with RenderOptions::nextTile: the tiles this call rendered, in increasing order,
    /// and for a filter wider than the box their films (same order), whose sums over all the
    /// processes' tiles give the colour (resolveTileFilms); `color` then stays black. With the
    /// box filter the images hold this call's tiles and zeros elsewhere.
    std::vector<int> tiles;
    std::vector<TileFilm> films;
};

/// The colour of `region` from the films of every tile regionTiles() lists for it, given in
/// increasing tile order: the same sums, in the same order, as render() makes.
void resolveTileFilms(const std::vector<const TileFilm*>& films, const PixelRect& region,
                      Image& color);

/// The default relative tolerance for an image of `height` rows and vertical field of view
/// `fovDegrees`: a fraction of the angle one pixel spans (see docs/accuracy.md).
double defaultTolerance(int height, double fovDegrees);

/// Adaptive sampling takes at least this many samples of a pixel (or all, if fewer) before it
/// trusts the estimate of the noise.
constexpr int kMinAdaptiveSamples = 16;

RenderResult render(const Scene& scene, const RenderOptions& options);

}  // namespace kerf
