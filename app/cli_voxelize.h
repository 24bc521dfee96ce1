/// @file app/cli_voxelize.h
/// @brief `kerf voxelize FILE -o OUT.vdb --voxel H [--band W] [--max-voxels N] [--stats]
/// [--quiet]`: each solid object as an OpenVDB narrow-band level set (volume/export/voxelize.h).
#pragma once

#include <string>

namespace CLI {
class App;
}  // namespace CLI

namespace kerf::app {

struct VoxelizeCommandLine {
    std::string model;
    std::string output;
    std::string voxel;  ///< parsed here, so "nan" or "-1" get kerf's own message
    std::string band = "3";
    std::string maxVoxels;  ///< empty: kVoxelizeDefaultMaxVoxels
    bool stats = false;
    bool quiet = false;
};

/// Adds the `voxelize` subcommand to `parent`, parsing into `line`.
CLI::App* addVoxelizeCommand(CLI::App& parent, VoxelizeCommandLine& line);

/// Runs the command; returns the exit code. Throws UsageError for bad options or a model that
/// cannot be voxelized at that size, FileWriteError for an output that cannot be written;
/// nothing is written in either case.
int runVoxelize(const VoxelizeCommandLine& line);

}  // namespace kerf::app
