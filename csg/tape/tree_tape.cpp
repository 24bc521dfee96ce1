// A tree compiled into one expression, by a walk over the open tree (kinds, children, params).
#include "csg/tape/tree_tape.h"

#include <variant>

#include "csg/primitives/implicit_expr.h"
#include "csg/primitives/primitive.h"

namespace kerf {

ExprId treeExpr(const Node& node, ExprGraph& g, ExprId x, ExprId y, ExprId z) {
    ExprBuilder e{g};
    const NodeKind kind = node.kind();
    if (isSurfaceKind(kind)) return e.c(1.0);  // csg/primitives/surfaces.h: a sheet has no inside
    if (isLeaf(kind)) {
        const ExprId f = static_cast<const Primitive&>(node).implicitExpr(g, x, y, z);
        if (kind != NodeKind::Implicit) return f;
        // An implicit's value() also holds its bound: max(f, slab distances).
        const Bounds3 b = std::get<ImplicitParams>(node.params()).bound;
        const ExprId v[3] = {x, y, z};
        ExprId outside = f;
        for (int a = 0; a < 3; ++a)
            outside = e.max(outside, e.max(e.sub(e.c(b.lo[a]), v[a]), e.sub(v[a], e.c(b.hi[a]))));
        return outside;
    }
    const NodeSpan kids = node.children();
    // A moving child as at scene time 0, where a motion leaves it unmoved.
    if (kind == NodeKind::Material || kind == NodeKind::Motion || kind == NodeKind::Interior)
        return treeExpr(*kids[0], g, x, y, z);
    if (kind == NodeKind::Transform) {
        // As TransformNode::value: the point mapped by the inverse, row by row.
        ExprId local[3];
        e.mapPoint(std::get<TransformParams>(node.params()).localFromWorld, x, y, z, local);
        return treeExpr(*kids[0], g, local[0], local[1], local[2]);
    }
    // Booleans, left to right as BooleanNode::value combines them.
    ExprId v = treeExpr(*kids[0], g, x, y, z);
    for (size_t i = 1; i < kids.size(); ++i) {
        const ExprId c = treeExpr(*kids[i], g, x, y, z);
        switch (kind) {
            case NodeKind::Union: v = g.binary(Op::Min, v, c); break;
            case NodeKind::Intersection: v = e.max(v, c); break;
            case NodeKind::Difference: v = e.max(v, e.neg(c)); break;
            default: v = e.max(g.binary(Op::Min, v, c), e.neg(e.max(v, c))); break;  // xor
        }
    }
    return v;
}

std::shared_ptr<const Tape> treeTape(const Node& node) {
    ExprGraph g;
    return Tape::compile(g, treeExpr(node, g, g.x(), g.y(), g.z()));
}

}  // namespace kerf
