/// @file app/cli_render.cpp
#include "app/cli_render.h"

#include "app/exit_codes.h"
#include "app/frame_sequence.h"
#include "app/model_loader.h"
#include "app/option_text.h"
#include "app/output_paths.h"
#include "app/progress_bar.h"
#include "app/region_option.h"
#include "app/render_setup.h"
#include "app/stats_report.h"
#include "csg/normalize.h"
#include "csg/stopwatch.h"
#include "io/image.h"
#include "render/render.h"
#include "scene/limits.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <thread>

namespace kerf::app {

namespace {

using Clock = std::chrono::steady_clock;

void requireAtLeast(const CLI::Option* option, int value, int minimum) {
    if (option->count() > 0 && value < minimum) {
        throw UsageError(option->get_name() + " must be at least " + std::to_string(minimum) +
                         " (got " + std::to_string(value) + ")");
    }
}

/// The same upper limits as a model's render { } block (scene/limits.h).
void requireAtMost(const CLI::Option* option, int value, int maximum) {
    if (option->count() > 0 && value > maximum) {
        throw UsageError(option->get_name() + " must be at most " + std::to_string(maximum) +
                         " (got " + std::to_string(value) + ")");
    }
}

/// Range checks of the numeric flags; each message names its flag.
void checkNumbers(const RenderCommandLine& line) {
    requireAtLeast(line.widthOption, line.width, 1);
    requireAtLeast(line.heightOption, line.height, 1);
    requireAtLeast(line.sppOption, line.spp, 1);
    requireAtMost(line.widthOption, line.width, kMaxImageSide);
    requireAtMost(line.heightOption, line.height, kMaxImageSide);
    requireAtMost(line.sppOption, line.spp, kMaxSamplesPerPixel);
    requireAtLeast(line.threadsOption, line.threads, 0);
    requireAtMost(line.threadsOption, line.threads, kMaxThreads);
    if (line.toleranceOption->count() > 0 && !(line.tolerance > 0 && line.tolerance < 1)) {
        throw UsageError("--tolerance must be between 0 and 1, exclusive (got " +
                         line.toleranceOption->results().front() + ")");
    }
}

/// --section: `x=V`, `y=V` or `z=V` (the plane at that coordinate, the side above it
/// removed), or `PX,PY,PZ:NX,NY,NZ` (a point and the normal towards the removed side).
SectionPlane parseSection(const std::string& spec, const Vec3& color) {
    const std::string usage =
        "--section expects x=V, y=V, z=V or PX,PY,PZ:NX,NY,NZ (got '" + spec + "')";
    SectionPlane plane;
    plane.color = color;
    if (const auto axisSpec = parseAxisSpec(spec)) {
        const int axis = axisSpec->first;
        const std::optional<double> v = parseWholeNumber(axisSpec->second);
        if (!v || !std::isfinite(*v)) throw UsageError(usage);
        plane.point = Vec3(0.0);
        plane.point[axis] = *v;
        plane.normal = Vec3(0.0);
        plane.normal[axis] = 1.0;
        return plane;
    }
    const size_t colon = spec.find(':');
    if (colon == std::string::npos) throw UsageError(usage);
    const std::optional<Vec3> point = parseTriple(spec.substr(0, colon));
    const std::optional<Vec3> normal = parseTriple(spec.substr(colon + 1));
    if (!point || !normal) throw UsageError(usage);
    if (*normal == Vec3(0.0))
        throw UsageError("--section: the normal must not be zero (got '" + spec + "')");
    plane.point = *point;
    plane.normal = normalizeSafe(*normal);
    return plane;
}

/// The command line's section planes, checked before the model is read.
std::vector<SectionPlane> sectionPlanes(const RenderCommandLine& line) {
    Vec3 color = SectionPlane{}.color;
    if (!line.sectionColor.empty()) {
        const std::optional<Vec3> c = parseTriple(line.sectionColor);
        if (!c || c->x < 0 || c->y < 0 || c->z < 0)
            throw UsageError("--section-color expects R,G,B, each 0 or more (got '" +
                             line.sectionColor + "')");
        color = *c;
    }
    std::vector<SectionPlane> planes;
    for (const std::string& spec : line.sections) planes.push_back(parseSection(spec, color));
    if (planes.size() > size_t(kMaxSections))
        throw UsageError("--section: at most " + std::to_string(kMaxSections) +
                         " section planes (got " + std::to_string(planes.size()) + ")");
    return planes;
}

OutputPlan planOutputs(const RenderCommandLine& line) {
    OutputPlan plan;
    // One frame of a sequence comes with its own name (app/frame_sequence.h).
    plan.color =
        line.outputOption->count() > 0 || line.frame ? line.output : defaultOutputPath(line.model);
    if (plan.color.empty()) throw UsageError("-o: the output file name is empty");
    for (const std::string& spec : line.aovs) plan.aovs.push_back(parseAovSpec(spec));
    checkOutputPlan(plan, line.model);
    checkOutputsWritable(plan);
    return plan;
}

RenderOptions renderOptions(const RenderCommandLine& line, const OutputPlan& plan) {
    RenderOptions options;
    // 0 leaves the value of the model's render { } block (and hardware threads) in force.
    options.width = line.widthOption->count() > 0 ? line.width : 0;
    options.height = line.heightOption->count() > 0 ? line.height : 0;
    options.spp = line.sppOption->count() > 0 ? line.spp : 0;
    options.threads = line.threadsOption->count() > 0 ? line.threads : 0;
    options.tolerance = line.toleranceOption->count() > 0 ? line.tolerance : 0;
    const std::optional<TraceMethod> method = parseTraceMethod(line.method);
    if (!method)
        throw UsageError("--method must be closed, interval or sphere-trace (got '" + line.method +
                         "')");
    options.method = *method;
    const std::optional<Accel> accel = parseAccel(line.accel);
    if (!accel)
        throw UsageError("--accel must be auto, none, bvh or octree (got '" + line.accel + "')");
    options.accel = *accel;
    if (line.accelDepth != 0 &&
        (line.accelDepth < kMinOctreeDepth || line.accelDepth > kMaxOctreeDepth))
        throw UsageError("--accel-depth must be 0 (from the pixel footprint) or " +
                         std::to_string(kMinOctreeDepth) + " to " +
                         std::to_string(kMaxOctreeDepth) + " (got " +
                         std::to_string(line.accelDepth) + ")");
    options.accelDepth = line.accelDepth;
    const std::optional<BeamMode> beams = parseBeamMode(line.beams);
    if (!beams) throw UsageError("--beams must be auto, on or off (got '" + line.beams + "')");
    options.beams = *beams;
    if (!line.filter.empty()) {
        options.filter = parseFilter(line.filter);
        if (!options.filter)
            throw UsageError("--filter must be box, gaussian or mitchell (got '" + line.filter +
                             "')");
    }
    if (line.noiseOption && line.noiseOption->count() > 0) {
        if (!(line.noise >= 0.0 && std::isfinite(line.noise)))
            throw UsageError("--noise must be a standard error of 0 or more (got " +
                             std::to_string(line.noise) + ")");
        options.noise = line.noise;
    }
    if (!line.sampler.empty()) {
        options.sampler = parseSampler(line.sampler);
        if (!options.sampler)
            throw UsageError("--sampler must be regular, random, jittered or lattice (got '" +
                             line.sampler + "')");
    }
    for (const AovRequest& aov : plan.aovs) {
        if (aov.kind == AovRequest::Kind::Depth) options.wantDepth = true;
        if (aov.kind == AovRequest::Kind::Normal) options.wantNormal = true;
    }
    return options;
}

}  // namespace

CLI::App* addRenderCommand(CLI::App& parent, RenderCommandLine& line) {
    CLI::App* cmd = parent.add_subcommand("render", "Render a model file to an image");
    cmd->add_option("FILE", line.model, "The model file (.kerf)")->required();
    line.outputOption =
        cmd->add_option("-o,--output", line.output,
                        "Output image; the format follows the extension: .png .jpg (8-bit sRGB), "
                        ".exr .tif (float linear). Default: the model's base name with .png, here");
    line.widthOption = cmd->add_option("--width", line.width, "Image width in pixels");
    line.heightOption = cmd->add_option("--height", line.height, "Image height in pixels");
    line.sppOption =
        cmd->add_option("--spp", line.spp, "Samples per pixel, exactly (placed by --sampler)");
    line.threadsOption =
        cmd->add_option("--threads", line.threads, "Worker threads; 0 uses every hardware thread");
    line.toleranceOption = cmd->add_option(
        "--tolerance", line.tolerance,
        "Relative hit-distance tolerance in (0, 1); default: derived from the pixel footprint");
    cmd->add_option("--method", line.method,
                    "How primitives find crossings: closed (closed forms where they exist, the "
                    "default), interval (interval root isolation everywhere) or sphere-trace "
                    "(Lipschitz marching, for comparison: can miss thin features)")
        ->type_name("closed|interval|sphere-trace");
    cmd->add_option("--accel", line.accel,
                    "Acceleration: auto (the default: an octree for objects with an implicit "
                    "part at least 8 finest cells wide, a BVH over objects), none (no BVH over "
                    "objects, no octree), bvh, or octree (an octree for every bounded object)")
        ->type_name("auto|none|bvh|octree");
    cmd->add_option("--accel-depth", line.accelDepth,
                    "The octree's finest level: 2^N cells along an object's longest side "
                    "(3-10); 0, the default, derives it from the pixel footprint");
    cmd->add_option("--sampler", line.sampler,
                    "How each pixel's samples are placed: regular, random, jittered (the "
                    "default) or lattice (low discrepancy); overrides the model's render setting")
        ->type_name("regular|random|jittered|lattice");
    cmd->add_option("--filter", line.filter,
                    "Reconstruction filter: box (the default: each pixel averages its own "
                    "samples), gaussian (radius 1.5 pixels) or mitchell (Mitchell-Netravali, "
                    "radius 2); overrides the model's render setting")
        ->type_name("box|gaussian|mitchell");
    line.noiseOption = cmd->add_option(
        "--noise", line.noise,
        "Adaptive sampling: stop a pixel once the standard error of its mean luminance is below "
        "T (after at least 16 samples; spp stays the most); 0 turns it off");
    cmd->add_option("--beams", line.beams,
                    "Coherent camera rays: each tile's rays start where an interval test of "
                    "the tile's frustum proved space empty. auto (the default: on for scenes "
                    "with an implicit part and at most 64 primitives), on, or off")
        ->type_name("auto|on|off");
    cmd->add_option("--aov", line.aovs,
                    "Also write an output variable: depth=FILE.exr (eye-to-hit distance) or "
                    "normal=FILE.exr (world normal); may be repeated")
        ->type_name("KIND=FILE");
    cmd->add_option("--section", line.sections,
                    "A section view: cut the model by a plane and cap the cut in colour. x=V, y=V "
                    "or z=V removes the side where that coordinate exceeds V; PX,PY,PZ:NX,NY,NZ "
                    "removes the side the normal N points to from the point P. May be repeated; "
                    "adds to the model's section { } planes")
        ->type_name("PLANE");
    cmd->add_option("--section-color", line.sectionColor,
                    "The colour of the caps of --section planes (default 0.85,0.2,0.15)")
        ->type_name("R,G,B");
    line.regionOption =
        cmd->add_option(
               "--region", line.region,
               "Render only the pixels [X0, X1) x [Y0, Y1) of the full image, each equal bit "
               "for bit to the same pixel of a full render. An .exr or .tif output keeps "
               "the region's place (its data window inside the full display window) and "
               "'kerf assemble' stitches such parts; a .png or .jpg holds the region alone "
               "and loses its place (assemble refuses it)")
            ->type_name("X0,Y0,X1,Y1");
    cmd->add_flag("--stats", line.stats, "Print statistics to stderr");
    cmd->add_flag("-q,--quiet", line.quiet, "No progress bar and no echo lines from the model");
    addFrameOptions(*cmd, line);
    return cmd;
}

int runRender(const RenderCommandLine& line) {
    // A sequence renders each frame through this same function (app/frame_sequence.h).
    if (wantsFrameSequence(line)) return renderFrames(line, runRender);
    checkNumbers(line);
    const std::optional<PixelRect> region = parseRegion(line.regionOption, line.region);
    const std::vector<SectionPlane> sections = sectionPlanes(line);
    const OutputPlan plan = planOutputs(line);

    const auto compileStart = Clock::now();
    std::optional<Scene> scene =
        loadModel(line.model, std::cerr, line.quiet, line.frame.value_or(SequenceFrame{}));
    if (!scene) return kExitUsage;
    checkPlanNotInputs(plan, processAssets().inputs());
    if (scene->sections.size() + sections.size() > size_t(kMaxSections))
        throw UsageError("--section: the model's " + std::to_string(scene->sections.size()) +
                         " section planes and " + std::to_string(sections.size()) +
                         " more are over the limit of " + std::to_string(kMaxSections));
    scene->sections.insert(scene->sections.end(), sections.begin(), sections.end());
    const double secondsCompile = secondsSince(compileStart);

    RenderOptions options = renderOptions(line, plan);
    if (region) {
        checkRegionInside(*region, options.width > 0 ? options.width : scene->settings.width,
                          options.height > 0 ? options.height : scene->settings.height);
        options.region = region;
    }
    std::unique_ptr<ProgressBar> bar;
    if (!line.quiet && stderrIsTerminal()) {
        bar = std::make_unique<ProgressBar>(stderr);
        options.progress = [&bar](double fraction) { bar->update(fraction); };
    }
    const RenderResult result = render(*scene, options);
    if (bar) bar->finish();

    const auto writeStart = Clock::now();
    writeImage(result.color, plan.color, windowOf(result));
    for (const AovRequest& aov : plan.aovs) {
        writeImage(aov.kind == AovRequest::Kind::Depth ? result.depth : result.normal, aov.path,
                   windowOf(result));
    }
    const double secondsWrite = secondsSince(writeStart);

    if (line.stats) {
        RunReport report;
        report.width = result.color.width;
        report.height = result.color.height;
        report.spp = options.spp > 0 ? options.spp : scene->settings.spp;
        report.threads = options.threads > 0
                             ? options.threads
                             : int(std::max(1u, std::thread::hardware_concurrency()));
        report.render = result.stats;
        report.secondsCompile = secondsCompile;
        report.secondsWrite = secondsWrite;
        printStats(report, std::cerr);
    }
    return kExitSuccess;
}

}  // namespace kerf::app

