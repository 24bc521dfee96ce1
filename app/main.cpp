/// @file app/main.cpp
/// @brief The `kerf` executable: parses the command line, runs one subcommand and turns its
/// outcome into an exit code. The only place in kerf that exits; every exception stops here.
#include "app/cli_assemble.h"
#include "app/cli_bench.h"
#include "app/cli_check.h"
#include "app/cli_mesh.h"
#include "app/cli_render.h"
#include "app/cli_slice.h"
#include "app/cli_voxelize.h"
#include "app/exit_codes.h"
#include "io/image.h"
#include "io/image_plugin_loader.h"

#include <tbb/global_control.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <exception>
#include <filesystem>
#include <iostream>
#include <new>
#include <string>

namespace {

using namespace kerf::app;

std::string lowerExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

bool endsWithPng(const std::string& path) { return lowerExtension(path) == ".png"; }

/// Whether `kerf slice -o PATH` needs the plug-in: a raster other than PNG (SVG and DXF are
/// text kerf writes, a PNG kerf encodes itself, io/png_write.h).
bool sliceNeedsPlugin(const std::string& output) {
    const std::string ext = lowerExtension(output);
    return ext != ".svg" && ext != ".dxf" && ext != ".png";
}

/// Whether every file `kerf render` writes is a whole PNG, which kerf encodes itself
/// (io/png_write.h): the plug-in is then loaded only if the model reads a texture.
bool renderWritesOnlyWholePngs(const RenderCommandLine& line) {
    if (!line.region.empty() || !endsWithPng(line.output)) return false;
    return std::all_of(line.aovs.begin(), line.aovs.end(), endsWithPng);
}

/// Commands that will read or write an image load the plug-in before any work, so a kerf
/// without its plug-in says so at once (exit 2, naming the paths tried), not after a render.
/// Returns the exit code, or -1 to go on.
int checkImageSupport(bool needed) {
    if (!needed) return -1;
    try {
        kerf::requireImagePlugin();
    } catch (const kerf::ImageSupportError& e) {
        std::cerr << "kerf: error: " << e.what() << "\n";
        return kExitUsage;
    }
    return -1;
}

/// Parses and runs; usage and write errors become their exit codes here, anything else
/// propagates to main().
int run(int argc, char** argv) {
    CLI::App cli(
        "kerf: a solid-modelling ray tracer. Model files (.kerf) describe CSG trees of "
        "implicit solids, traced exactly and rendered Whitted-style.",
        "kerf");
    cli.set_version_flag("--version", std::string("kerf ") + KERF_VERSION);
    cli.require_subcommand(1);

    RenderCommandLine renderLine;
    CheckCommandLine checkLine;
    BenchCommandLine benchLine;
    CLI::App* renderCmd = addRenderCommand(cli, renderLine);
    CLI::App* checkCmd = addCheckCommand(cli, checkLine);
    CLI::App* benchCmd = addBenchCommand(cli, benchLine);
    MeshCommandLine meshLine;
    CLI::App* meshCmd = addMeshCommand(cli, meshLine);
    SliceCommandLine sliceLine;
    CLI::App* sliceCmd = addSliceCommand(cli, sliceLine);
    AssembleCommandLine assembleLine;
    CLI::App* assembleCmd = addAssembleCommand(cli, assembleLine);
    VoxelizeCommandLine voxelizeLine;
    CLI::App* voxelizeCmd = addVoxelizeCommand(cli, voxelizeLine);

    try {
        cli.parse(argc, argv);
    } catch (const CLI::Success& e) {
        return cli.exit(e);  // --help, --version: printed by CLI11, exit 0
    } catch (const CLI::ParseError& e) {
        std::cerr << "kerf: error: " << e.what() << "\n"
                  << "Run 'kerf --help' (or 'kerf render --help') for usage.\n";
        return kExitUsage;
    }

    const bool needsImages = (renderCmd->parsed() && !renderWritesOnlyWholePngs(renderLine)) ||
                             assembleCmd->parsed() ||
                             (sliceCmd->parsed() && sliceNeedsPlugin(sliceLine.output));
    if (const int code = checkImageSupport(needsImages); code >= 0) return code;

    try {
        if (renderCmd->parsed()) return runRender(renderLine);
        if (checkCmd->parsed()) return runCheck(checkLine);
        if (benchCmd->parsed()) return runBench(benchLine);
        if (meshCmd->parsed()) return runMesh(meshLine);
        if (sliceCmd->parsed()) return runSlice(sliceLine);
        if (assembleCmd->parsed()) return runAssemble(assembleLine);
        if (voxelizeCmd->parsed()) return runVoxelize(voxelizeLine);
    } catch (const UsageError& e) {
        std::cerr << "kerf: error: " << e.what() << "\n";
        return kExitUsage;
    } catch (const kerf::FileWriteError& e) {  // images, text, CSV, SVG; before or after work
        std::cerr << "kerf: error: " << e.what() << "\n";
        return kExitFailure;
    }
    std::cerr << "kerf: error: no command given; try 'kerf --help'\n";
    return kExitUsage;
}

}  // namespace

namespace {

int runReportingErrors(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::bad_alloc&) {
        std::cerr << "kerf: error: out of memory\n";
    } catch (const std::exception& e) {
        std::cerr << "kerf: error: " << e.what() << "\n";
    } catch (...) {
        std::cerr << "kerf: error: unknown failure\n";
    }
    return kExitFailure;
}

}  // namespace

int main(int argc, char** argv) {
    // The process ends only after TBB's worker threads have, so no worker still runs while exit
    // handlers and the sanitizers' exit-time checks do.
    tbb::task_scheduler_handle workers{tbb::attach{}};
    const int code = runReportingErrors(argc, argv);
    tbb::finalize(workers, std::nothrow);
    return code;
}
