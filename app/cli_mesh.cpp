/// @file app/cli_mesh.cpp
#include "app/cli_mesh.h"

#include "app/exit_codes.h"
#include "app/model_loader.h"
#include "app/option_text.h"
#include "app/output_paths.h"
#include "csg/stopwatch.h"
#include "io/mesh_writers.h"
#include "volume/export/mesh_export.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>

namespace kerf::app {

namespace {

static_assert(sizeof(Vec3) == 3 * sizeof(double), "vertices are handed to io/ as doubles");

/// The whole of `text` as a number ("nan" and "inf" parse, and are refused later by the range
/// checks with a message that names the option).
void printMeshStats(const MeshExportStats& s, const WatertightMesh& mesh, double secondsCompile,
                    double secondsWrite, double voxel, std::ostream& out) {
    char line[256];
    out << "kerf mesh statistics\n";
    out << "  objects meshed:       " << s.objects << " (" << s.unboundedSkipped
        << " unbounded left out)\n";
    out << "  lattice:              " << s.lattice[0] << " x " << s.lattice[1] << " x "
        << s.lattice[2] << " points\n";
    out << "  interval evaluations: " << s.intervalEvaluations << "\n";
    out << "  boundary blocks:      " << s.boundaryBlocks << " of 8^3 (" << s.leaves
        << " OpenVDB leaves with the ring), " << s.fullRegions << " full regions\n";
    out << "  vertices:             " << mesh.vertices.size() << " (" << s.placement.features
        << " on creases, " << s.placement.projected << " projected, " << s.placement.kept
        << " kept; " << s.placement.unpinched << " crease points given up to unpinch edges)\n";
    out << "  triangles:            " << mesh.triangles.size() << " (" << s.crowdedEdges
        << " edges of more than two faces left)\n";
    std::snprintf(line, sizeof line,
                  "  hausdorff (mesh to surface): %.3e (%.4f voxels), mean %.3e, over %llu points "
                  "(vertices, edge midpoints, centroids), %llu first-order\n",
                  s.distance.hausdorff, s.distance.hausdorff / voxel, s.distance.mean,
                  (unsigned long long)s.distance.samples,
                  (unsigned long long)s.distance.firstOrder);
    out << line;
    std::snprintf(line, sizeof line, "  volume:               mesh %.9g, model in [%.9g, %.9g]\n",
                  s.meshVolume, s.modelVolume.lo, s.modelVolume.hi);
    out << line;
    std::snprintf(line, sizeof line,
                  "  time:                 compile %.3f s, classify+sample %.3f s, "
                  "volume-to-mesh %.3f s, place %.3f s, measure %.3f s, write %.3f s\n",
                  secondsCompile, s.secondsClassify, s.secondsPolygonize, s.secondsPlace,
                  s.secondsMeasure, secondsWrite);
    out << line;
}

}  // namespace

CLI::App* addMeshCommand(CLI::App& parent, MeshCommandLine& line) {
    CLI::App* cmd = parent.add_subcommand(
        "mesh", "Write a watertight triangle mesh of the model's bounded objects");
    cmd->add_option("FILE", line.model, "The model file (.kerf)")->required();
    cmd->add_option("-o,--output", line.output, "The mesh file: .obj, .ply or .stl")->required();
    cmd->add_option("--voxel", line.voxel, "Voxel size in model units (> 0)")->required();
    cmd->add_option("--adaptivity", line.adaptivity,
                    "OpenVDB adaptivity from 0 (uniform, default) to 1 (fewest triangles)");
    cmd->add_flag("--stats", line.stats,
                  "Print counts, times, the distance to the surface and volumes to stderr");
    cmd->add_flag("-q,--quiet", line.quiet, "No echo lines from the model");
    return cmd;
}

int runMesh(const MeshCommandLine& line) {
    MeshExportOptions options;
    options.voxel = numberOption("--voxel", line.voxel);
    options.adaptivity = numberOption("--adaptivity", line.adaptivity);
    options.measure = line.stats;
    if (!std::isfinite(options.voxel) || !(options.voxel > 0.0))
        throw UsageError("--voxel must be a finite number greater than 0 (got '" + line.voxel +
                         "')");
    if (!(options.adaptivity >= 0.0 && options.adaptivity <= 1.0))
        throw UsageError("--adaptivity must be a number from 0 to 1 (got '" + line.adaptivity +
                         "')");
    MeshFormat format;
    if (!meshFormatFromPath(line.output, format))
        throw UsageError("-o: the mesh file must end in .obj, .ply or .stl (got '" + line.output +
                         "')");
    if (samePath(line.output, line.model))
        throw UsageError("-o: the output '" + line.output + "' is the model file");
    checkOutputWritable(line.output);  // before any work: exit 1, nothing done

    const auto compileStart = std::chrono::steady_clock::now();
    const std::optional<Scene> scene = loadModel(line.model, std::cerr, line.quiet);
    if (!scene) return kExitUsage;
    checkNotAnInput("-o", line.output, processAssets().inputs());
    const double secondsCompile = secondsSince(compileStart);

    MeshExportStats stats;
    WatertightMesh mesh;
    try {
        mesh = exportMesh(scene->objects, options, stats);
    } catch (const MeshInputError& e) {
        throw UsageError(e.what());
    }
    if (stats.unboundedSkipped > 0)
        std::cerr << "kerf: warning: left out " << stats.unboundedSkipped
                  << " unbounded object(s) (such as half-spaces): a mesh must be closed\n";
    if (mesh.triangles.empty())
        std::cerr << "kerf: warning: the solid has no surface at this voxel size; '" << line.output
                  << "' holds an empty mesh\n";

    const auto writeStart = std::chrono::steady_clock::now();
    MeshArrays arrays;
    arrays.xyz = mesh.vertices.empty() ? nullptr : &mesh.vertices[0].x;
    arrays.vertexCount = mesh.vertices.size();
    arrays.indices = mesh.triangles.empty() ? nullptr : mesh.triangles[0].data();
    arrays.triangleCount = mesh.triangles.size();
    writeMeshFile(line.output, format, arrays);
    const double secondsWrite = secondsSince(writeStart);
    if (line.stats)
        printMeshStats(stats, mesh, secondsCompile, secondsWrite, options.voxel, std::cerr);
    return kExitSuccess;
}

}  // namespace kerf::app
