/// @file accuracy/measure.h
/// @brief One cell of the speed-against-error report: the primary rays of a camera traced by
/// one method at one tolerance, timed, and compared with the extended-precision reference.
#pragma once

#include <vector>

#include "csg/bvh/scene_geometry.h"
#include "csg/primitives/reference.h"
#include "csg/trace_context.h"
#include "render/camera.h"

namespace kerf {

/// The pixel-centre rays of a width × height image, row by row from the top.
std::vector<Ray> primaryRays(const Camera& camera, int width, int height);

/// The reference first hit of every ray (csg/primitives/reference.h), computed once per scene and
/// shared by every measurement of it. Computed in parallel (it is deterministic per ray).
struct ReferenceImage {
    std::vector<ReferenceHit> hits;  ///< one per ray, in the order of the rays
    double seconds = 0;              ///< wall time spent computing it
};
ReferenceImage computeReference(const SceneGeometry& geometry, const std::vector<Ray>& rays);

/// What one method at one tolerance did on the rays of a scene.
struct AccuracyMeasurement {
    int rays = 0;
    int runs = 0;              ///< timed runs; the time is their median
    double medianSeconds = 0;  ///< one single-threaded pass over every ray
    double nsPerRay = 0;
    double raysPerSecond = 0;
    double rootStepsPerRay = 0;  ///< TraceStats::rootSteps / rays
    int bothHit = 0;             ///< rays where the trace and a certain reference both hit
    /// |t − t_ref| / t_ref over the bothHit rays (0 when there are none).
    double maxRelError = 0;
    double meanRelError = 0;
    double p99RelError = 0;            ///< the 99th percentile (nearest rank)
    double maxNormalErrorDegrees = 0;  ///< angle between the normals, over the bothHit rays
    /// bothHit rays whose error exceeds the requested tolerance: a span thinner than the
    /// tolerance that vanished (allowed) and the ray went on to a farther surface, or a broken
    /// bound (not allowed): overToleranceNotThin counts the latter.
    int overTolerance = 0;
    int hitMissMismatches = 0;  ///< hit in one and miss in the other, certain rays only
    /// Of overTolerance and hitMissMismatches, the rays NOT explained by the tolerance
    /// contract: explained are rays whose reference surfaces in front of the traced hit (or
    /// all of them, for a traced miss) bound only spans thinner than 3·tolerance·t (the
    /// vanishing threshold plus the allowed error at both ends). These break the contract.
    int overToleranceNotThin = 0;
    int mismatchesNotThin = 0;
    int uncertainRays = 0;  ///< rays whose reference is Uncertain: left out of the above
};

/// Traces every ray with SceneGeometry::nearestHit(ray, 0, ∞) under
/// TraceContext{relTolerance, method} `runs` times on the calling thread, and compares the
/// hits of the last run with `reference` (same order as `rays`).
AccuracyMeasurement measureAccuracy(const SceneGeometry& geometry, const std::vector<Ray>& rays,
                                    const ReferenceImage& reference, TraceMethod method,
                                    double relTolerance, int runs);

}  // namespace kerf
