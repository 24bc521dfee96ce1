/// @file lang/value.h
/// @brief What an expression evaluates to while lowering: a number, a vector, a boolean, a
/// string, a list, a solid, or (inside an implicit function) a node of an expression graph
/// over x, y, z. Lists and strings are shared, immutable, so copying a Value is cheap.
#pragma once

#include "csg/tape/expr.h"
#include "csg/tree/node.h"
#include "csg/types.h"

#include <memory>
#include <string>
#include <vector>

namespace kerf {

struct Value;
using ValueList = std::vector<Value>;

struct Value {
    enum class Type : uint8_t { Number, Vector, Field, Bool, String, List, Solid };
    Type type = Type::Number;
    double number = 0.0;  ///< Number; Bool as 0 or 1
    Vec3 vector{0.0};
    ExprId field = -1;                        ///< for Field: the graph node
    std::shared_ptr<const std::string> text;  ///< String
    std::shared_ptr<const ValueList> items;   ///< List
    NodePtr solid;  ///< Solid; null for the empty solid (a union of nothing)

    static Value ofNumber(double v) {
        Value r;
        r.number = v;
        return r;
    }
    static Value ofVector(const Vec3& v) {
        Value r;
        r.type = Type::Vector;
        r.vector = v;
        return r;
    }
    static Value ofField(ExprId id) {
        Value r;
        r.type = Type::Field;
        r.field = id;
        return r;
    }
    static Value ofBool(bool b) {
        Value r;
        r.type = Type::Bool;
        r.number = b ? 1.0 : 0.0;
        return r;
    }
    static Value ofString(std::string s) {
        Value r;
        r.type = Type::String;
        r.text = std::make_shared<const std::string>(std::move(s));
        return r;
    }
    static Value ofList(ValueList items) {
        Value r;
        r.type = Type::List;
        r.items = std::make_shared<const ValueList>(std::move(items));
        return r;
    }
    static Value ofSolid(NodePtr node) {
        Value r;
        r.type = Type::Solid;
        r.solid = std::move(node);
        return r;
    }

    bool truth() const { return number != 0.0; }  ///< for Bool
    const ValueList& list() const { return *items; }
    const std::string& string() const { return *text; }
};

/// "a number", "a vector", "a function of x, y, z", …: for type errors.
inline std::string typeName(Value::Type t) {
    switch (t) {
        case Value::Type::Number: return "a number";
        case Value::Type::Vector: return "a vector";
        case Value::Type::Field: return "a function of x, y, z";
        case Value::Type::Bool: return "a boolean";
        case Value::Type::String: return "a string";
        case Value::Type::List: return "a list";
        case Value::Type::Solid: return "a solid";
    }
    return "a value";
}

}  // namespace kerf
