// Section views: objects cut by half-spaces whose boundaries carry the cap material.
#include "render/section_cut.h"

#include "csg/solids.h"

namespace kerf {
namespace {

/// One plane: the half-space kept, under its cap material.
struct KeptSide {
    NodePtr halfSpace;  ///< bare, for classifying bounds
    NodePtr capped;     ///< under the cap material, for cutting
};

IntervalVec3 boxOf(const Bounds3& b) {
    return {Interval(b.lo.x, b.hi.x), Interval(b.lo.y, b.hi.y), Interval(b.lo.z, b.hi.z)};
}

}  // namespace

Scene cutBySections(const Scene& scene) {
    Scene cut = scene;
    if (scene.sections.empty()) return cut;
    std::vector<KeptSide> sides;
    for (const SectionPlane& plane : scene.sections) {
        Material cap;
        cap.name = "section cap";
        cap.color = plane.color;
        const int32_t index = int32_t(cut.materials.size());
        cut.materials.push_back(cap);
        // dot(n, p) ≤ dot(n, point): the side the normal points away from.
        NodePtr h = makeHalfSpace(plane.normal, glm::dot(plane.normal, plane.point));
        sides.push_back({h, makeMaterial(h, index)});
    }

    cut.objects.clear();
    cut.objectFlags.clear();
    const bool flagged = !scene.objectFlags.empty();
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const NodePtr& object = scene.objects[i];
        const Bounds3& bounds = object->bounds();
        std::vector<NodePtr> cutters;
        bool removed = false;
        for (const KeptSide& side : sides) {
            // An outward-rounded enclosure of the plane's value over the object's box: Empty
            // proves every point removed, Filled every point kept (NaN, from an unbounded
            // box, is Ambiguous: cut).
            const Classification c = bounds.empty()
                                         ? Classification::Filled
                                         : side.halfSpace->valueInterval(boxOf(bounds)).classify();
            if (c == Classification::Empty) {
                removed = true;
                break;
            }
            if (c == Classification::Ambiguous) cutters.push_back(side.capped);
        }
        if (removed) continue;
        NodePtr kept = object;
        if (!cutters.empty()) {
            // Two operands, the second closed-form only: the intersection searches the object
            // inside the half-spaces' spans (csg/boolean.cpp, guidedFirstSurface).
            NodePtr keep = cutters.size() == 1 ? cutters[0]
                                               : makeBoolean(BoolOp::Intersection, cutters);
            kept = makeBoolean(BoolOp::Intersection, {object, keep});
        }
        cut.objects.push_back(std::move(kept));
        if (flagged) cut.objectFlags.push_back(i < scene.objectFlags.size() ? scene.objectFlags[i]
                                                                           : ObjectFlags{});
    }
    return cut;
}

}  // namespace kerf
