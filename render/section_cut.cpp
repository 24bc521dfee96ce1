// Section views: objects cut by half-spaces whose boundaries carry the cap material.
#include "render/section_cut.h"

#include "csg/tree/solids.h"

namespace kerf {
namespace {

/// One plane: the half-space dot(normal, p) ≤ offset kept, under its cap material.
struct KeptSide {
    NodePtr halfSpace;  ///< bare, for classifying bounds
    NodePtr capped;     ///< under the cap material, for cutting
    int axis = -1;      ///< a plane x, y or z = offset·normal[axis] (normal ±1 there), or −1
    double at = 0.0;    ///< that coordinate
    double sign = 0.0;  ///< normal[axis]
};

IntervalVec3 boxOf(const Bounds3& b) {
    return {Interval(b.lo.x, b.hi.x), Interval(b.lo.y, b.hi.y), Interval(b.lo.z, b.hi.z)};
}

/// Which side of the plane the box is on: Empty (all removed), Filled (all kept) or
/// Ambiguous. Planes across an axis compare coordinates exactly, so a box with a face in the
/// plane on the kept side is left alone (its face and the cap would be coincident surfaces);
/// other planes take an outward-rounded enclosure (NaN from an unbounded box is Ambiguous).
Classification classify(const KeptSide& side, const Bounds3& box) {
    if (box.empty()) return Classification::Filled;
    if (side.axis < 0) return side.halfSpace->valueInterval(boxOf(box)).classify();
    const double lo = box.lo[side.axis], hi = box.hi[side.axis];
    if (side.sign > 0)
        return lo > side.at    ? Classification::Empty
               : hi <= side.at ? Classification::Filled
                               : Classification::Ambiguous;
    return hi < side.at    ? Classification::Empty
           : lo >= side.at ? Classification::Filled
                           : Classification::Ambiguous;
}

KeptSide keptSide(const SectionPlane& plane, int32_t capMaterial) {
    KeptSide side;
    Vec3 n = plane.normal;
    int nonZero = 0;
    for (int a = 0; a < 3; ++a)
        if (n[a] != 0.0) {
            ++nonZero;
            side.axis = a;
        }
    if (nonZero == 1) {
        // The unit normal of a plane across an axis, exactly: n·p ≤ offset is then exact.
        side.sign = n[side.axis] > 0 ? 1.0 : -1.0;
        side.at = plane.point[side.axis];
        n = Vec3(0.0);
        n[side.axis] = side.sign;
    } else {
        side.axis = -1;
    }
    // dot(n, p) ≤ dot(n, point): the side the normal points away from.
    side.halfSpace = makeHalfSpace(n, glm::dot(n, plane.point));
    side.capped = makeMaterial(side.halfSpace, capMaterial);
    return side;
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
        sides.push_back(keptSide(plane, int32_t(cut.materials.size())));
        cut.materials.push_back(cap);
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
            const Classification c = classify(side, bounds);
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
            // inside the half-spaces' spans (csg/tree/boolean.cpp, guidedFirstSurface).
            NodePtr keep =
                cutters.size() == 1 ? cutters[0] : makeBoolean(BoolOp::Intersection, cutters);
            kept = makeBoolean(BoolOp::Intersection, {object, keep});
        }
        cut.objects.push_back(std::move(kept));
        if (flagged)
            cut.objectFlags.push_back(i < scene.objectFlags.size() ? scene.objectFlags[i]
                                                                   : ObjectFlags{});
    }
    return cut;
}

}  // namespace kerf
