/// @file accuracy/bench.h
/// @brief The speed-against-error benchmark: every scene × method × tolerance, each measured
/// against one reference per scene (accuracy/measure.h).
#pragma once

#include <functional>
#include <string>
#include <vector>
#include "volume/octree/accelerate.h"

#include "accuracy/catalogue.h"
#include "accuracy/measure.h"
#include "scene/scene.h"

namespace kerf {

/// A benchmark scene, compiled.
struct AccuracyScene {
    AccuracySceneSpec spec;
    Scene scene;
};

struct AccuracyBenchOptions {
    int width = 320;  ///< image size before the scene's resolutionDivisor
    int height = 240;
    int runs = 5;  ///< timed passes per measurement; the median is reported
    std::vector<TraceMethod> methods{TraceMethod::Closed, TraceMethod::Interval,
                                     TraceMethod::SphereTrace};
    /// The acceleration the traced geometry gets (the reference always traces the plain
    /// objects): the renderer's default unless asked otherwise.
    Accel accel = Accel::Auto;
    /// Measured in this order; the scene's default tolerance (defaultTolerance of its traced
    /// height and field of view) is measured after them.
    std::vector<double> tolerances = accuracyDecadeTolerances();
    /// Called with one line of progress at a time (no newline); may be empty.
    std::function<void(const std::string&)> progress;
};

/// One row of the report.
struct AccuracyRow {
    std::string scene;
    TraceMethod method = TraceMethod::Closed;
    double tolerance = 0;
    bool isDefaultTolerance = false;
    int width = 0;
    int height = 0;
    AccuracyMeasurement m;
};

/// Per-scene facts the report states beside the rows.
struct AccuracySceneSummary {
    std::string name;
    std::string description;
    bool hasClosedForms = true;
    int width = 0;
    int height = 0;
    double defaultTolerance = 0;
    double referenceSeconds = 0;
    int referenceHits = 0;
    int referenceUncertain = 0;
};

struct AccuracyBenchResult {
    std::vector<AccuracyRow> rows;
    std::vector<AccuracySceneSummary> scenes;
};

/// Runs the benchmark on the calling thread (the reference uses every core). The Closed method
/// is skipped on scenes without closed forms, where it would repeat the Interval rows.
AccuracyBenchResult runAccuracyBench(const std::vector<AccuracyScene>& scenes,
                                     const AccuracyBenchOptions& options);

}  // namespace kerf
