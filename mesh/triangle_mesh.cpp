// The indexed triangle mesh's own helpers.
#include "mesh/triangle_mesh.h"

namespace kerf {

Bounds3 meshBounds(const TriangleMesh& mesh) {
    Bounds3 box;
    for (const auto& t : mesh.triangles)
        for (uint32_t v : t) box.extend(mesh.positions[v]);
    return box;
}

}  // namespace kerf
