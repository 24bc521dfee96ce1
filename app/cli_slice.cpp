/// @file app/cli_slice.cpp
#include "app/cli_slice.h"

#include "app/exit_codes.h"
#include "app/model_loader.h"
#include "app/numbered_names.h"
#include "app/option_text.h"
#include "app/output_paths.h"
#include "csg/format.h"
#include "io/atomic_file.h"
#include "io/image.h"
#include "io/section_writers.h"
#include "io/text_file.h"
#include "slice/slice.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace kerf::app {

namespace {

enum class Format { Svg, Dxf, Png };

double finiteNumber(const std::string& text, const std::string& option) {
    const std::optional<double> v = parseWholeNumber(text);
    if (!v || !std::isfinite(*v))
        throw UsageError(option + ": '" + text + "' is not a finite number");
    return *v;
}

/// "x=V" → axis and the rest after '='.
int parseAxis(const std::string& spec, const std::string& option, std::string& rest) {
    const auto axisSpec = parseAxisSpec(spec);
    if (!axisSpec)
        throw UsageError(option + " must look like z=0.5 (x=, y= or z=), got '" + spec + "'");
    rest = axisSpec->second;
    return axisSpec->first;
}

Vec3 parseVector(const std::string& text, const std::string& option) {
    const std::optional<Vec3> v = parseTriple(text);
    if (!v) throw UsageError(option + " must be three finite numbers x,y,z, got '" + text + "'");
    return *v;
}

Format formatOf(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    if (ext == ".svg") return Format::Svg;
    if (ext == ".dxf") return Format::Dxf;
    if (ext == ".png") return Format::Png;
    throw UsageError("-o: '" + path + "' must end in .svg, .dxf or .png");
}

/// The file name of layer i: the pattern's one %d conversion (with flags/width) filled in.
std::string layerPath(const std::string& pattern, int index) {
    char buffer[4096];
    std::snprintf(buffer, sizeof buffer, pattern.c_str(), index);
    return buffer;
}

void checkLayerPattern(const std::string& pattern) {
    size_t conversions = 0;
    for (size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '%') continue;
        if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
            ++i;
            continue;
        }
        size_t j = i + 1;
        while (j < pattern.size() &&
               (std::isdigit(static_cast<unsigned char>(pattern[j])) || pattern[j] == '0'))
            ++j;
        if (j >= pattern.size() || pattern[j] != 'd' || j - i > 4)
            throw UsageError("-o: with --stack the name needs one %d (e.g. cut_%04d.svg), got '" +
                             pattern + "'");
        ++conversions;
        i = j;
    }
    if (conversions != 1)
        throw UsageError(
            "-o: with --stack the name needs exactly one %d (e.g. cut_%04d.svg), got '" + pattern +
            "'");
}

void checkNotInput(const std::string& out, const std::string& model) {
    std::error_code ec;
    if (std::filesystem::equivalent(out, model, ec) && !ec)
        throw UsageError("-o: '" + out + "' is the model file; refusing to write over it");
}

void writeSection(const SectionDrawing& drawing, const std::string& path, Format format,
                  const SliceCommandLine& line) {
    if (format == Format::Svg)
        return writeTextFileAtomically(path, sectionSvg(drawing, line.outline));
    if (format == Format::Dxf) return writeTextFileAtomically(path, sectionDxf(drawing));
    const double w = drawing.maxU - drawing.minU, h = drawing.maxV - drawing.minV;
    SectionGrid grid;
    grid.pixel =
        line.pixel > 0.0 ? line.pixel : std::max(w, h) / (line.width > 0 ? line.width : 1024);
    grid.width = std::max(1, static_cast<int>(std::ceil(w / grid.pixel)));
    grid.height = std::max(1, static_cast<int>(std::ceil(h / grid.pixel)));
    if (double(grid.width) * grid.height > 1e9)
        throw UsageError("--pixel: " + std::to_string(grid.width) + " x " +
                         std::to_string(grid.height) + " pixels is too many");
    grid.u0 = drawing.minU;
    grid.v1 = drawing.maxV;
    writeImage(sectionRaster(drawing, grid), path);
}

