/// @file csg/tape/expr.h
/// @brief Expression graphs over x, y, z: hash-consed, so equal subexpressions are one node.
/// Built by lang/ for `implicit { f … }` and compiled into a Tape (csg/tape/tape.h).
#pragma once

#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

namespace kerf {

class ScalarField;

enum class Op : uint8_t {
    Const,
    VarX,
    VarY,
    VarZ,
    // unary
    Neg,
    Square,
    Sqrt,
    Abs,
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Exp,
    Log,
    Floor,
    Ceil,
    // binary
    Add,
    Sub,
    Mul,
    Div,
    Pow,
    Atan2,
    Min,
    Max,
    // binary with an integer exponent held in `value`: a^n
    PowInt,
    // ternary: gradient noise at the point (a, b, c) (csg/tape/noise.h), its seed held in `value`
    Noise,
    // ternary: an external field at the point (a, b, c) (csg/tape/scalar_field.h); `value` holds
    // its index in the graph's (and the tape's) field table
    Field,
};

/// One node of the graph. Operands are indices of earlier nodes (-1 when unused).
struct ExprNode {
    Op op = Op::Const;
    int32_t a = -1;
    int32_t b = -1;
    int32_t c = -1;      ///< the third operand of Noise and Field
    double value = 0.0;  ///< the constant for Const, the exponent for PowInt, Noise's seed
};

using ExprId = int32_t;

class ExprGraph {
public:
    ExprId constant(double v);
    ExprId x();
    ExprId y();
    ExprId z();
    ExprId unary(Op op, ExprId a);
    ExprId binary(Op op, ExprId a, ExprId b);
    ExprId add(ExprId a, ExprId b) { return binary(Op::Add, a, b); }
    ExprId sub(ExprId a, ExprId b) { return binary(Op::Sub, a, b); }
    ExprId mul(ExprId a, ExprId b) { return binary(Op::Mul, a, b); }
    ExprId powInt(ExprId a, int n);
    /// Gradient noise at (x, y, z) with the given seed (an integer below 2⁵³, so that the
    /// double `value` holds it exactly).
    ExprId noise(ExprId x, ExprId y, ExprId z, uint64_t seed);
    /// The field at (x, y, z). One field object gets one table index however often it is used.
    ExprId field(ExprId x, ExprId y, ExprId z, std::shared_ptr<const ScalarField> field);

    const std::vector<ExprNode>& nodes() const { return mNodes; }
    /// The fields Op::Field nodes name by index.
    const std::vector<std::shared_ptr<const ScalarField>>& fields() const { return mFields; }

private:
    ExprId intern(const ExprNode& n);
    std::vector<ExprNode> mNodes;
    std::vector<std::shared_ptr<const ScalarField>> mFields;
    std::unordered_map<uint64_t, std::vector<ExprId>> mIndex;  // hash -> candidates
};

}  // namespace kerf
