/// @file app/cli_voxelize.cpp
#include "app/cli_voxelize.h"

#include "app/exit_codes.h"
#include "app/model_loader.h"
#include "app/option_text.h"
#include "app/output_paths.h"
#include "csg/stopwatch.h"
#include "io/atomic_file.h"
#include "volume/export/voxelize.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace kerf::app {

namespace {

bool endsWithVdb(const std::string& path) {
    if (path.size() < 4) return false;
    std::string tail = path.substr(path.size() - 4);
    for (char& c : tail) c = char(std::tolower(static_cast<unsigned char>(c)));
    return tail == ".vdb";
}

void printVoxelizeStats(const VoxelizeStats& s, double secondsCompile, double secondsTotal,
                        std::ostream& out) {
    char line[320];
    out << "kerf voxelize statistics\n";
    for (const VoxelizedGrid& g : s.grids) {
        std::snprintf(
            line, sizeof line,
            "  %s: %llu active voxels (estimated %llu), dense alternative %.4g voxels "
            "(%.4g x the active ones); %llu cells classified, %llu boundary blocks of "
            "8^3, %llu triangles, %llu distance queries; %.3f s (mesh %.3f s, band %.3f s)\n",
            g.name.c_str(), (unsigned long long)g.activeVoxels,
            (unsigned long long)g.estimatedVoxels, g.denseVoxels,
            g.activeVoxels ? g.denseVoxels / double(g.activeVoxels) : 0.0,
            (unsigned long long)g.cellsClassified, (unsigned long long)g.boundaryBlocks,
            (unsigned long long)g.triangles, (unsigned long long)g.distanceQueries, g.seconds,
            g.secondsMesh, g.secondsBand);
        out << line;
    }
    std::snprintf(line, sizeof line, "  time: compile %.3f s, write %.3f s, total %.3f s\n",
                  secondsCompile, s.secondsWrite, secondsTotal);
    out << line;
}

}  // namespace

CLI::App* addVoxelizeCommand(CLI::App& parent, VoxelizeCommandLine& line) {
    CLI::App* cmd = parent.add_subcommand(
        "voxelize", "Write each solid object as an OpenVDB narrow-band level set (.vdb)");
    cmd->add_option("FILE", line.model, "The model file (.kerf or .csg)")->required();
    cmd->add_option("-o,--output", line.output, "The .vdb file")->required();
    cmd->add_option("--voxel", line.voxel, "Voxel size in model units (> 0)")->required();
    cmd->add_option("--band", line.band, "Half-width of the narrow band in voxels (1 to 16; 3)");
    cmd->add_option("--max-voxels", line.maxVoxels,
                    "Refuse when more active voxels than this are estimated (2^24)");
    cmd->add_flag("--stats", line.stats,
                  "Print per grid the active voxels, the dense alternative, cells and times");
    cmd->add_flag("-q,--quiet", line.quiet, "No echo lines from the model");
    return cmd;
}

int runVoxelize(const VoxelizeCommandLine& line) {
    const auto start = std::chrono::steady_clock::now();
    VoxelizeOptions options;
    options.voxel = numberOption("--voxel", line.voxel);
    options.band = numberOption("--band", line.band);
    if (!std::isfinite(options.voxel) || !(options.voxel > 0.0))
        throw UsageError("--voxel must be a finite number greater than 0 (got '" + line.voxel +
                         "')");
    if (!(options.band >= kVoxelizeMinBand && options.band <= kVoxelizeMaxBand))
        throw UsageError("--band must be a number of voxels from 1 to 16 (got '" + line.band +
                         "')");
    if (!line.maxVoxels.empty()) {
        const double n = numberOption("--max-voxels", line.maxVoxels);
        if (!(n >= 1.0 && n <= 9.0e18) || n != std::floor(n))
            throw UsageError("--max-voxels must be a whole number of at least 1 (got '" +
                             line.maxVoxels + "')");
        options.maxVoxels = uint64_t(n);
    }
    if (!endsWithVdb(line.output))
        throw UsageError("-o: the output must end in .vdb (got '" + line.output + "')");
    if (samePath(line.output, line.model))
        throw UsageError("-o: the output '" + line.output + "' is the model file");
    checkOutputWritable(line.output);  // before any work: exit 1, nothing done

    const std::optional<Scene> scene = loadModel(line.model, std::cerr, line.quiet);
    if (!scene) return kExitUsage;
    checkNotAnInput("-o", line.output, processAssets().inputs());
    const double secondsCompile = secondsSince(start);

    VoxelizeStats stats;
    try {
        stats = voxelizeToFile(scene->objects, options, line.output);
    } catch (const VoxelizeInputError& e) {
        throw UsageError(e.what());
    }
    for (const VoxelizeSkip& skip : stats.skipped)
        std::cerr << "kerf: note: " << objectGridName(skip.object) << " left out: " << skip.reason
                  << "\n";
    if (line.stats) printVoxelizeStats(stats, secondsCompile, secondsSince(start), std::cerr);
    return kExitSuccess;
}

}  // namespace kerf::app
