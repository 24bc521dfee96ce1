// The material of a point inside a solid, by a walk down the tree.
#include "slice/material_at.h"

#include <variant>

namespace kerf {

int32_t materialAt(const Node& node, const Vec3& p, int32_t inherited) {
    const NodeKind kind = node.kind();
    if (isLeaf(kind)) return inherited;
    const NodeSpan kids = node.children();
    switch (kind) {
        case NodeKind::Material:
            return materialAt(*kids[0], p, std::get<MaterialParams>(node.params()).material);
        case NodeKind::Transform:
            return materialAt(*kids[0],
                              std::get<TransformParams>(node.params()).localFromWorld.point(p),
                              inherited);
        case NodeKind::Motion:  // as at scene time 0, where a motion leaves its child unmoved
            return materialAt(*kids[0], p, inherited);
        case NodeKind::Difference:  // the body's material; the cutters only remove
            return materialAt(*kids[0], p, inherited);
        default: {
            // Union, xor: the first child holding p (least value if none does, for rounding at
            // the boundary). Intersection: every child holds p; the first speaks for it.
            size_t best = 0;
            double bestValue = kids[0]->value(p);
            for (size_t i = 0; i < kids.size() && bestValue > 0.0; ++i) {
                const double v = kids[i]->value(p);
                if (v < bestValue) {
                    best = i;
                    bestValue = v;
                }
            }
            return materialAt(*kids[best], p, inherited);
        }
    }
}

}  // namespace kerf