void printStats(const SliceResult& r, const std::string& label, std::ostream& out) {
    const SliceStats& s = r.stats;
    out << label << "regions " << s.regions.size() << ", contours " << s.contours << ", holes "
        << s.holes << "\n";
    char buf[256];
    for (size_t i = 0; i < s.regions.size(); ++i) {
        const RegionStats& g = s.regions[i];
        std::snprintf(buf, sizeof buf, "  region %zu (%s): area %.15g  perimeter %.15g  holes %d\n",
                      i + 1, g.material.c_str(), g.area, g.perimeter, g.holes);
        out << buf;
    }
    std::snprintf(buf, sizeof buf, "  total: area %.15g  perimeter %.15g\n", s.area, s.perimeter);
    out << buf;
    std::snprintf(
        buf, sizeof buf,
        "  cells %zu (boundary leaves %zu, proved simple %zu), depth %d, point evaluations %zu\n",
        s.contour.cells, s.contour.boundaryLeaves, s.contour.simpleLeaves, s.contour.depth,
        s.contour.pointEvals);
    out << buf;
    if (s.contour.repairedLoops > 0)
        out << "  open chains closed: " << s.contour.repairedLoops << "\n";
    if (s.contour.flatCells > 0)
        out << "  cells with f within rounding of 0: " << s.contour.flatCells << "\n";
    std::snprintf(buf, sizeof buf, "  time: contour %.3f ms, regions %.3f ms\n",
                  1e3 * s.contourSeconds, 1e3 * s.regionSeconds);
    out << buf;
}

bool someLayers(const SliceCommandLine& line) {
    return line.layersOption && line.layersOption->count() > 0;
}

/// Options first, then outputs, then the model: no work for a run that cannot succeed.
void checkSliceOptions(const SliceCommandLine& line) {
    const int planeForms =
        !line.plane.empty() + (!line.point.empty() || !line.normal.empty()) + !line.stack.empty();
    if (planeForms != 1)
        throw UsageError("give exactly one of --plane, --point with --normal, or --stack");
    if (!(line.tolerance > 0.0 && line.tolerance < 1.0))
        throw UsageError("--tolerance must be between 0 and 1, exclusive (got " +
                         formatDouble("%g", line.tolerance) + ")");
    if (line.tolerance < 1e-13)
        throw UsageError("--tolerance must be at least 1e-13 (finer than doubles resolve; got " +
                         formatDouble("%g", line.tolerance) + ")");
    if (line.widthOption->count() && line.pixelOption->count())
        throw UsageError("--width and --pixel: give one of them");
    if (line.widthOption->count() && (line.width < 1 || line.width > 65536))
        throw UsageError("--width must be between 1 and 65536 (got " + std::to_string(line.width) +
                         ")");
    if (line.pixelOption->count() && !(line.pixel > 0.0 && std::isfinite(line.pixel)))
        throw UsageError("--pixel must be a positive size");
    if (someLayers(line) && line.stack.empty()) throw UsageError("--layers goes with --stack");
}

/// The planes to cut: one family of parallel planes and the offsets along its normal.
struct SlicePlan {
    SlicePlane family;
    std::vector<double> offsets;
    std::vector<int> layerNumbers;  // with --stack: each offset's layer number in the full stack
};

/// --stack A=FROM:TO:STEP, narrowed by --layers and by this job's share (part of parts).
SlicePlan stackPlan(const SliceCommandLine& line) {
    SlicePlan plan;
    std::string rest;
    const int axis = parseAxis(line.stack, "--stack", rest);
    plan.family = SlicePlane::axisAligned(axis, 0.0);
    const size_t c1 = rest.find(':'), c2 = c1 == std::string::npos ? c1 : rest.find(':', c1 + 1);
    if (c2 == std::string::npos)
        throw UsageError("--stack must look like z=0:2.4:0.05, got '" + line.stack + "'");
    const double from = finiteNumber(rest.substr(0, c1), "--stack");
    const double to = finiteNumber(rest.substr(c1 + 1, c2 - c1 - 1), "--stack");
    const double step = finiteNumber(rest.substr(c2 + 1), "--stack");
    if (!(step > 0.0) || !(to >= from))
        throw UsageError("--stack: the step must be positive and FROM ≤ TO, got '" + line.stack +
                         "'");
    const double count = std::floor((to - from) / step * (1.0 + 1e-12)) + 1.0;
    if (count > 100000) throw UsageError("--stack: more than 100000 layers");
    // The range picks layers of the full stack: the same offsets and numbers as without it.
    NumberRange kept{0, int64_t(count) - 1};
    if (someLayers(line)) {
        kept = parseNumberRange(line.layers, "--layers");
        if (kept.last >= int64_t(count))
            throw UsageError("--layers " + line.layers + ": the stack " + line.stack +
                             " has layers 0 to " + std::to_string(int64_t(count) - 1));
    }
    for (int64_t i = kept.first; i <= kept.last; ++i) {
        if ((i - kept.first) % line.parts != line.part) continue;
        plan.offsets.push_back(from + double(i) * step);
        plan.layerNumbers.push_back(int(i));
    }
    return plan;
}

