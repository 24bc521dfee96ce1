/// @file render/render.cpp
/// @brief The render loop: tiles in parallel, per-pixel samples, film and auxiliary outputs.
#include "render/render.h"

#include "csg/bvh/scene_geometry.h"
#include "csg/tree/motion.h"
#include "render/camera.h"
#include "render/film.h"
#include "render/medium_bake.h"
#include "render/sampler.h"
#include "render/section_cut.h"
#include "render/shading.h"

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
    const WhittedIntegrator& integrator;
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

/// tStart: where the pixel's camera rays may start (render/primary_beams.h).
void renderPixel(const FrameJob& job, int i, int j, double tStart, ShadingContext& ctx,
                 TileFilm* film, uint64_t& samplesTaken) {
    RenderResult& out = job.result;
    // Seeds follow the pixel's place in the full image, so a region sees the same samples.
    const uint64_t pixel = uint64_t(j) * uint64_t(job.width) + uint64_t(i);
    const bool kept = job.region.contains(i, j);  // else traced only for its filtered samples
    const int oi = i - job.region.x0, oj = j - job.region.y0;
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
    double lumSum = 0.0, lumSum2 = 0.0;
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
        // Each sample sees the scene at its own time in the shutter interval.
        const double time =
            job.shutterClose > job.shutterOpen
                ? job.shutterOpen + job.sampler.get2D(pixel, s, sample_dim::kTime).x *
                                        (job.shutterClose - job.shutterOpen)
                : job.shutterOpen;
        const SceneTimeScope clock(time);
        const Vec3 c = job.integrator.traceCamera(
            ray, ctx, centreServes && wantAov ? &centreHit : nullptr, tStart);
        if (film) film->add(i + at.x, j + at.y, c, job.filter);
        sum += c;
        ++taken;
        if (job.noise > 0.0) {
            // Stop once the mean's standard error is below the target (the sample variance
            // over-estimates it for stratified samples: the rule errs toward more samples).
            const double l = luminance(c);
            lumSum += l;
            lumSum2 += l * l;
            if (taken >= std::min(kMinAdaptiveSamples, count) && taken >= 2) {
                const double variance =
                    std::max(0.0, (lumSum2 - lumSum * lumSum / taken) / (taken - 1));
                if (std::sqrt(variance / taken) < job.noise) break;
            }
        }
    }
    samplesTaken += uint64_t(taken);
    if (!kept) return;
    if (!film) {
        const Vec3 c = sum / double(taken);
        for (int k = 0; k < 3; ++k) out.color.at(oi, oj, k) = float(c[k]);
    }

    if (!wantAov) return;
    if (!centreServes) {
        const SceneTimeScope clock(job.shutterOpen);  // the AOVs show the shutter's opening
        ++ctx.rays.camera;
        centreHit = job.geometry.nearestHit(centreRay, tStart, kInf, ctx.trace);
    }
    if (job.wantDepth)
        out.depth.at(oi, oj, 0) =
            centreHit ? float(glm::length(centreRay.dir) * centreHit->t) : float(kInf);
    if (job.wantNormal && centreHit)
        for (int k = 0; k < 3; ++k) out.normal.at(oi, oj, k) = float(centreHit->normal[k]);
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
    // Section views: every consumer below (acceleration, shadows, beams) sees the cut model.
    std::optional<Scene> cutScene;
    const Scene& cut = input.sections.empty() ? input : cutScene.emplace(cutBySections(input));
    std::optional<Scene> bakedScene;  // a mist's `bake N` is made here (render/medium_bake.h)
    const Scene& scene = cut.medium.bake ? bakedScene.emplace(withBakedMedium(cut)) : cut;
    const int width = options.width > 0 ? options.width : scene.settings.width;
    const int height = options.height > 0 ? options.height : scene.settings.height;
    const int spp = options.spp > 0 ? options.spp : scene.settings.spp;
    if (width <= 0 || height <= 0)
        throw std::invalid_argument("render: image size must be positive, got " +
                                    std::to_string(width) + "x" + std::to_string(height));

    const PixelRect full{0, 0, width, height};
    const PixelRect region = options.region.value_or(full);
    if (region.empty() || !(intersect(region, full) == region))
        throw std::invalid_argument("render: the region must be a non-empty part of the " +
                                    std::to_string(width) + "x" + std::to_string(height) +
                                    " image");

    RenderResult result;
    result.region = region;
    result.fullWidth = width;
    result.fullHeight = height;
    result.stats.tolerance = options.tolerance > 0
                                 ? options.tolerance
                                 : defaultTolerance(height, scene.camera.fovDegrees);
    result.color = Image(region.width(), region.height(), 3);
    if (options.wantDepth) result.depth = Image(region.width(), region.height(), 1);
    if (options.wantNormal) result.normal = Image(region.width(), region.height(), 3);

    const Camera camera(scene.camera, width, height);
    tbb::task_arena arena(options.threads > 0 ? options.threads : int(tbb::task_arena::automatic));
    const auto accelStart = Clock::now();
    OctreeOptions octreeOptions;
    octreeOptions.depth = options.accelDepth;
    octreeOptions.eye = scene.camera.eye;
    octreeOptions.footprintPerDistance =
        2.0 * std::tan(0.5 * scene.camera.fovDegrees * glm::pi<double>() / 180.0) / height;
    AcceleratedObjects accelerated;
    arena.execute([&] { accelerated = accelerate(scene.objects, options.accel, octreeOptions); });
    result.stats.secondsAccel = secondsSince(accelStart);
    // Objects marked no_shadow are left out of a second geometry that shadow rays use.
    std::optional<SceneGeometry> shadowGeometry;
    {
        std::vector<NodePtr> casters;
        for (size_t k = 0; k < accelerated.objects.size(); ++k)
            if (k >= scene.objectFlags.size() || scene.objectFlags[k].castsShadow)
                casters.push_back(accelerated.objects[k]);
        if (casters.size() != accelerated.objects.size())
            shadowGeometry.emplace(std::move(casters), accelerated.objectBvh);
    }
    const SceneGeometry geometry(std::move(accelerated.objects), accelerated.objectBvh);
    const PixelSampler sampler(spp, options.sampler.value_or(scene.settings.sampler));
    result.stats.samplesPerPixel = sampler.sampleCount();
    result.stats.sampler = sampler.kind();
    const WhittedIntegrator integrator(scene, geometry, scene.settings.maxDepth,
                                       shadowGeometry ? &*shadowGeometry : nullptr);
    const PrimaryBeams beams(camera, scene.objects);
    // Beams bound rays from the eye: a lens (issue 10) would start them elsewhere.
    const bool useBeams =
        beams.enabled() && scene.camera.aperture == 0.0 &&
        (options.beams == BeamMode::On ||
         (options.beams == BeamMode::Auto && beamsPay(scene.objects, octreeOptions)));
    result.stats.beamsUsed = useBeams;
    const FilterKind filterKind = options.filter.value_or(scene.settings.filter);
    const int tileCount =
        ((width + kTileSize - 1) / kTileSize) * ((height + kTileSize - 1) / kTileSize);
    const int margin = filterMargin(filterKind);
    const std::vector<int> tiles = regionTiles(width, height, region, margin);
    std::vector<TileFilm> films;
    if (filterKind != FilterKind::Box) films.resize(size_t(tileCount));
    const PixelRect traced = intersect(
        {region.x0 - margin, region.y0 - margin, region.x1 + margin, region.y1 + margin}, full);
    const FrameJob job{camera,
                       sampler,
                       geometry,
                       integrator,
                       useBeams ? &beams : nullptr,
                       result,
                       width,
                       height,
                       region,
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
    tbb::enumerable_thread_specific<BeamStats> beamStats;
    tbb::enumerable_thread_specific<uint64_t> samples(uint64_t(0));
    tbb::enumerable_thread_specific<ShadingContext> contexts([tolerance, method] {
        ShadingContext ctx;
        ctx.trace.relTolerance = tolerance;
        ctx.trace.method = method;
        return ctx;
    });
    ProgressReporter progress(options.progress, int(tiles.size()));
    // With a shared tile counter (app/mpi), each thread takes tiles until none is left.
    tbb::enumerable_thread_specific<std::vector<int>> taken;
    std::mutex counterMutex;
    if (options.nextTile)
        arena.execute([&] {
            tbb::parallel_for(
                tbb::blocked_range<int>(0, arena.max_concurrency(), 1),
                [&](const tbb::blocked_range<int>&) {
                    ShadingContext& ctx = contexts.local();
                    for (;;) {
                        int n;
                        {
                            std::lock_guard<std::mutex> lock(counterMutex);
                            n = options.nextTile();
                        }
                        if (n < 0 || size_t(n) >= tiles.size()) break;
                        renderTile(job, tiles[size_t(n)], ctx, beamStats.local(), samples.local());
                        taken.local().push_back(tiles[size_t(n)]);
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
                    ShadingContext& ctx = contexts.local();
                    BeamStats& beamCounts = beamStats.local();
                    uint64_t& samplesTaken = samples.local();
                    for (int k = range.begin(); k != range.end(); ++k) {
                        renderTile(job, tiles[size_t(k)], ctx, beamCounts, samplesTaken);
                        progress.tileDone();
                    }
                },
                tbb::simple_partitioner());
        });
    progress.finished();

    for (const ShadingContext& ctx : contexts) {
        result.stats.cameraRays += ctx.rays.camera;
        result.stats.shadowRays += ctx.rays.shadow;
        result.stats.reflectionRays += ctx.rays.reflection;
        result.stats.refractionRays += ctx.rays.refraction;
        result.stats.trace += ctx.trace.stats;
    }
    for (const BeamStats& b : beamStats) result.stats.beams += b;
    for (uint64_t n : samples) result.stats.samplesTaken += n;
    if (options.nextTile) {
        // The driver gathers the tiles: hand them over in increasing order.
        for (const std::vector<int>& t : taken)
            result.tiles.insert(result.tiles.end(), t.begin(), t.end());
        std::sort(result.tiles.begin(), result.tiles.end());
        if (!films.empty())
            for (int tile : result.tiles) result.films.push_back(std::move(films[size_t(tile)]));
    } else if (!films.empty()) {
        std::vector<const TileFilm*> inOrder;
        for (int tile : tiles) inOrder.push_back(&films[size_t(tile)]);
        resolveTileFilms(inOrder, region, result.color);
    }
    result.stats.secondsTrace = secondsSince(traceStart);
    result.stats.octree = octreeStats(geometry.objects());
    return result;
}

}  // namespace kerf
