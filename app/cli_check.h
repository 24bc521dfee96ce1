/// @file app/cli_check.h
/// @brief `kerf check FILE`: parse and compile a model and print a summary of the scene.
#pragma once

#include "scene/scene.h"

#include <iosfwd>
#include <string>

namespace CLI {
class App;
}  // namespace CLI

namespace kerf::app {

struct CheckCommandLine {
    std::string model;
    bool quiet = false;  ///< leave out the model's echo lines
};

/// Adds the `check` subcommand to `parent`, parsing into `line`.
CLI::App* addCheckCommand(CLI::App& parent, CheckCommandLine& line);

/// Prints the summary of a compiled scene: objects, materials, lights, primitives, the
/// deepest CSG tree, the bounds of everything, the render settings and the meshes' reports.
void printSceneSummary(const std::string& model, const Scene& scene, std::ostream& out);

/// Per mesh file the scene uses (once each, in the order of first use): the validation
/// counts (mesh/half_edges.h), whether it is a solid, its first bad edge, its BVH's nodes.
/// Prints nothing for a scene without meshes.
void printMeshReports(const Scene& scene, std::ostream& out);
/// For each level set the scene reads (`volume "file.vdb"`): its grid, voxel size, active
/// voxels and bounds.
void printVolumeReports(const Scene& scene, std::ostream& out);

/// Runs the command; returns the exit code (0 valid, 2 with diagnostics otherwise).
int runCheck(const CheckCommandLine& line);

}  // namespace kerf::app