// The same steps for the MPI driver (app/render_setup.h).
namespace kerf::app {

RenderSetup setUpRender(const RenderCommandLine& line, bool probeOutputs) {
    RenderSetup setup;
    checkNumbers(line);
    setup.region = parseRegion(line.regionOption, line.region);
    setup.sections = sectionPlanes(line);
    if (probeOutputs) {
        setup.plan = planOutputs(line);
    } else {
        setup.plan.color =
            line.outputOption->count() > 0 ? line.output : defaultOutputPath(line.model);
        for (const std::string& spec : line.aovs) setup.plan.aovs.push_back(parseAovSpec(spec));
    }
    setup.options = renderOptions(line, setup.plan);
    return setup;
}

void applySetup(RenderSetup& setup, Scene& scene) {
    if (scene.sections.size() + setup.sections.size() > size_t(kMaxSections))
        throw UsageError("--section: the model's " + std::to_string(scene.sections.size()) +
                         " section planes and " + std::to_string(setup.sections.size()) +
                         " more are over the limit of " + std::to_string(kMaxSections));
    scene.sections.insert(scene.sections.end(), setup.sections.begin(), setup.sections.end());
    if (setup.region) {
        const RenderOptions& o = setup.options;
        checkRegionInside(*setup.region, o.width > 0 ? o.width : scene.settings.width,
                          o.height > 0 ? o.height : scene.settings.height);
        setup.options.region = setup.region;
    }
}

void writeRenderOutputs(const RenderResult& result, const OutputPlan& plan) {
    writeImage(result.color, plan.color, windowOf(result));
    for (const AovRequest& aov : plan.aovs)
        writeImage(aov.kind == AovRequest::Kind::Depth ? result.depth : result.normal, aov.path,
                   windowOf(result));
}

}  // namespace kerf::app
