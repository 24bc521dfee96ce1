/// @file accuracy/bench.cpp
/// @brief The benchmark loop: one reference per scene, then every method and tolerance.
#include "accuracy/bench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "render/render.h"

namespace kerf {
namespace {

std::string formatProgress(const AccuracyRow& row) {
    char line[200];
    std::snprintf(line, sizeof line, "  %-13s tol %-9.3g %9.1f ns/ray  max rel %.2e  mismatches %d",
                  traceMethodName(row.method), row.tolerance, row.m.nsPerRay,
                  std::isnan(row.m.maxRelError) ? std::fabs(row.m.maxRelError) : row.m.maxRelError,
                  row.m.hitMissMismatches);
    return line;
}

}  // namespace

AccuracyBenchResult runAccuracyBench(const std::vector<AccuracyScene>& scenes,
                                     const AccuracyBenchOptions& options) {
    if (options.width < 1 || options.height < 1 || options.runs < 1)
        throw std::invalid_argument("runAccuracyBench: width, height and runs must be positive");
    const auto say = [&](const std::string& text) {
        if (options.progress) options.progress(text);
    };
    AccuracyBenchResult result;
    for (const AccuracyScene& entry : scenes) {
        const int divisor = std::max(1, entry.spec.resolutionDivisor);
        const int width = std::max(1, options.width / divisor);
        const int height = std::max(1, options.height / divisor);
        const SceneGeometry geometry(entry.scene.objects);  // the reference's: plain objects
        OctreeOptions octree;
        octree.eye = entry.scene.camera.eye;
        octree.footprintPerDistance =
            2.0 * std::tan(0.5 * entry.scene.camera.fovDegrees * 3.14159265358979323846 / 180.0) /
            height;
        AcceleratedObjects accelerated = accelerate(entry.scene.objects, options.accel, octree);
        const SceneGeometry traced(std::move(accelerated.objects), accelerated.objectBvh);
        const Camera camera(entry.scene.camera, width, height);
        const std::vector<Ray> rays = primaryRays(camera, width, height);

        AccuracySceneSummary summary;
        summary.name = entry.spec.name;
        summary.description = entry.spec.description;
        summary.hasClosedForms = entry.spec.hasClosedForms;
        summary.width = width;
        summary.height = height;
        summary.defaultTolerance = defaultTolerance(height, entry.scene.camera.fovDegrees);

        say(entry.spec.name + ": reference for " + std::to_string(width) + "x" +
            std::to_string(height) + " rays");
        const ReferenceImage reference = computeReference(geometry, rays);
        summary.referenceSeconds = reference.seconds;
        for (const ReferenceHit& hit : reference.hits) {
            if (hit.kind == ReferenceHit::Kind::Hit) ++summary.referenceHits;
            if (hit.kind == ReferenceHit::Kind::Uncertain) ++summary.referenceUncertain;
        }
        result.scenes.push_back(summary);

        std::vector<double> tolerances = options.tolerances;
        tolerances.push_back(summary.defaultTolerance);
        for (TraceMethod method : options.methods) {
            if (method == TraceMethod::Closed && !entry.spec.hasClosedForms) continue;
            for (size_t k = 0; k < tolerances.size(); ++k) {
                AccuracyRow row;
                row.scene = entry.spec.name;
                row.method = method;
                row.tolerance = tolerances[k];
                row.isDefaultTolerance = k + 1 == tolerances.size();
                row.width = width;
                row.height = height;
                row.m =
                    measureAccuracy(traced, rays, reference, method, row.tolerance, options.runs);
                say(formatProgress(row) + (row.isDefaultTolerance ? "  (default)" : ""));
                result.rows.push_back(row);
            }
        }
    }
    return result;
}

}  // namespace kerf
