/// @file lang/value.h
/// @brief What an expression evaluates to while lowering: a number, a vector, or (inside an
/// implicit function) a node of an expression graph over x, y, z.
#pragma once

#include "csg/expr.h"
#include "csg/types.h"

#include <string>

namespace kerf {

struct Value {
    enum class Type { Number, Vector, Field };
    Type type = Type::Number;
    double number = 0.0;
    Vec3 vector{0.0};
    ExprId field = -1;  ///< for Field: the graph node

    static Value ofNumber(double v) { Value r; r.number = v; return r; }
    static Value ofVector(const Vec3& v) { Value r; r.type = Type::Vector; r.vector = v; return r; }
    static Value ofField(ExprId id) { Value r; r.type = Type::Field; r.field = id; return r; }
};

/// "a number", "a vector", "a function of x, y, z": for type errors.
inline std::string typeName(Value::Type t) {
    switch (t) {
        case Value::Type::Number: return "a number";
        case Value::Type::Vector: return "a vector";
        case Value::Type::Field: return "a function of x, y, z";
    }
    return "a value";
}

}  // namespace kerf
