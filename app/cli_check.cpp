/// @file app/cli_check.cpp
#include "app/cli_check.h"

#include "csg/primitives/surfaces.h"

#include "app/exit_codes.h"
#include "app/model_loader.h"
#include "csg/format.h"
#include "csg/tree/tree_stats.h"
#include "mesh/mesh_shape.h"
#include "volume/grids/level_set_grid.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <unordered_set>
#include <variant>
#include <vector>

namespace kerf::app {

namespace {

/// A coordinate of a box whose largest finite coordinate has magnitude `scale`, without the
/// rounding residue of transforms (csg/format.h).
std::string number(double v, double scale) {
    if (std::isinf(v)) return v < 0 ? "-unbounded" : "unbounded";
    return formatDoubleAtScale("%.6g", v, scale);
}

/// One axis of a box: "[lo, hi]", "unbounded" when both ends are infinite, and "unbounded"
/// in place of an infinite end otherwise.
std::string axisRange(double lo, double hi, double scale) {
    if (std::isinf(lo) && std::isinf(hi)) return "unbounded";
    return "[" + (std::isinf(lo) ? std::string("unbounded") : number(lo, scale)) + ", " +
           (std::isinf(hi) ? std::string("unbounded") : number(hi, scale)) + "]";
}

std::string describeBounds(const Bounds3& b) {
    if (b.empty()) return "empty";
    double scale = 0.0;  // the largest finite coordinate
    for (const double v : {b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z})
        if (std::isfinite(v)) scale = std::max(scale, std::fabs(v));
    return "x " + axisRange(b.lo.x, b.hi.x, scale) + "  y " + axisRange(b.lo.y, b.hi.y, scale) +
           "  z " + axisRange(b.lo.z, b.hi.z, scale);
}

/// The distinct shared data (`get` of a node) of the scene's leaves of one kind, in the order
/// the objects first use them. Every node is visited once, however often a shared subtree is
/// used.
template <class T, class Get>
std::vector<const T*> distinctLeafData(const Scene& scene, NodeKind kind, Get get) {
    std::vector<const T*> found;
    std::unordered_set<const Node*> seen;
    std::unordered_set<const T*> seenData;
    std::vector<const Node*> stack;
    for (auto it = scene.objects.rbegin(); it != scene.objects.rend(); ++it)
        stack.push_back(it->get());
    while (!stack.empty()) {
        const Node* node = stack.back();
        stack.pop_back();
        if (!seen.insert(node).second) continue;
        if (node->kind() == kind) {
            const T* data = get(*node);
            if (seenData.insert(data).second) found.push_back(data);
        }
        const NodeSpan children = node->children();
        for (size_t i = children.size(); i-- > 0;) stack.push_back(children[i].get());
    }
    return found;
}

/// The distinct mesh shapes of the scene (`mesh "file"`).
std::vector<const MeshShape*> meshShapes(const Scene& scene) {
    return distinctLeafData<MeshShape>(scene, NodeKind::Mesh, [](const Node& n) {
        return std::get<MeshParams>(n.params()).shape.get();
    });
}

/// The distinct level sets of the scene (`volume "file.vdb"`).
std::vector<const LevelSetGrid*> levelSets(const Scene& scene) {
    return distinctLeafData<LevelSetGrid>(scene, NodeKind::Volume, [](const Node& n) {
        return std::get<VolumeParams>(n.params()).grid.get();
    });
}

}  // namespace

void printVolumeReports(const Scene& scene, std::ostream& out) {
    for (const LevelSetGrid* grid : levelSets(scene)) {
        const LevelSetInfo& info = grid->info();
        const Vec3& h = info.voxelSize;
        out << "  volume '" << info.file << "' grid '" << info.gridName << "':\n";
        out << "    voxel size:           " << number(h.x, h.x);
        if (h.y != h.x || h.z != h.x) out << " x " << number(h.y, h.y) << " x " << number(h.z, h.z);
        out << "\n";
        out << "    active voxels:        " << info.activeVoxels << "\n";
        out << "    bounds (file space):  "
            << describeBounds(info.worldFromIndex.map(grid->insideBounds())) << "\n";
        out << "    bricks:               " << grid->brickCount() << " ("
            << grid->memoryBytes() / 1024 << " KiB)\n";
    }
}

void printMeshReports(const Scene& scene, std::ostream& out) {
    for (const MeshShape* shape : meshShapes(scene)) {
        const MeshReport& r = shape->report();
        out << "  mesh '" << shape->source() << "':\n";
        out << "    vertices:             " << r.vertices << "\n";
        out << "    triangles:            " << r.triangles << "\n";
        out << "    boundary edges:       " << r.boundaryEdges << "\n";
        out << "    non-manifold edges:   " << r.nonManifoldEdges << "\n";
        out << "    inconsistent edges:   " << r.inconsistentEdges
            << " (two faces running an edge the same way)\n";
        out << "    degenerate triangles: " << r.degenerateTriangles << "\n";
        out << "    solid:                "
            << (r.solid ? "yes" : "no (renders as a surface; not a CSG operand)") << "\n";
        if (r.firstBadEdge)
            out << "    first bad edge:       " << describeBadEdge(*r.firstBadEdge) << "\n";
        out << "    BVH nodes:            " << shape->bvh().nodeCount() << "\n";
    }
}

CLI::App* addCheckCommand(CLI::App& parent, CheckCommandLine& line) {
    CLI::App* cmd = parent.add_subcommand("check", "Parse and compile a model; print a summary");
    cmd->add_option("FILE", line.model, "The model file (.kerf)")->required();
    cmd->add_flag("-q,--quiet", line.quiet, "Leave out the model's echo lines");
    return cmd;
}

void printSceneSummary(const std::string& model, const Scene& scene, std::ostream& out) {
    // One memoised walk over all objects: shared subtrees are visited once, however often
    // they are used (a subtree doubled 31 times used to take 2^31 visits and overflow an int).
    const TreeStats trees = treeStats(scene.objects);
    Bounds3 bounds;  // empty until the first object
    for (const NodePtr& object : scene.objects) bounds = Bounds3::hull(bounds, object->bounds());
    // materials[0] is the built-in default; the others are the model's own.
    const size_t declaredMaterials = scene.materials.empty() ? 0 : scene.materials.size() - 1;
    const RenderSettings& r = scene.settings;

    out << model << ": ok\n";
    out << "  objects:     " << scene.objects.size() << "\n";
    size_t surfaces = 0;  // csg/primitives/surfaces.h: rendered, but not sliced nor meshed
    for (const NodePtr& object : scene.objects) surfaces += isSurfaceTree(*object) ? 1 : 0;
    if (surfaces > 0) out << "  surfaces:    " << surfaces << " (no inside: left out of slices)\n";
    out << "  materials:   " << declaredMaterials << " (plus the default)\n";
    out << "  lights:      " << scene.lights.size() << "\n";
    // Instanced first: what a ray may meet, as the tree would be written out in full.
    out << "  primitives:  " << (trees.instancesSaturated ? "more than " : "") << trees.instances
        << " (" << trees.primitives << " unique)\n";
    out << "  csg depth:   " << trees.depth << "\n";
    out << "  bounds:      " << describeBounds(bounds) << "\n";
    out << "  mist:        " << (scene.mist.enabled ? "yes" : "no") << "\n";
    out << "  render:      " << r.width << " x " << r.height << ", spp " << r.spp << ", max depth "
        << r.maxDepth << "\n";
    printMeshReports(scene, out);
    printVolumeReports(scene, out);
}

int runCheck(const CheckCommandLine& line) {
    const std::optional<Scene> scene = loadModel(line.model, std::cerr, line.quiet);
    if (!scene) return kExitUsage;
    printSceneSummary(line.model, *scene, std::cout);
    return kExitSuccess;
}

}  // namespace kerf::app
