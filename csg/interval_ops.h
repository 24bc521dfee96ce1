/// @file csg/interval_ops.h
/// @brief The meaning of each expression Op on intervals: shared by the interval evaluator and
/// the interval-along-a-ray evaluator.
#pragma once

#include "csg/expr.h"
#include "csg/interval.h"

namespace kerf {

/// op(a, b) on intervals; `value` is the PowInt exponent. Const and the variables are not
/// handled here (they have no operands).
inline Interval applyIntervalOp(Op op, const Interval& a, const Interval& b, double value) {
    switch (op) {
        case Op::Neg:
            return -a;
        case Op::Square:
            return sqr(a);
        case Op::Sqrt:
            return sqrt(a);
        case Op::Abs:
            return abs(a);
        case Op::Sin:
            return sin(a);
        case Op::Cos:
            return cos(a);
        case Op::Tan:
            return tan(a);
        case Op::Asin:
            return asin(a);
        case Op::Acos:
            return acos(a);
        case Op::Atan:
            return atan(a);
        case Op::Exp:
            return exp(a);
        case Op::Log:
            return log(a);
        case Op::Floor:
            return floor(a);
        case Op::Ceil:
            return ceil(a);
        case Op::Add:
            return a + b;
        case Op::Sub:
            return a - b;
        case Op::Mul:
            return a * b;
        case Op::Div:
            return a / b;
        case Op::Pow:
            return pow(a, b);
        case Op::Atan2:
            return atan2(a, b);
        case Op::Min:
            return min(a, b);
        case Op::Max:
            return max(a, b);
        case Op::PowInt:
            return powInt(a, static_cast<int>(value));
        default:
            return a;
    }
}

}  // namespace kerf
