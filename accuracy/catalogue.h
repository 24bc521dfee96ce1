/// @file accuracy/catalogue.h
/// @brief The fixed scene set, tolerances and method names of `kerf bench accuracy`. The scenes
/// are model files in accuracy/scenes/; compiling them is the caller's job (accuracy/ does not
/// depend on lang/).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "csg/trace_context.h"

namespace kerf {

/// One scene of the accuracy benchmark.
struct AccuracySceneSpec {
    std::string name;  ///< short name, used by --scenes and in the CSV
    std::string file;  ///< model file name inside accuracy/scenes/
    /// False when every primitive of the scene is root-found (torus, implicit): the Closed
    /// method is then the Interval method and is not measured separately.
    bool hasClosedForms = true;
    /// Slow scenes trace (width / divisor) × (height / divisor) rays, so the full bench stays
    /// within minutes.
    int resolutionDivisor = 1;
    std::string description;  ///< one line for the report
};

/// Every scene of the benchmark, in report order.
const std::vector<AccuracySceneSpec>& accuracySceneCatalogue();

/// The spec named `name`, or nullptr.
const AccuracySceneSpec* findAccuracyScene(const std::string& name);

/// The decade tolerances 1e-2, 1e-3, …, 1e-12 (the default tolerance is added per scene).
std::vector<double> accuracyDecadeTolerances();

}  // namespace kerf
