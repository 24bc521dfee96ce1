// The acceleration rule: which objects get an octree.
#include "volume/octree/accelerate.h"

#include "csg/primitives/surfaces.h"

namespace kerf {

const char* accelName(Accel accel) {
    switch (accel) {
        case Accel::Auto: return "auto";
        case Accel::None: return "none";
        case Accel::Bvh: return "bvh";
        case Accel::Octree: return "octree";
    }
    return "?";
}

std::optional<Accel> parseAccel(const std::string& name) {
    for (Accel a : {Accel::Auto, Accel::None, Accel::Bvh, Accel::Octree})
        if (name == accelName(a)) return a;
    return std::nullopt;
}

AcceleratedObjects accelerate(const std::vector<NodePtr>& objects, Accel accel,
                              const OctreeOptions& options) {
    AcceleratedObjects out;
    out.objectBvh = accel != Accel::None;
    out.objects.reserve(objects.size());
    for (const NodePtr& o : objects) {
        // A surface (csg/primitives/surfaces.h) has no inside for the octree's cells to classify; a
        // tree with a mesh or a profile (Op::Field) keeps its own search (hasExternalField).
        const bool octree =
            (accel == Accel::Octree && !isSurfaceTree(*o) && !hasExternalField(o)) ||
            (accel == Accel::Auto && octreePays(o, options));
        out.objects.push_back(octree ? withOctree(o, options) : o);
    }
    return out;
}

}  // namespace kerf
