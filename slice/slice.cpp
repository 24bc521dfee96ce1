// The scene's section: objects contoured, loops grouped into regions and material layers.
#include "slice/slice.h"

#include "csg/primitives/surfaces.h"

#include "slice/material_at.h"
#include "slice/mesh_section.h"
#include "slice/section_tape.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

namespace kerf {

struct SceneSlicer::Object {
    NodePtr node;
    std::shared_ptr<const Tape> tape;
    Bounds3 bounds;
    std::shared_ptr<const PlacedMesh> mesh;  ///< set when the object is one mesh: cut exactly
};

namespace {

double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

bool pointInLoop(const SectionLoop& loop, double x, double y) {
    bool in = false;
    const auto& p = loop.points;
    for (size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
        if ((p[i][1] > y) != (p[j][1] > y) &&
            x < (p[j][0] - p[i][0]) * (y - p[i][1]) / (p[j][1] - p[i][1]) + p[i][0])
            in = !in;
    }
    return in;
}

/// The rectangle padded by a sixteenth of its size (at least the tolerance), so the boundary
/// lies strictly inside it even where the bounds are tight.
PlaneRect padded(PlaneRect r, double tolerance) {
    const double pad =
        std::max(0.0625 * std::max(r.maxU - r.minU, r.maxV - r.minV), 4.0 * tolerance);
    return {r.minU - pad, r.minV - pad, r.maxU + pad, r.maxV + pad};
}

/// The section's loops as regions: each hole goes with the smallest outer loop holding it.
struct Regions {
    std::vector<double> area;                  ///< signed: outer loops positive, holes negative
    std::vector<size_t> outers;                ///< the loops that begin a region
    std::vector<std::vector<size_t>> holesOf;  ///< by outer loop
};

Regions groupRegions(const std::vector<SectionLoop>& loops) {
    Regions r;
    r.area.resize(loops.size());
    for (size_t i = 0; i < loops.size(); ++i) {
        r.area[i] = loopArea(loops[i]);
        if (r.area[i] > 0.0) r.outers.push_back(i);
    }
    r.holesOf.resize(loops.size());
    for (size_t i = 0; i < loops.size(); ++i) {
        if (r.area[i] > 0.0) continue;
        const auto& p = loops[i].points[0];
        size_t best = SIZE_MAX;
        for (const size_t o : r.outers)
            if ((best == SIZE_MAX || r.area[o] < r.area[best]) && pointInLoop(loops[o], p[0], p[1]))
                best = o;
        if (best != SIZE_MAX)
            r.holesOf[best].push_back(i);
        else
            r.outers.push_back(i);  // no outer around it (should not happen): keep it alone
    }
    return r;
}

/// The material just inside an outer loop: probed left of its longest segment, at growing
/// distances until the point is inside the object (0 if none is).
int32_t materialInside(const SectionLoop& outer, const Node& node, const SlicePlane& plane,
                       double tolerance) {
    const auto& pts = outer.points;
    size_t longest = 0;
    double len = -1.0;
    for (size_t i = 0; i < pts.size(); ++i) {
        const auto& a = pts[i];
        const auto& b = pts[(i + 1) % pts.size()];
        const double l = std::hypot(b[0] - a[0], b[1] - a[1]);
        if (l > len) {
            len = l;
            longest = i;
        }
    }
    const auto& a = pts[longest];
    const auto& b = pts[(longest + 1) % pts.size()];
    const double nu = -(b[1] - a[1]) / len, nv = (b[0] - a[0]) / len;
    for (double d = 4.0 * tolerance; d < 0.5 * len + 8.0 * tolerance; d *= 4.0) {
        const Vec3 p = plane.at(0.5 * (a[0] + b[0]) + d * nu, 0.5 * (a[1] + b[1]) + d * nv);
        if (node.value(p) <= 0.0) return materialAt(node, p);
    }
    return 0;
}

/// The drawing's layer of a material, added (named and coloured after it) on first use.
SectionLayer& layerFor(int32_t material, const Scene& scene, std::map<int32_t, size_t>& layerOf,
                       SectionDrawing& drawing) {
    auto [it, added] = layerOf.emplace(material, drawing.layers.size());
    if (added) {
        SectionLayer layer;
        const bool known = material >= 0 && size_t(material) < scene.materials.size();
        layer.name = known ? scene.materials[material].name : "material" + std::to_string(material);
        if (known) {
            const Vec3 c = scene.materials[material].color;
            layer.color = {c.x, c.y, c.z};
        }
        drawing.layers.push_back(std::move(layer));
    }
    return drawing.layers[it->second];
}

/// Moves region `o` (its outer loop and holes) into `layer` and counts it.
void addRegion(std::vector<SectionLoop>& loops, const Regions& regions, size_t o,
               SectionLayer& layer, SliceStats& stats) {
    RegionStats region;
    region.material = layer.name;
    region.area = regions.area[o];
    region.perimeter = loopLength(loops[o]);
    layer.loops.push_back(std::move(loops[o]));
    for (const size_t h : regions.holesOf[o]) {
        region.area += regions.area[h];
        region.perimeter += loopLength(loops[h]);
        ++region.holes;
        layer.loops.push_back(std::move(loops[h]));
    }
    stats.area += region.area;
    stats.perimeter += region.perimeter;
    stats.contours += 1 + region.holes;
    stats.holes += region.holes;
    stats.regions.push_back(std::move(region));
}

}  // namespace

SceneSlicer::SceneSlicer(const Scene& scene, const SlicePlane& family, const SliceOptions& options)
    : mScene(scene), mFamily(family) {
    const auto t0 = std::chrono::steady_clock::now();
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const NodePtr& node = scene.objects[i];
        const Bounds3 b = node->bounds();
        if (b.empty()) continue;
        if (isSurfaceTree(*node)) {  // csg/primitives/surfaces.h: a sheet has no inside to cut
            mNotes.push_back("object " + std::to_string(i + 1) +
                             " is a surface (disc, triangle, open cylinder or cone, surface, "
                             "clip), not a solid; "
                             "left out of the section");
            continue;
        }
        if (!b.finite()) {
            mNotes.push_back(
                "object " + std::to_string(i + 1) +
                " is unbounded (a half-space or infinite solid); left out of the section");
            continue;
        }
        if (auto mesh = placedMeshOf(*node)) {
            if (!mesh->solid) {
                mNotes.push_back(
                    "object " + std::to_string(i + 1) +
                    " is an open mesh (a surface, not a solid); left out of the section");
                continue;
            }
            mBounds.extend(b);
            mObjects.push_back(Object{node, nullptr, b, std::move(mesh)});
            continue;
        }
        mBounds.extend(b);
        mObjects.push_back(Object{node, sectionTape(*node, family), b, nullptr});
    }
    if (!mBounds.empty()) {
        const Vec3 e = mBounds.extent();
        mModelSize = std::max({e.x, e.y, e.z});
        if (!(mModelSize > 0.0)) mModelSize = std::max(1.0, glm::length(mBounds.hi));
    }
    mTolerance = options.tolerance * mModelSize;
    mCompileSeconds = secondsSince(t0);
}

