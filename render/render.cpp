/// @file render/render.cpp
/// @brief The render loop: tiles in parallel, per-pixel samples, film and auxiliary outputs.
#include "render/render.h"

#include "csg/bvh/scene_geometry.h"
#include "csg/tree/motion.h"
#include "render/camera.h"
#include "render/film.h"
#include "render/integrator.h"
#include "render/medium_bake.h"
#include "render/sampler.h"
#include "render/section_cut.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <stdexcept>
#include <string>

namespace kerf {
namespace {

using Clock = std::chrono::steady_clock;

/// Progress is reported at most this often (about 20 times a second).
constexpr auto kProgressInterval = std::chrono::milliseconds(50);

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

/// Everything a tile needs, shared by all threads (only `result` is written, each pixel by
/// exactly one thread).
struct FrameJob {
    const Camera& camera;
    const PixelSampler& sampler;
    const SceneGeometry& geometry;
    const Integrator& integrator;
    const PrimaryBeams* beams;  ///< null when camera rays start at the eye
    RenderResult& result;       ///< images of the region's size
    int width, height;          ///< the full image
    PixelRect region;           ///< the pixels kept
    PixelRect traced;  ///< the region and the pixels whose samples the filter spreads into it
    bool wantDepth;
    bool wantNormal;
    ReconstructionFilter filter;       ///< box: each pixel averages its own samples
    double noise;                      ///< adaptive sampling's target standard error; 0: off
    std::vector<TileFilm>* films;      ///< one per tile, for filters wider than the box
    double shutterOpen, shutterClose;  ///< scene times; equal: one instant, no motion blur
};

/// Rec. 709 luminance: the quantity whose noise adaptive sampling watches.
double luminance(const Vec3& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

/// Runs f with the scene's clock (csg/tree/motion.h) at `time`: the one place the render
/// loop sets the motion-blur time.
template <class F>
auto atSceneTime(double time, F&& f) {
    const SceneTimeScope clock(time);
    return f();
}

/// The scene time sample s of the pixel sees: its own point in the shutter interval.
double sampleTime(const FrameJob& job, uint64_t pixel, int s) {
    if (!(job.shutterClose > job.shutterOpen)) return job.shutterOpen;
    return job.shutterOpen +
           job.sampler.get2D(pixel, s, sample_dim::kTime).x * (job.shutterClose - job.shutterOpen);
}

/// Adaptive sampling's running estimate of a pixel's noise.
struct NoiseEstimate {
    double lumSum = 0.0, lumSum2 = 0.0;

    /// Adds sample c (the taken-th) and tells whether the mean's standard error is below the
    /// target (the sample variance over-estimates it for stratified samples: the rule errs
    /// toward more samples).
    bool addAndConverged(const Vec3& c, int taken, int count, double target) {
        const double l = luminance(c);
        lumSum += l;
        lumSum2 += l * l;
        if (taken < std::min(kMinAdaptiveSamples, count) || taken < 2) return false;
        const double variance = std::max(0.0, (lumSum2 - lumSum * lumSum / taken) / (taken - 1));
        return std::sqrt(variance / taken) < target;
    }
};

/// The depth and normal outputs of pixel (i, j) at (oi, oj) of the images, from the
/// centre ray's hit (traced here unless the camera sample already gave it).
void writeAovs(const FrameJob& job, int i, int j, double tStart, bool centreServes,
               std::optional<Hit> centreHit, ShadingContext& ctx) {
    RenderResult& out = job.result;
    const int oi = i - job.region.x0, oj = j - job.region.y0;
    const Ray centreRay = job.camera.rayThrough(i + 0.5, j + 0.5);
    if (!centreServes) {
        ++ctx.rays.camera;
        // The AOVs show the shutter's opening.
        centreHit = atSceneTime(job.shutterOpen, [&] {
            return job.geometry.nearestHit(centreRay, tStart, kInf, ctx.trace);
        });
    }
    if (job.wantDepth)
        out.depth.at(oi, oj, 0) =
            centreHit ? float(glm::length(centreRay.dir) * centreHit->t) : float(kInf);
    if (job.wantNormal && centreHit)
        for (int k = 0; k < 3; ++k) out.normal.at(oi, oj, k) = float(centreHit->normal[k]);
}

/// tStart: where the pixel's camera rays may start (render/primary_beams.h).
void renderPixel(const FrameJob& job, int i, int j, double tStart, ShadingContext& ctx,
                 TileFilm* film, uint64_t& samplesTaken) {
    // Seeds follow the pixel's place in the full image, so a region sees the same samples.
    const uint64_t pixel = uint64_t(j) * uint64_t(job.width) + uint64_t(i);
    const bool wantAov = job.wantDepth || job.wantNormal;
    const int count = job.sampler.sampleCount();

    // With one sample through a pinhole the camera ray is the pixel-centre ray, and its hit
    // serves the AOVs; otherwise they come from that ray traced once more.
    const Ray centreRay = job.camera.rayThrough(i + 0.5, j + 0.5);
    const bool lens = job.camera.hasLens();
    const bool centreServes = count == 1 && !lens;
    std::optional<Hit> centreHit;
    Vec3 sum(0.0);
    int taken = 0;
    NoiseEstimate noise;
    ctx.sampler = &job.sampler;
    ctx.pixel = pixel;
    // Each of n samples stands for 1/n of the pixel: a square about 1/√n of its side.
    ctx.sampleAngle = job.camera.pixelAngle() / std::sqrt(double(count));
    for (int k = 0; k < count; ++k) {
        // Adaptive sampling may stop after any k samples: it takes them in an order whose every
        // prefix covers the pixel (render/sampler.h); otherwise in index order.
        const int s = job.noise > 0.0 ? int(job.sampler.spreadOrder()[size_t(k)]) : k;
        ctx.sample = s;
        Ray ray = centreRay;
        SubPixel at;  // the film position within the pixel
        if (!centreServes) {
            at = job.sampler.position(pixel, s);
            const SubPixel lensAt =
                lens ? job.sampler.get2D(pixel, s, sample_dim::kLens) : SubPixel{};
            ray = job.camera.rayThrough(i + at.x, j + at.y, lensAt.x, lensAt.y);
        }
        const Vec3 c = atSceneTime(sampleTime(job, pixel, s), [&] {
            return job.integrator.traceCamera(
                ray, ctx, centreServes && wantAov ? &centreHit : nullptr, tStart);
        });
        if (film) film->add(i + at.x, j + at.y, c, job.filter);
        sum += c;
        ++taken;
        if (job.noise > 0.0 && noise.addAndConverged(c, taken, count, job.noise)) break;
    }
    samplesTaken += uint64_t(taken);
    if (!job.region.contains(i, j)) return;  // traced only for its filtered samples
    if (!film) {
        const Vec3 c = sum / double(taken);
        const int oi = i - job.region.x0, oj = j - job.region.y0;
        for (int k = 0; k < 3; ++k) job.result.color.at(oi, oj, k) = float(c[k]);
    }
    if (wantAov) writeAovs(job, i, j, tStart, centreServes, centreHit, ctx);
}

void renderTile(const FrameJob& job, int tile, ShadingContext& ctx, BeamStats& beamStats,
                uint64_t& samplesTaken) {
    const PixelRect t = tileRect(tile, job.width, job.height);
    const int x0 = t.x0, y0 = t.y0, x1 = t.x1, y1 = t.y1;
    // Beams over the whole tile even when part of it is traced: the same start distances.
    double starts[kTileSize * kTileSize];
    std::fill(starts, starts + kTileSize * kTileSize, 0.0);
    if (job.beams) job.beams->tileStarts(x0, y0, x1, y1, starts, beamStats);
    TileFilm* film = nullptr;
    if (job.films) {
        (*job.films)[size_t(tile)] = TileFilm(x0, y0, x1, y1, int(std::ceil(job.filter.radius)));
        film = &(*job.films)[size_t(tile)];
    }
    const PixelRect part = intersect(t, job.traced);
    for (int j = part.y0; j < part.y1; ++j)
        for (int i = part.x0; i < part.x1; ++i)
            renderPixel(job, i, j, starts[(j - y0) * (x1 - x0) + (i - x0)], ctx, film,
                        samplesTaken);
}

/// Calls the user's progress callback from the tile loop: rarely, and from one thread at a
/// time (a thread that finds another one reporting simply skips its turn).
class ProgressReporter {
public:
    ProgressReporter(const std::function<void(double)>& callback, int total)
        : mCallback(callback), mTotal(total), mLast(Clock::now()) {}

    void tileDone() {
        ++mDone;
        if (!mCallback || !mMutex.try_lock()) return;
        std::lock_guard<std::mutex> lock(mMutex, std::adopt_lock);
        const auto now = Clock::now();
        if (now - mLast < kProgressInterval) return;
        mLast = now;
        // Read under the lock, so the reported fractions never go backwards.
        mCallback(double(mDone.load()) / mTotal);
    }
    void finished() {
        if (mCallback) mCallback(1.0);
    }

private:
    const std::function<void(double)>& mCallback;
    const int mTotal;
    std::atomic<int> mDone{0};
    std::mutex mMutex;
    Clock::time_point mLast;  ///< guarded by mMutex
};

/// The image size, samples and region a render traces, from the options over the scene's
/// settings; a bad size or region is an error.
struct FrameSize {
    int width = 0, height = 0, spp = 0;
    PixelRect full, region;
};

FrameSize resolveFrameSize(const Scene& scene, const RenderOptions& options) {
    FrameSize f;
    f.width = options.width > 0 ? options.width : scene.settings.width;
    f.height = options.height > 0 ? options.height : scene.settings.height;
    f.spp = options.spp > 0 ? options.spp : scene.settings.spp;
    if (f.width <= 0 || f.height <= 0)
        throw std::invalid_argument("render: image size must be positive, got " +
                                    std::to_string(f.width) + "x" + std::to_string(f.height));
    f.full = PixelRect{0, 0, f.width, f.height};
    f.region = options.region.value_or(f.full);
    if (f.region.empty() || !(intersect(f.region, f.full) == f.region))
        throw std::invalid_argument("render: the region must be a non-empty part of the " +
                                    std::to_string(f.width) + "x" + std::to_string(f.height) +
                                    " image");
    return f;
}

/// The scene the render sees: the input, or its section-cut copy (kept in `cut`) and its copy
/// with the mist baked (kept in `baked`), so every consumer below (acceleration, shadows,
/// beams, integrator) sees the cut, baked model. Preparation of the scene's data for rendering
/// belongs here.
const Scene& prepareScene(const Scene& input, std::optional<Scene>& cut,
                          std::optional<Scene>& baked) {
    const Scene& sectioned = input.sections.empty() ? input : cut.emplace(cutBySections(input));
    // A mist's `bake N` is made here, not while compiling (render/medium_bake.h).
    return sectioned.medium.bake ? baked.emplace(withBakedMedium(sectioned)) : sectioned;
}

/// The octree's options for a render of `height` rows (volume/octree/accelerate.h).
OctreeOptions octreeOptionsFor(const Scene& scene, const RenderOptions& options, int height) {
    OctreeOptions o;
    o.depth = options.accelDepth;
    o.eye = scene.camera.eye;
    o.footprintPerDistance =
        2.0 * std::tan(0.5 * scene.camera.fovDegrees * glm::pi<double>() / 180.0) / height;
    return o;
}

/// The accelerated objects, and, when some are marked no_shadow, a second geometry of the
/// casters that shadow rays use.
struct RenderGeometry {
    std::optional<SceneGeometry> all;
    std::optional<SceneGeometry> casters;
    const SceneGeometry* shadowGeometry() const { return casters ? &*casters : nullptr; }
};

void buildGeometry(const Scene& scene, const RenderOptions& options,
                   const OctreeOptions& octreeOptions, tbb::task_arena& arena, RenderResult& result,
                   RenderGeometry& out) {
    const auto accelStart = Clock::now();
    AcceleratedObjects accelerated;
    arena.execute([&] { accelerated = accelerate(scene.objects, options.accel, octreeOptions); });
    result.stats.secondsAccel = secondsSince(accelStart);
    std::vector<NodePtr> casters;
    for (size_t k = 0; k < accelerated.objects.size(); ++k)
        if (k >= scene.objectFlags.size() || scene.objectFlags[k].castsShadow)
            casters.push_back(accelerated.objects[k]);
    if (casters.size() != accelerated.objects.size())
        out.casters.emplace(std::move(casters), accelerated.objectBvh);
    out.all.emplace(std::move(accelerated.objects), accelerated.objectBvh);
}

/// What each thread keeps while tracing tiles.
struct ThreadState {
    ShadingContext ctx;
    BeamStats beams;
    uint64_t samples = 0;
    std::vector<int> taken;  ///< tiles taken from RenderOptions::nextTile
};

/// Traces `tiles` on the arena: each tile once, or, with options.nextTile, the tiles the
/// shared counter hands out.
void traceTiles(const FrameJob& job, const std::vector<int>& tiles, const RenderOptions& options,
                tbb::task_arena& arena, tbb::enumerable_thread_specific<ThreadState>& threads) {
    ProgressReporter progress(options.progress, int(tiles.size()));
    std::mutex counterMutex;
    if (options.nextTile)
        arena.execute([&] {
            tbb::parallel_for(
                tbb::blocked_range<int>(0, arena.max_concurrency(), 1),
                [&](const tbb::blocked_range<int>&) {
                    ThreadState& t = threads.local();
                    for (;;) {
                        int n;
                        {
                            std::lock_guard<std::mutex> lock(counterMutex);
                            n = options.nextTile();
                        }
                        if (n < 0 || size_t(n) >= tiles.size()) break;
                        renderTile(job, tiles[size_t(n)], t.ctx, t.beams, t.samples);
                        t.taken.push_back(tiles[size_t(n)]);
                        progress.tileDone();
                    }
                },
                tbb::simple_partitioner());
        });
    else
        arena.execute([&] {
            // One tile per task: tiles are already coarse, and the simple partitioner keeps the
            // split independent of timing (the image never depends on it, the load balance does).
            tbb::parallel_for(
                tbb::blocked_range<int>(0, int(tiles.size()), 1),
                [&](const tbb::blocked_range<int>& range) {
                    ThreadState& t = threads.local();
                    for (int k = range.begin(); k != range.end(); ++k) {
                        renderTile(job, tiles[size_t(k)], t.ctx, t.beams, t.samples);
                        progress.tileDone();
                    }
                },
                tbb::simple_partitioner());
        });
    progress.finished();
}

/// Sums the threads' counters into the stats, and hands over the tiles and films
/// (nextTile) or resolves the films into the colour image.
void gatherResults(tbb::enumerable_thread_specific<ThreadState>& threads,
                   const std::vector<int>& tiles, const RenderOptions& options,
                   const PixelRect& region, std::vector<TileFilm>& films, RenderResult& result) {
    for (const ThreadState& t : threads) {
        result.stats.cameraRays += t.ctx.rays.camera;
        result.stats.shadowRays += t.ctx.rays.shadow;
        result.stats.reflectionRays += t.ctx.rays.reflection;
        result.stats.refractionRays += t.ctx.rays.refraction;
        result.stats.trace += t.ctx.trace.stats;
        result.stats.beams += t.beams;
        result.stats.samplesTaken += t.samples;
    }
    if (options.nextTile) {
        // The driver gathers the tiles: hand them over in increasing order.
        for (const ThreadState& t : threads)
            result.tiles.insert(result.tiles.end(), t.taken.begin(), t.taken.end());
        std::sort(result.tiles.begin(), result.tiles.end());
        if (!films.empty())
            for (int tile : result.tiles) result.films.push_back(std::move(films[size_t(tile)]));
    } else if (!films.empty()) {
        std::vector<const TileFilm*> inOrder;
        for (int tile : tiles) inOrder.push_back(&films[size_t(tile)]);
        resolveTileFilms(inOrder, region, result.color);
    }
}

/// The result's images and region for a frame (colour always; depth and normal if asked).
void allocateImages(const FrameSize& f, const RenderOptions& options, RenderResult& result) {
    result.region = f.region;
    result.fullWidth = f.width;
    result.fullHeight = f.height;
    result.color = Image(f.region.width(), f.region.height(), 3);
    if (options.wantDepth) result.depth = Image(f.region.width(), f.region.height(), 1);
    if (options.wantNormal) result.normal = Image(f.region.width(), f.region.height(), 3);
}

}  // namespace

/// An eighth of the angle one pixel spans: the image plane at distance 1 is 2·tan(fov/2)
/// high, so one pixel spans 2·tan(fov/2)/height there. A hit distance within this relative
/// tolerance moves the hit along its ray by under an eighth of the pixel footprint at that
/// distance, so on screen it lies within 1/8 pixel of its true position.
double defaultTolerance(int height, double fovDegrees) {
    const double halfFov = 0.5 * fovDegrees * glm::pi<double>() / 180.0;
    return 0.125 * (2.0 * std::tan(halfFov) / std::max(height, 1));
}

RenderResult render(const Scene& input, const RenderOptions& options) {
    const auto setupStart = Clock::now();
    std::optional<Scene> cutScene, bakedScene;
    const Scene& scene = prepareScene(input, cutScene, bakedScene);
    const FrameSize f = resolveFrameSize(scene, options);
    RenderResult result;
    allocateImages(f, options, result);
    result.stats.tolerance = options.tolerance > 0
                                 ? options.tolerance
                                 : defaultTolerance(f.height, scene.camera.fovDegrees);

    const Camera camera(scene.camera, f.width, f.height);
    tbb::task_arena arena(options.threads > 0 ? options.threads : int(tbb::task_arena::automatic));
    const OctreeOptions octreeOptions = octreeOptionsFor(scene, options, f.height);
    RenderGeometry geometry;
    buildGeometry(scene, options, octreeOptions, arena, result, geometry);
    const PixelSampler sampler(f.spp, options.sampler.value_or(scene.settings.sampler));
    result.stats.samplesPerPixel = sampler.sampleCount();
    result.stats.sampler = sampler.kind();
    const IntegratorInputs inputs{scene, *geometry.all, geometry.shadowGeometry()};
    const std::unique_ptr<Integrator> integrator =
        options.integrator ? options.integrator(inputs) : makeIntegrator(inputs);
    if (!integrator) throw std::invalid_argument("render: the integrator factory gave none");
    const PrimaryBeams beams(camera, scene.objects);
    // Beams bound rays from the eye: a lens (issue 10) would start them elsewhere.
    const bool useBeams =
        beams.enabled() && scene.camera.aperture == 0.0 &&
        (options.beams == BeamMode::On ||
         (options.beams == BeamMode::Auto && beamsPay(scene.objects, octreeOptions)));
    result.stats.beamsUsed = useBeams;
    const FilterKind filterKind = options.filter.value_or(scene.settings.filter);
    const int tileCount =
        ((f.width + kTileSize - 1) / kTileSize) * ((f.height + kTileSize - 1) / kTileSize);
    const int margin = filterMargin(filterKind);
    const std::vector<int> tiles = regionTiles(f.width, f.height, f.region, margin);
    std::vector<TileFilm> films;
    if (filterKind != FilterKind::Box) films.resize(size_t(tileCount));
    const PixelRect traced = intersect(
        {f.region.x0 - margin, f.region.y0 - margin, f.region.x1 + margin, f.region.y1 + margin},
        f.full);
    const FrameJob job{camera,
                       sampler,
                       *geometry.all,
                       *integrator,
                       useBeams ? &beams : nullptr,
                       result,
                       f.width,
                       f.height,
                       f.region,
                       traced,
                       options.wantDepth,
                       options.wantNormal,
                       ReconstructionFilter::of(filterKind),
                       options.noise >= 0.0 ? options.noise : scene.settings.noise,
                       films.empty() ? nullptr : &films,
                       scene.camera.shutterOpen,
                       scene.camera.shutterClose};
    result.stats.filter = filterKind;
    result.stats.secondsSetup = secondsSince(setupStart);

    const auto traceStart = Clock::now();
    const double tolerance = result.stats.tolerance;
    const TraceMethod method = options.method;
    tbb::enumerable_thread_specific<ThreadState> threads([tolerance, method] {
        ThreadState t;
        t.ctx.trace.relTolerance = tolerance;
        t.ctx.trace.method = method;
        return t;
    });
    traceTiles(job, tiles, options, arena, threads);
    gatherResults(threads, tiles, options, f.region, films, result);
    result.stats.secondsTrace = secondsSince(traceStart);
    result.stats.octree = octreeStats(geometry.all->objects());
    return result;
}

}  // namespace kerf
