/// @file app/render_setup.h
/// @brief The steps of `kerf render` before and after the model, for a driver that runs them
/// itself (app/mpi/): same checks, same messages, same outputs.
#pragma once

#include "app/cli_render.h"
#include "app/output_paths.h"
#include "render/render.h"
#include "scene/scene.h"

#include <optional>
#include <vector>

namespace kerf::app {

struct RenderSetup {
    std::optional<PixelRect> region;     ///< --region, checked against the image once known
    std::vector<SectionPlane> sections;  ///< --section planes
    OutputPlan plan;
    RenderOptions options;  ///< without region and progress
};

/// The checks `kerf render` makes before reading the model; throws UsageError like it.
/// `probeOutputs`: also check that the outputs can be written (one process only).
RenderSetup setUpRender(const RenderCommandLine& line, bool probeOutputs);

/// Adds the setup's sections to the compiled scene and its region to the options, checked
/// against the image size; throws UsageError like `kerf render`.
void applySetup(RenderSetup& setup, Scene& scene);

/// Writes the colour image and the AOVs of `result` where the plan says.
void writeRenderOutputs(const RenderResult& result, const OutputPlan& plan);

}  // namespace kerf::app
