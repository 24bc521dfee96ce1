/// @file app/cli_check.cpp
#include "app/cli_check.h"

#include "app/exit_codes.h"
#include "app/model_loader.h"
#include "csg/format.h"
#include "csg/tree_stats.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

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
    return "x " + axisRange(b.lo.x, b.hi.x, scale) + "  y " + axisRange(b.lo.y, b.hi.y, scale) + "  z " +
           axisRange(b.lo.z, b.hi.z, scale);
}

}  // namespace

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
    out << "  materials:   " << declaredMaterials << " (plus the default)\n";
    out << "  lights:      " << scene.lights.size() << "\n";
    // Instanced first: what a ray may meet, as the tree would be written out in full.
    out << "  primitives:  " << (trees.instancesSaturated ? "more than " : "") << trees.instances << " ("
        << trees.primitives << " unique)\n";
    out << "  csg depth:   " << trees.depth << "\n";
    out << "  bounds:      " << describeBounds(bounds) << "\n";
    out << "  mist:        " << (scene.mist.enabled ? "yes" : "no") << "\n";
    out << "  render:      " << r.width << " x " << r.height << ", spp " << r.spp
        << ", max depth " << r.maxDepth << "\n";
}

int runCheck(const CheckCommandLine& line) {
    const std::optional<Scene> scene = loadModel(line.model, std::cerr, line.quiet);
    if (!scene) return kExitUsage;
    printSceneSummary(line.model, *scene, std::cout);
    return kExitSuccess;
}

}  // namespace kerf::app
