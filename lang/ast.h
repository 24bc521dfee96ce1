/// @file lang/ast.h
/// @brief The syntax tree of a model file, as the parser builds it: plain data, every node
/// with the SourceLoc that diagnostics point at. No meaning is checked here (lower.h does that).
#pragma once

#include "lang/diagnostic.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace kerf {

struct Expr;
using ExprPtr = std::unique_ptr<Expr>;

/// An arithmetic expression.
struct Expr {
    enum class Kind : uint8_t {
        Number,  ///< `number`
        Vector,  ///< `<args[0], args[1], args[2]>`
        Name,    ///< `name`: a let, pi, or x/y/z inside an implicit function
        Negate,  ///< `-args[0]`
        Binary,  ///< `args[0] op args[1]`, op one of + - * / ^
        Call,    ///< `name(args…)`
    };
    // The small fields first: a model holds millions of these (memory per byte of model).
    Kind kind = Kind::Number;
    char op = 0;
    int depth = 1;  ///< height of this subtree, bounded by the parser
    double number = 0.0;
    SourceLoc loc;    ///< the literal, the name, the operator, or the function name
    SourceLoc start;  ///< the first token of the whole expression
    std::string name;
    std::vector<ExprPtr> args;
};

struct Solid;
using SolidPtr = std::unique_ptr<Solid>;

/// `name value` inside a block; the value is an expression or (for `bound`) a solid.
struct Property {
    std::string name;
    SourceLoc loc;    ///< of the name
    ExprPtr expr;     ///< set unless the value is a solid
    SolidPtr solid;   ///< set when the value is written as `kind { … }`
    const SourceLoc& valueLoc() const;
};

/// A modifier after a solid: `translate v`, `rotate v`, `scale s|v`, `matrix [12 numbers]`,
/// `material NAME`.
struct Modifier {
    enum class Kind { Translate, Rotate, Scale, Matrix, Material };
    Kind kind = Kind::Translate;
    SourceLoc loc;  ///< of the keyword
    std::vector<ExprPtr> args;  ///< one, or twelve for matrix
    std::string material;
    SourceLoc materialLoc;
};

struct Solid {
    enum class Kind {
        Primitive,  ///< `kind { properties }`; the kind is checked when lowering
        Boolean,    ///< `union|intersection|difference|xor { children }`
        Reference,  ///< the name of a `solid` definition
    };
    Kind kind = Kind::Primitive;
    SourceLoc loc;     ///< of the kind keyword or the name
    std::string name;  ///< the primitive kind, the Boolean operation, or the referenced name
    std::vector<Property> properties;
    std::vector<SolidPtr> children;
    std::vector<Modifier> modifiers;
};

struct Statement {
    enum class Kind { Let, SolidDef, Object, Material, Camera, Light, Mist, Background, Render, Include };
    Kind kind = Kind::Let;
    SourceLoc loc;      ///< of the keyword
    std::string name;   ///< let/solid/material name, the light kind, or the include path
    SourceLoc nameLoc;
    ExprPtr expr;       ///< let, background
    SolidPtr solid;     ///< solid, object
    std::vector<Property> properties;  ///< material, camera, light, mist, render
    /// A definition whose body had a syntax error (already reported): its name exists, so
    /// uses are not reported again, but it is not lowered.
    bool broken = false;
};

struct Program {
    std::vector<Statement> statements;
};

inline const SourceLoc& Property::valueLoc() const {
    if (expr) return expr->start;
    if (solid) return solid->loc;
    return loc;
}

}  // namespace kerf
