/// @file csg/interval/scalar_ops.h
/// @brief The meaning of each expression Op on doubles: shared by constant folding in the
/// expression graph and by the point evaluator, so both agree bit for bit.
#pragma once

#include <algorithm>
#include <cmath>

#include "csg/tape/expr.h"

namespace kerf {

/// op(a, b) on doubles (or long doubles, for references); `value` is the PowInt exponent. Const and
/// the variables are not handled here (they have no operands).
template <class T>
inline T applyScalarOp(Op op, T a, T b, double value) {
    switch (op) {
        case Op::Neg: return -a;
        case Op::Square: return a * a;
        case Op::Sqrt: return std::sqrt(a);
        case Op::Abs: return std::fabs(a);
        case Op::Sin: return std::sin(a);
        case Op::Cos: return std::cos(a);
        case Op::Tan: return std::tan(a);
        case Op::Asin: return std::asin(a);
        case Op::Acos: return std::acos(a);
        case Op::Atan: return std::atan(a);
        case Op::Exp: return std::exp(a);
        case Op::Log: return std::log(a);
        case Op::Floor: return std::floor(a);
        case Op::Ceil: return std::ceil(a);
        case Op::Add: return a + b;
        case Op::Sub: return a - b;
        case Op::Mul: return a * b;
        case Op::Div: return a / b;
        case Op::Pow: return std::pow(a, b);
        case Op::Atan2: return std::atan2(a, b);
        case Op::Min: return a < b ? a : b;  // std::min without naming T twice
        case Op::Max: return a > b ? a : b;
        case Op::PowInt: return std::pow(a, static_cast<int>(value));
        default: return a;
    }
}

/// True for ops whose operand order does not matter (used to canonicalise before hashing).
inline bool isCommutative(Op op) {
    return op == Op::Add || op == Op::Mul || op == Op::Min || op == Op::Max;
}

}  // namespace kerf