SceneSlicer::~SceneSlicer() = default;

SliceResult SceneSlicer::slice(double w) const {
    SliceResult result;
    SliceStats& stats = result.stats;
    SlicePlane plane = mFamily;
    plane.w = w;
    const PlaneRect sceneRect = planeSectionOfBox(plane, mBounds);
    if (!sceneRect.empty()) {
        result.drawing.minU = sceneRect.minU;
        result.drawing.minV = sceneRect.minV;
        result.drawing.maxU = std::max(sceneRect.maxU, sceneRect.minU + mTolerance);
        result.drawing.maxV = std::max(sceneRect.maxV, sceneRect.minV + mTolerance);
    }
    std::map<int32_t, size_t> layerOf;  // material → layer
    for (const Object& object : mObjects) {
        const PlaneRect rect = planeSectionOfBox(plane, object.bounds);
        if (rect.empty()) continue;
        auto t0 = std::chrono::steady_clock::now();
        ContourOptions co;
        co.tolerance = mTolerance;
        co.rect = padded(rect, mTolerance);
        ContourStats cs;
        std::vector<SectionLoop> loops = object.mesh ? meshSectionLoops(*object.mesh, plane)
                                                     : contourSection(*object.tape, w, co, cs);
        stats.contour.add(cs);
        stats.contourSeconds += secondsSince(t0);
        t0 = std::chrono::steady_clock::now();

        const Regions regions = groupRegions(loops);
        for (const size_t o : regions.outers) {
            const int32_t material = materialInside(loops[o], *object.node, plane, mTolerance);
            addRegion(loops, regions, o, layerFor(material, mScene, layerOf, result.drawing),
                      stats);
        }
        stats.regionSeconds += secondsSince(t0);
    }
    return result;
}

std::vector<SliceResult> SceneSlicer::sliceMany(const std::vector<double>& offsets) const {
    std::vector<SliceResult> results(offsets.size());
    tbb::parallel_for(size_t(0), offsets.size(), [&](size_t i) { results[i] = slice(offsets[i]); });
    return results;
}

}  // namespace kerf
