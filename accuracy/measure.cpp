/// @file accuracy/measure.cpp
/// @brief Timing a method over a scene's primary rays and measuring its error.
#include "accuracy/measure.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <optional>
#include <stdexcept>

namespace kerf {
namespace {

using Clock = std::chrono::steady_clock;

/// The angle between two unit vectors in degrees; atan2 keeps small angles accurate where
/// acos(dot) would round them to 0 below about 1e-8 rad.
double angleDegrees(const Vec3& a, const Vec3& b) {
    const double s = glm::length(glm::cross(a, b));
    const double c = glm::dot(a, b);
    return std::atan2(s, c) * 180.0 / glm::pi<double>();
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

/// Fills `hits` from one pass over the rays; returns the seconds it took.
double tracePass(const SceneGeometry& geometry, const std::vector<Ray>& rays, TraceContext& ctx,
                 std::vector<std::optional<Hit>>& hits) {
    const auto start = Clock::now();
    for (size_t i = 0; i < rays.size(); ++i) hits[i] = geometry.nearestHit(rays[i], 0.0, kInf, ctx);
    return std::chrono::duration<double>(Clock::now() - start).count();
}

/// The reference crossing after t (just past t's own long-double precision).
ReferenceHit referenceAfter(const SceneGeometry& geometry, const Ray& ray, long double t) {
    return referenceNearestHit(geometry, ray, double(t + 1e-12L * std::fabs(t)));
}

/// Whether a traced hit at `traced` (nullopt: a miss) differs from the reference's first
/// crossing at `first` only by spans the tolerance lets vanish: walks the reference
/// crossings in pairs (entry, exit) up to the traced hit and requires each span to be
/// thinner than 3·E·t. A traced hit in front of the reference, or on no reference surface,
/// is never explained.
bool explainedByThinSpans(const SceneGeometry& geometry, const Ray& ray, long double first,
                          const std::optional<Hit>& traced, double relTolerance) {
    constexpr int kMaxSpans = 32;
    const long double slack = 3.0L * relTolerance;
    long double entry = first;
    for (int k = 0; k < kMaxSpans; ++k) {
        if (traced && std::fabs((long double)traced->t - entry) <= slack * std::fabs(entry))
            return true;  // the trace is on this reference surface
        if (traced && (long double)traced->t < entry) return false;
        const ReferenceHit exit = referenceAfter(geometry, ray, entry);
        if (exit.kind != ReferenceHit::Kind::Hit) return false;
        if (exit.t - entry > slack * std::fabs(exit.t)) return false;  // a real span vanished
        const ReferenceHit next = referenceAfter(geometry, ray, exit.t);
        if (next.kind == ReferenceHit::Kind::Miss) return !traced;
        if (next.kind != ReferenceHit::Kind::Hit) return false;
        entry = next.t;
    }
    return false;
}

/// Fills the error fields of `m` from the traced hits against the reference.
void compareWithReference(const SceneGeometry& geometry, const std::vector<Ray>& rays,
                          const std::vector<std::optional<Hit>>& hits,
                          const ReferenceImage& reference, double relTolerance,
                          AccuracyMeasurement& m) {
    std::vector<double> relErrors;
    relErrors.reserve(hits.size());
    long double sum = 0;
    for (size_t i = 0; i < hits.size(); ++i) {
        const ReferenceHit& ref = reference.hits[i];
        if (ref.kind == ReferenceHit::Kind::Uncertain) {
            ++m.uncertainRays;
            continue;
        }
        const bool refHit = ref.kind == ReferenceHit::Kind::Hit;
        if (refHit != hits[i].has_value()) {
            ++m.hitMissMismatches;
            if (!refHit || !explainedByThinSpans(geometry, rays[i], ref.t, hits[i], relTolerance))
                ++m.mismatchesNotThin;
            continue;
        }
        if (!refHit) continue;
        // In long double, so the difference of two nearby distances is not rounded away.
        const long double diff = std::fabs((long double)hits[i]->t - ref.t);
        const double rel = double(diff / std::fabs(ref.t));
        relErrors.push_back(rel);
        sum += rel;
        if (rel > relTolerance) {
            ++m.overTolerance;
            if (!explainedByThinSpans(geometry, rays[i], ref.t, hits[i], relTolerance))
                ++m.overToleranceNotThin;
        }
        m.maxRelError = std::max(m.maxRelError, rel);
        m.maxNormalErrorDegrees =
            std::max(m.maxNormalErrorDegrees, angleDegrees(hits[i]->normal, ref.normal));
    }
    m.bothHit = int(relErrors.size());
    if (relErrors.empty()) return;
    m.meanRelError = double(sum / relErrors.size());
    // Nearest rank: the smallest error that at least 99 % of the rays do not exceed.
    const size_t rank = size_t(std::ceil(0.99 * relErrors.size())) - 1;
    std::nth_element(relErrors.begin(), relErrors.begin() + rank, relErrors.end());
    m.p99RelError = relErrors[rank];
}

}  // namespace

std::vector<Ray> primaryRays(const Camera& camera, int width, int height) {
    std::vector<Ray> rays;
    rays.reserve(size_t(width) * height);
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) rays.push_back(camera.rayThrough(i + 0.5, j + 0.5));
    return rays;
}

ReferenceImage computeReference(const SceneGeometry& geometry, const std::vector<Ray>& rays) {
    ReferenceImage reference;
    reference.hits.resize(rays.size());
    const auto start = Clock::now();
    tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 64),
                      [&](const tbb::blocked_range<size_t>& range) {
                          for (size_t i = range.begin(); i != range.end(); ++i)
                              reference.hits[i] = referenceNearestHit(geometry, rays[i]);
                      });
    reference.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return reference;
}

AccuracyMeasurement measureAccuracy(const SceneGeometry& geometry, const std::vector<Ray>& rays,
                                    const ReferenceImage& reference, TraceMethod method,
                                    double relTolerance, int runs) {
    if (reference.hits.size() != rays.size())
        throw std::invalid_argument("measureAccuracy: the reference does not match the rays");
    if (runs < 1) throw std::invalid_argument("measureAccuracy: runs must be at least 1");
    AccuracyMeasurement m;
    m.rays = int(rays.size());
    m.runs = runs;
    std::vector<std::optional<Hit>> hits(rays.size());
    std::vector<double> seconds;
    TraceStats stats;
    for (int run = 0; run < runs; ++run) {
        TraceContext ctx;
        ctx.relTolerance = relTolerance;
        ctx.method = method;
        seconds.push_back(tracePass(geometry, rays, ctx, hits));
        stats = ctx.stats;  // every run counts the same; keep one
    }
    m.medianSeconds = median(seconds);
    if (!rays.empty()) {
        m.nsPerRay = 1e9 * m.medianSeconds / double(rays.size());
        m.rootStepsPerRay = double(stats.rootSteps) / double(rays.size());
    }
    m.raysPerSecond = m.medianSeconds > 0 ? double(rays.size()) / m.medianSeconds : 0.0;
    compareWithReference(geometry, rays, hits, reference, relTolerance, m);
    return m;
}

}  // namespace kerf
