// `kerf mesh`'s pipeline, stage by stage, with the time of each.
#include "volume/export/mesh_export.h"

#include "csg/primitives/surfaces.h"
#include "csg/stopwatch.h"
#include "csg/tape/tree_tape.h"
#include "volume/export/mesh_unpinch.h"
#include "volume/export/vdb_mesh.h"

#include <chrono>
#include <cmath>

namespace kerf {

WatertightMesh exportMesh(const std::vector<NodePtr>& objects, const MeshExportOptions& options,
                          MeshExportStats& stats) {
    stats = MeshExportStats{};
    if (!(options.adaptivity >= 0.0 && options.adaptivity <= 1.0))
        throw MeshInputError("--adaptivity must be a number from 0 to 1");
    // The solid: the union of the bounded objects, as one tape.
    ExprGraph g;
    ExprId solid = -1;
    Bounds3 bounds;
    for (const NodePtr& object : objects) {
        if (isSurfaceTree(*object))
            continue;  // csg/primitives/surfaces.h: a sheet encloses nothing to mesh
        const Bounds3& b = object->bounds();
        if (!b.empty() && !b.finite()) {
            ++stats.unboundedSkipped;
            continue;
        }
        ++stats.objects;
        if (b.empty()) continue;  // an empty solid (say, disjoint parts intersected)
        const ExprId f = treeExpr(*object, g, g.x(), g.y(), g.z());
        solid = solid < 0 ? f : g.binary(Op::Min, solid, f);
        bounds = Bounds3::hull(bounds, b);
    }
    // The voxel is checked before anything else can fail, so its message comes first.
    const MeshLattice lattice =
        meshLattice(bounds.empty() ? Bounds3{Vec3(0.0), Vec3(0.0)} : bounds, options.voxel);
    if (stats.objects == 0)
        throw MeshInputError(
            "the model has no bounded object to mesh (unbounded objects such "
            "as half-spaces are left out)");
    if (solid < 0) return {};  // only empty solids: an empty mesh
    stats.lattice = lattice.points;

    auto t0 = std::chrono::steady_clock::now();
    const SampledField field = sampleField(lattice, Tape::compile(g, solid));
    stats.secondsClassify = secondsSince(t0);
    stats.intervalEvaluations = field.intervalEvaluations;
    stats.boundaryBlocks = field.boundary.size();
    stats.fullRegions = field.full.size();

    t0 = std::chrono::steady_clock::now();
    LatticePolygons polygons = polygonizeField(field, options.adaptivity);
    stats.secondsPolygonize = secondsSince(t0);
    stats.leaves = polygons.leaves;

    t0 = std::chrono::steady_clock::now();
    const std::vector<Vec3> openvdbPoints = polygons.points;
    placeVertices(field, polygons.points, stats.placement);
    splitQuads(field, polygons.points, polygons.quads, polygons.triangles);
    const UnpinchResult unpinched =
        unpinchCreases(field, openvdbPoints, polygons.points, polygons.triangles);
    stats.placement.unpinched = unpinched.replaced;
    stats.crowdedEdges = unpinched.crowdedLeft;
    stats.secondsPlace = secondsSince(t0);

    WatertightMesh mesh{std::move(polygons.points), std::move(polygons.triangles)};
    if (options.measure) {
        t0 = std::chrono::steady_clock::now();
        stats.distance = measureSurfaceDistance(field, mesh.vertices, mesh.triangles);
        stats.meshVolume = enclosedVolume(mesh.vertices, mesh.triangles);
        stats.modelVolume = modelVolumeBounds(field);
        stats.secondsMeasure = secondsSince(t0);
    }
    return mesh;
}

}  // namespace kerf
