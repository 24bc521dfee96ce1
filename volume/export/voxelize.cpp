// `kerf voxelize`: the objects sorted into solids to voxelize and ones to leave out, the size
// estimated and checked for all of them before any grid is made, then per object the surface
// mesh (volume/export/mesh_export.h) and its level set (volume/export/vdb_voxelize_writer.h), one
// file.
#include "volume/export/voxelize.h"

#include "csg/primitives/surfaces.h"
#include "csg/stopwatch.h"
#include "csg/tape/tree_tape.h"
#include "io/atomic_file.h"
#include "volume/export/vdb_voxelize_writer.h"
#include "volume/export/voxelize_estimate.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace kerf {

namespace {

std::string number(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

/// An object to voxelize.
struct Planned {
    size_t object;
    std::shared_ptr<const Tape> tape;
    Bounds3 bounds;  ///< empty for an empty solid: an empty grid
    BandEstimate estimate;
};

/// OpenVDB's coordinates are 32-bit: the band round the bounds must stay well inside them.
constexpr double kMaxIndex = double(int64_t(1) << 30);

}  // namespace

std::string objectGridName(size_t index) { return "object_" + std::to_string(index); }

namespace {

void checkOptions(const VoxelizeOptions& options) {
    const double h = options.voxel;
    if (!std::isfinite(h) || !(h > 0.0))
        throw VoxelizeInputError("--voxel must be a finite number greater than 0, not " +
                                 number(h));
    if (!(h * h * h >= kVoxelizeMinVoxelCube))
        throw VoxelizeInputError("--voxel " + number(h) +
                                 " is smaller than an OpenVDB transform "
                                 "can be (its cube must be at least 3e-15, so voxels of at least "
                                 "1.45e-05 model units): scale the model up");
    if (!(options.band >= kVoxelizeMinBand && options.band <= kVoxelizeMaxBand))
        throw VoxelizeInputError("--band must be a number of voxels from " +
                                 number(kVoxelizeMinBand) + " to " + number(kVoxelizeMaxBand) +
                                 ", not " + number(options.band));
}

/// The objects to voxelize, each with its tape; the others are listed in stats.skipped.
std::vector<Planned> planObjects(const std::vector<NodePtr>& objects,
                                 const VoxelizeOptions& options, VoxelizeStats& stats) {
    const double h = options.voxel;
    std::vector<Planned> plan;
    for (size_t i = 0; i < objects.size(); ++i) {
        const Node& object = *objects[i];
        if (isSurfaceTree(object)) {
            stats.skipped.push_back({i, "an open surface, not a solid: it has no inside"});
            continue;
        }
        const Bounds3& b = object.bounds();
        if (!b.empty() && !b.finite()) {
            stats.skipped.push_back({i,
                                     "unbounded (such as a half-space): its level set would "
                                     "have no end"});
            continue;
        }
        Planned p{i, nullptr, b, {}};
        ExprGraph g;
        if (b.empty()) {
            p.tape = Tape::compile(g, g.constant(1.0));  // an empty solid: outside everywhere
        } else {
            const double reach = std::max({std::abs(b.lo.x), std::abs(b.lo.y), std::abs(b.lo.z),
                                           std::abs(b.hi.x), std::abs(b.hi.y), std::abs(b.hi.z)}) /
                                     h +
                                 options.band + 64.0;
            if (!(reach < kMaxIndex))
                throw VoxelizeInputError("--voxel " + number(h) + " is too fine for " +
                                         objectGridName(i) + ": its bounds reach " + number(reach) +
                                         " voxels from the origin, past "
                                         "OpenVDB's 32-bit coordinates (2^30 here)");
            p.tape = Tape::compile(g, treeExpr(object, g, g.x(), g.y(), g.z()));
        }
        plan.push_back(std::move(p));
    }
    if (plan.empty())
        throw VoxelizeInputError(
            "the model has no solid object to voxelize (open surfaces and "
            "unbounded objects are left out)");
    return plan;
}

/// Every object's estimate before any grid is made, so a refusal costs little.
void estimateAll(std::vector<Planned>& plan, const VoxelizeOptions& options) {
    const double h = options.voxel;
    double estimated = 0.0, area = 0.0;
    for (Planned& p : plan) {
        if (p.bounds.empty()) continue;
        p.estimate = estimateBand(p.tape, p.bounds, h, options.band);
        estimated += p.estimate.voxels;
        area += p.estimate.area;
    }
    if (estimated > double(options.maxVoxels))
        throw VoxelizeInputError(
            "about " + number(estimated) + " active voxels estimated at --voxel " + number(h) +
            " (a surface of about " + number(area * h * h) + " square units, " + number(area) +
            " voxel faces, times 2 x --band " + number(options.band) + "), more than the limit " +
            std::to_string(options.maxVoxels) + ": use a larger --voxel or raise --max-voxels");
}

/// One object's surface mesh and level set, added to `file`.
VoxelizedGrid voxelizeObject(const Planned& p, const std::vector<NodePtr>& objects,
                             const VoxelizeOptions& options, LevelSetFile& file) {
    const double h = options.voxel;
    const auto t0 = std::chrono::steady_clock::now();
    VoxelizedGrid grid;
    grid.object = p.object;
    grid.name = objectGridName(p.object);
    grid.estimatedVoxels = uint64_t(p.estimate.voxels);
    grid.cellsClassified = p.estimate.cells;
    WatertightMesh mesh;
    if (!p.bounds.empty()) {
        grid.denseVoxels = 1.0;
        for (int a = 0; a < 3; ++a)
            grid.denseVoxels *= std::max(1.0, std::ceil((p.bounds.hi[a] - p.bounds.lo[a]) / h));
        MeshExportOptions meshOptions;
        meshOptions.voxel = h;
        MeshExportStats meshStats;
        const auto tMesh = std::chrono::steady_clock::now();
        try {
            mesh = exportMesh({objects[p.object]}, meshOptions, meshStats);
        } catch (const MeshInputError& e) {
            throw VoxelizeInputError(grid.name + ": " + e.what());
        }
        grid.secondsMesh = secondsSince(tMesh);
        grid.cellsClassified += meshStats.intervalEvaluations;
        grid.boundaryBlocks = meshStats.boundaryBlocks;
        grid.triangles = mesh.triangles.size();
    }
    const auto tBand = std::chrono::steady_clock::now();
    const LevelSetFile::Added added = file.add(grid.name, mesh, h, options.band, *p.tape);
    grid.activeVoxels = added.activeVoxels;
    grid.distanceQueries = added.distanceQueries;
    grid.secondsBand = secondsSince(tBand);
    grid.seconds = secondsSince(t0);
    return grid;
}

}  // namespace

VoxelizeStats voxelizeToFile(const std::vector<NodePtr>& objects, const VoxelizeOptions& options,
                             const std::string& path) {
    checkOptions(options);
    VoxelizeStats stats;
    std::vector<Planned> plan = planObjects(objects, options, stats);
    estimateAll(plan, options);
    LevelSetFile file;
    for (const Planned& p : plan) stats.grids.push_back(voxelizeObject(p, objects, options, file));

    const auto t0 = std::chrono::steady_clock::now();
    const std::string bytes = file.bytes();
    const std::string problem = replaceFile(path, ".vdb", bytes.data(), bytes.size());
    if (!problem.empty()) throw FileWriteError(cannotWrite(path, problem));
    stats.secondsWrite = secondsSince(t0);
    return stats;
}

}  // namespace kerf
