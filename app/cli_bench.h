/// @file app/cli_bench.h
/// @brief `kerf bench accuracy [--out DIR] [--width W] [--height H] [--runs N]
/// [--scenes a,b,…] [--methods closed,interval,sphere-trace] [--accel A] [--scene-dir DIR]
/// [--quick]`: the speed-against-error report (accuracy/bench.h) as CSV, SVG plot and Markdown.
#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace kerf::app {

/// The command line of `kerf bench` as parsed; the option pointers tell which flags were given
/// (given flags override the --quick presets).
struct BenchCommandLine {
    std::string outDir = ".";
    std::string sceneDir = "accuracy/scenes";
    int width = 320;
    int height = 240;
    int runs = 5;
    std::vector<std::string> scenes;   ///< empty: every scene of the catalogue
    std::vector<std::string> methods;  ///< empty: all three
    std::string accel = "auto";
    bool quick = false;

    CLI::App* accuracyCommand = nullptr;
    CLI::Option* widthOption = nullptr;
    CLI::Option* heightOption = nullptr;
    CLI::Option* runsOption = nullptr;
};

/// Adds the `bench` subcommand (with its `accuracy` subcommand) to `parent`, parsing into
/// `line` (which must outlive parsing).
CLI::App* addBenchCommand(CLI::App& parent, BenchCommandLine& line);

/// Runs the command; returns the exit code. Throws UsageError for bad options and lets
/// FileWriteError (an output that cannot be written) and other failures through to main().
int runBench(const BenchCommandLine& line);

}  // namespace kerf::app
