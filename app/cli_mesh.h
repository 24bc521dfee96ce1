/// @file app/cli_mesh.h
/// @brief `kerf mesh FILE -o OUT.{obj,ply,stl} --voxel H [--adaptivity A] [--stats] [--quiet]`:
/// a watertight triangle mesh of the model's bounded objects (volume/export/mesh_export.h).
#pragma once

#include <string>

namespace CLI {
class App;
}  // namespace CLI

namespace kerf::app {

struct MeshCommandLine {
    std::string model;
    std::string output;
    std::string voxel;  ///< parsed here, so "nan" or "-1" get kerf's own message
    std::string adaptivity = "0";
    bool stats = false;
    bool quiet = false;
};

/// Adds the `mesh` subcommand to `parent`, parsing into `line`.
CLI::App* addMeshCommand(CLI::App& parent, MeshCommandLine& line);

/// Runs the command; returns the exit code. Throws UsageError for bad options or a voxel the
/// model cannot be meshed at, FileWriteError for an output that cannot be written; nothing
/// is written in either case.
int runMesh(const MeshCommandLine& line);

}  // namespace kerf::app