/// One plane, from --plane x=V or from --point with --normal.
SlicePlan singlePlan(const SliceCommandLine& line) {
    SlicePlan plan;
    if (!line.plane.empty()) {
        std::string rest;
        const int axis = parseAxis(line.plane, "--plane", rest);
        plan.family = SlicePlane::axisAligned(axis, 0.0);
        plan.offsets.push_back(finiteNumber(rest, "--plane"));
        return plan;
    }
    if (line.point.empty() || line.normal.empty())
        throw UsageError("--point and --normal go together");
    const Vec3 n = parseVector(line.normal, "--normal");
    const double len = glm::length(n);
    if (!(len > 0.0) || !std::isfinite(len))
        throw UsageError("--normal must be a non-zero finite vector");
    plan.family = SlicePlane::throughPoint(parseVector(line.point, "--point"), n);
    plan.offsets.push_back(0.0);
    return plan;
}

/// The output file of each offset, checked before the model is loaded.
std::vector<std::string> outputPaths(const SliceCommandLine& line, const SlicePlan& plan) {
    std::vector<std::string> paths;
    if (!line.stack.empty()) {
        checkLayerPattern(line.output);
        for (size_t i = 0; i < plan.offsets.size(); ++i)
            paths.push_back(layerPath(line.output, plan.layerNumbers[i]));
    } else {
        paths.push_back(line.output);
    }
    for (const std::string& p : {paths.front(), paths.back()}) {
        checkNotInput(p, line.model);
        checkOutputWritable(p);
    }
    return paths;
}

void reportSectionNotes(const std::vector<SliceResult>& results,
                        const std::vector<std::string>& paths, bool quiet) {
    for (size_t i = 0; i < results.size(); ++i) {
        if (results[i].stats.contour.budgetExceeded)
            std::cerr
                << "kerf: warning: " << paths[i]
                << ": the section needed more quadtree cells than allowed; parts are drawn coarser "
                   "than --tolerance\n";
        if (results[i].stats.contour.flatCells > 0 && !quiet)
            std::cerr
                << "kerf: note: " << paths[i]
                << ": the plane holds a face of the model, or faces coincide, where the section is "
                   "decided by the sign of f within rounding\n";
        if (results[i].drawing.layers.empty())
            std::cerr << "kerf: note: " << paths[i] << ": the section is empty\n";
    }
}

void writeSections(const std::vector<SliceResult>& results, const std::vector<std::string>& paths,
                   Format format, const SliceCommandLine& line) {
    // A stack's files are independent: vector files are written a few at a time, so one
    // file's fsync does not wait for the last. Images go one by one (the image plug-in is
    // loaded on the first).
    if (format == Format::Png || results.size() == 1) {
        for (size_t i = 0; i < results.size(); ++i)
            writeSection(results[i].drawing, paths[i], format, line);
    } else {
        tbb::task_arena writers(8);
        writers.execute([&] {
            tbb::parallel_for(size_t(0), results.size(), [&](size_t i) {
                writeSection(results[i].drawing, paths[i], format, line);
            });
        });
    }
}

/// The moments of a run, for --stats.
struct SliceTimes {
    std::chrono::steady_clock::time_point start, loaded, sliced, written;
};

