/// @file csg/primitives/implicit_expr.h
/// @brief Shorthands for writing a primitive's implicit form into an expression graph
/// (Primitive::implicitExpr), in the same order of operations as its value().
#pragma once

#include "csg/tape/expr.h"
#include "csg/types.h"

namespace kerf {

struct ExprBuilder {
    ExprGraph& g;

    ExprId c(double v) { return g.constant(v); }
    ExprId add(ExprId a, ExprId b) { return g.binary(Op::Add, a, b); }
    ExprId sub(ExprId a, ExprId b) { return g.binary(Op::Sub, a, b); }
    ExprId mul(ExprId a, ExprId b) { return g.binary(Op::Mul, a, b); }
    ExprId max(ExprId a, ExprId b) { return g.binary(Op::Max, a, b); }
    ExprId neg(ExprId a) { return g.unary(Op::Neg, a); }
    ExprId sqr(ExprId a) { return g.unary(Op::Square, a); }
    ExprId sqrt(ExprId a) { return g.unary(Op::Sqrt, a); }

    /// k.x·x + k.y·y + k.z·z, left to right, terms with a zero coefficient left out (they
    /// add an exact zero).
    ExprId dot(const Vec3& k, ExprId x, ExprId y, ExprId z) {
        const ExprId v[3] = {x, y, z};
        ExprId sum = -1;
        for (int a = 0; a < 3; ++a) {
            if (k[a] == 0.0) continue;
            const ExprId term = mul(v[a], c(k[a]));
            sum = sum < 0 ? term : add(sum, term);
        }
        return sum < 0 ? c(0.0) : sum;
    }

    /// The point m·(x, y, z) + offset, row by row (as TransformNode::value maps a point).
    void mapPoint(const Affine& m, ExprId x, ExprId y, ExprId z, ExprId out[3]) {
        for (int row = 0; row < 3; ++row)
            out[row] = add(dot(Vec3(m.linear[0][row], m.linear[1][row], m.linear[2][row]), x, y, z),
                           c(m.offset[row]));
    }
};

}  // namespace kerf
