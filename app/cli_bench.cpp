/// @file app/cli_bench.cpp
#include "app/cli_bench.h"

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>

#include "accuracy/bench.h"
#include "accuracy/plot.h"
#include "accuracy/report.h"
#include "app/exit_codes.h"
#include "app/model_loader.h"
#include "io/atomic_file.h"
#include "io/text_file.h"

namespace kerf::app {

namespace {

/// --quick: a smoke run for tests, seconds long.
constexpr int kQuickWidth = 48;
constexpr int kQuickHeight = 36;

AccuracyBenchOptions benchOptions(const BenchCommandLine& line) {
    AccuracyBenchOptions options;
    options.width = line.width;
    options.height = line.height;
    options.runs = line.runs;
    if (line.quick) {
        if (line.widthOption->count() == 0) options.width = kQuickWidth;
        if (line.heightOption->count() == 0) options.height = kQuickHeight;
        if (line.runsOption->count() == 0) options.runs = 1;
        options.tolerances = {1e-3, 1e-9};
    }
    if (options.width < 1) throw UsageError("--width must be at least 1");
    if (options.height < 1) throw UsageError("--height must be at least 1");
    if (options.runs < 1) throw UsageError("--runs must be at least 1");
    if (!line.methods.empty()) {
        options.methods.clear();
        for (const std::string& name : line.methods) {
            const std::optional<TraceMethod> method = parseTraceMethod(name);
            if (!method)
                throw UsageError("--methods: unknown method '" + name +
                                 "' (use closed, interval, sphere-trace)");
            options.methods.push_back(*method);
        }
    }
    const std::optional<Accel> accel = parseAccel(line.accel);
    if (!accel)
        throw UsageError("--accel must be auto, none, bvh or octree (got '" + line.accel + "')");
    options.accel = *accel;
    return options;
}

std::vector<const AccuracySceneSpec*> selectScenes(const BenchCommandLine& line) {
    std::vector<const AccuracySceneSpec*> specs;
    if (line.scenes.empty()) {
        for (const AccuracySceneSpec& spec : accuracySceneCatalogue()) specs.push_back(&spec);
        return specs;
    }
    for (const std::string& name : line.scenes) {
        const AccuracySceneSpec* spec = findAccuracyScene(name);
        if (spec == nullptr) {
            std::string known;
            for (const AccuracySceneSpec& s : accuracySceneCatalogue())
                known += (known.empty() ? "" : ", ") + s.name;
            throw UsageError("--scenes: unknown scene '" + name + "' (known: " + known + ")");
        }
        specs.push_back(spec);
    }
    return specs;
}

/// Compiles the selected scenes; nullopt when one fails (its diagnostics are printed).
std::optional<std::vector<AccuracyScene>> loadScenes(const BenchCommandLine& line) {
    std::vector<AccuracyScene> scenes;
    for (const AccuracySceneSpec* spec : selectScenes(line)) {
        const std::string path = line.sceneDir + "/" + spec->file;
        if (!std::filesystem::exists(path))
            throw UsageError("scene file '" + path +
                             "' not found; run from the kerf source "
                             "folder or give --scene-dir (the folder accuracy/scenes)");
        std::optional<Scene> scene = loadModel(path, std::cerr);
        if (!scene) return std::nullopt;
        scenes.push_back({*spec, std::move(*scene)});
    }
    return scenes;
}

}  // namespace

CLI::App* addBenchCommand(CLI::App& parent, BenchCommandLine& line) {
    CLI::App* bench = parent.add_subcommand("bench", "Benchmarks");
    bench->require_subcommand(1);
    CLI::App* cmd = bench->add_subcommand(
        "accuracy",
        "Speed against error: trace fixed scenes by each method at tolerances 1e-2 … 1e-12 and "
        "the default, compare with an extended-precision reference, write accuracy.csv, "
        "accuracy.svg and accuracy_table.md");
    line.accuracyCommand = cmd;
    cmd->add_option("--out", line.outDir, "Output folder (created if missing)")
        ->capture_default_str();
    cmd->add_option("--scene-dir", line.sceneDir, "Folder of the benchmark's .kerf scenes")
        ->capture_default_str();
    line.widthOption =
        cmd->add_option("--width", line.width, "Image width before each scene's divisor")
            ->capture_default_str();
    line.heightOption =
        cmd->add_option("--height", line.height, "Image height before each scene's divisor")
            ->capture_default_str();
    line.runsOption =
        cmd->add_option("--runs", line.runs, "Timed passes per measurement (median reported)")
            ->capture_default_str();
    cmd->add_option("--scenes", line.scenes, "Comma-separated scene names (default: all)")
        ->delimiter(',');
    cmd->add_option("--methods", line.methods,
                    "Comma-separated: closed, interval, sphere-trace (default: all)")
        ->delimiter(',');
    cmd->add_option("--accel", line.accel,
                    "Acceleration of the traced geometry: auto (the renderer's default), none, "
                    "bvh or octree; the reference traces the plain objects")
        ->capture_default_str();
    cmd->add_flag("--quick", line.quick,
                  "Tiny images, tolerances 1e-3 and 1e-9 plus the default, one run (for tests)");
    return bench;
}

int runBench(const BenchCommandLine& line) {
    AccuracyBenchOptions options = benchOptions(line);
    const std::optional<std::vector<AccuracyScene>> scenes = loadScenes(line);
    if (!scenes) return kExitUsage;
    std::error_code error;
    std::filesystem::create_directories(line.outDir, error);
    if (error) throw UsageError("--out: cannot create '" + line.outDir + "': " + error.message());
    // Before the long run: a result that could not be kept is not worth computing.
    for (const char* name : {"accuracy.csv", "accuracy.svg", "accuracy_table.md"})
        checkOutputWritable(line.outDir + "/" + name);

    options.progress = [](const std::string& text) { std::cerr << text << std::endl; };
    std::cerr << "kerf bench accuracy: " << scenes->size() << " scenes, " << options.runs
              << " timed run(s) each on one thread\n";
    const AccuracyBenchResult result = runAccuracyBench(*scenes, options);

    writeTextFileAtomically(line.outDir + "/accuracy.csv", accuracyCsv(result));
    writeTextFileAtomically(line.outDir + "/accuracy.svg", accuracyPlotSvg(result));
    writeTextFileAtomically(line.outDir + "/accuracy_table.md", accuracyMarkdown(result));
    std::cerr << "wrote " << line.outDir << "/accuracy.csv, accuracy.svg, accuracy_table.md\n";
    return kExitSuccess;
}

}  // namespace kerf::app