void printRunStats(const std::vector<SliceResult>& results, const std::vector<std::string>& paths,
                   const SlicePlan& plan, const SceneSlicer& slicer, const SliceTimes& t,
                   const SliceCommandLine& line) {
    auto ms = [](auto a, auto b) { return 1e3 * std::chrono::duration<double>(b - a).count(); };
    if (results.size() == 1) {
        printStats(results[0], "", std::cerr);
    } else {
        for (size_t i = 0; i < results.size(); ++i)
            printStats(results[i],
                       "layer " + std::to_string(plan.layerNumbers[i]) + " (" + paths[i] + "): ",
                       std::cerr);
    }
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "tolerance %.3g (absolute %.3g); time: load %.3f ms, tapes %.3f ms, slice %.3f "
                  "ms (%zu layers), write %.3f ms\n",
                  line.tolerance, slicer.absoluteTolerance(), ms(t.start, t.loaded),
                  1e3 * slicer.compileSeconds(),
                  ms(t.loaded, t.sliced) - 1e3 * slicer.compileSeconds(), results.size(),
                  ms(t.sliced, t.written));
    std::cerr << buf;
}

}  // namespace

CLI::App* addSliceCommand(CLI::App& parent, SliceCommandLine& line) {
    CLI::App* cmd = parent.add_subcommand(
        "slice", "Cut the model's solids by a plane; write the section as SVG, DXF or PNG");
    cmd->add_option("FILE", line.model, "The model file (.kerf)")->required();
    cmd->add_option(
           "-o,--output", line.output,
           "Output .svg, .dxf or .png (with --stack: a name with one %d, e.g. cut_%04d.svg)")
        ->required();
    cmd->add_option("--plane", line.plane,
                    "An axis plane: x=V (u = y, v = z), y=V (u = z, v = x), z=V (u = x, v = y)");
    cmd->add_option("--point", line.point, "A point of the plane, x,y,z (with --normal)");
    cmd->add_option("--normal", line.normal, "The plane's normal, x,y,z (with --point)");
    cmd->add_option("--stack", line.stack, "Parallel planes A=FROM:TO:STEP, e.g. z=0:2.4:0.05");
    line.layersOption =
        cmd->add_option(
               "--layers", line.layers,
               "With --stack: only layers A to B (or layer N) of the stack, numbered from 0 and "
               "named as in the full stack, so jobs of a farm can each write a part")
            ->type_name("A-B|N");
    cmd->add_option("--tolerance", line.tolerance,
                    "Distance from vertices and chords to the true section, relative to the "
                    "model's size (default 1e-7)");
    cmd->add_flag("--outline", line.outline, "SVG: strokes only, no fill");
    line.widthOption =
        cmd->add_option("--width", line.width, "PNG: pixels across the longer side (default 1024)");
    line.pixelOption = cmd->add_option("--pixel", line.pixel, "PNG: pixel size in model units");
    cmd->add_flag("--stats", line.stats,
                  "Print areas, perimeters, contour counts and times to stderr");
    cmd->add_flag("-q,--quiet", line.quiet, "Leave out the model's echo lines");
    return cmd;
}

int runSlice(const SliceCommandLine& line) {
    SliceTimes times;
    times.start = std::chrono::steady_clock::now();
    checkSliceOptions(line);
    const SlicePlan plan = line.stack.empty() ? singlePlan(line) : stackPlan(line);
    if (plan.offsets.empty()) return kExitSuccess;  // a share of a stack with no layer left in it
    const Format format = formatOf(line.output);
    const std::vector<std::string> paths = outputPaths(line, plan);

    const std::optional<Scene> scene = loadModel(line.model, std::cerr, line.quiet);
    if (!scene) return kExitUsage;
    for (const std::string& path : paths) checkNotAnInput("-o", path, processAssets().inputs());
    times.loaded = std::chrono::steady_clock::now();

    SliceOptions options;
    options.tolerance = line.tolerance;
    SceneSlicer slicer(*scene, plan.family, options);
    for (const std::string& note : slicer.notes()) std::cerr << "kerf: note: " << note << "\n";
    const std::vector<SliceResult> results = slicer.sliceMany(plan.offsets);
    times.sliced = std::chrono::steady_clock::now();
    reportSectionNotes(results, paths, line.quiet);
    writeSections(results, paths, format, line);
    times.written = std::chrono::steady_clock::now();
    if (line.stats) printRunStats(results, paths, plan, slicer, times, line);
    return kExitSuccess;
}

}  // namespace kerf::app
