// The acceleration rule: which objects get an octree.
#include "volume/accelerate.h"

#include "csg/surfaces.h"

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
        // A surface (csg/surfaces.h) has no inside for the octree's cells to classify.
        const bool octree = (accel == Accel::Octree && !isSurfaceTree(*o)) ||
                            (accel == Accel::Auto && octreePays(o, options));
        out.objects.push_back(octree ? withOctree(o, options) : o);
    }
    return out;
}

}  // namespace kerf
