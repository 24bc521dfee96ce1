// The mist bake, at render time (render/medium_bake.h).
#include "render/medium_bake.h"

#include "volume/grids/bricked_field.h"

#include <algorithm>
#include <stdexcept>

namespace kerf {

Scene withBakedMedium(const Scene& scene) {
    Scene baked = scene;
    Medium& medium = baked.medium;
    if (!medium.bake || !medium.density) return baked;
    const std::shared_ptr<const ScalarField> exact = medium.density;
    try {
        medium.density =
            bakeField([exact](const Vec3& p) { return std::max(0.0, exact->value(p)); },
                      medium.bounds, medium.bake->resolution);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(medium.bake->where +
                                    ": cannot bake the mist density: " + e.what());
    }
    medium.bake.reset();
    return baked;
}

}  // namespace kerf
