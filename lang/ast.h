/// @file lang/ast.h
/// @brief The syntax tree of a model file, as the parser builds it: plain data, every node
/// with the SourcePos that diagnostics point at. No meaning is checked here (lower.h does that).
///
/// A model can hold millions of nodes, so the tree is laid out for memory (docs/robustness.md,
/// "Parse memory"): positions are 8-byte offsets (DiagnosticSink::locate finds line and
/// column), expressions are 40-byte values in the program's arena with their operands stored
/// side by side, and names are interned there.
#pragma once

#include "lang/ast_arena.h"
#include "lang/diagnostic.h"

#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <vector>

namespace kerf {

struct Expr;

/// The operands of an expression or a modifier: `count` expressions side by side in the arena.
class ExprList {
public:
    ExprList() = default;
    ExprList(const Expr* first, uint32_t count) : mFirst(first), mCount(count) {}
    const Expr* begin() const { return mFirst; }
    inline const Expr* end() const;
    size_t size() const { return mCount; }
    bool empty() const { return mCount == 0; }
    inline const Expr& operator[](size_t i) const;

private:
    const Expr* mFirst = nullptr;
    uint32_t mCount = 0;
};

/// An arithmetic expression. Trivially copyable: it lives in the arena and is never destroyed.
struct Expr {
    enum class Kind : uint8_t {
        Number,  ///< `number`
        Vector,  ///< `<args[0], args[1], args[2]>`
        Name,    ///< `name`: a let, pi, or x/y/z inside an implicit function
        Negate,  ///< `-args[0]`
        Binary,  ///< `args[0] op args[1]`, op one of + - * / ^
        Call,    ///< `name(args…)`
    };
    Kind kind = Kind::Number;
    char op = 0;
    uint16_t depth = 1;       ///< height of this subtree, bounded by the parser (kMaxExpressionDepth)
    uint32_t count = 0;       ///< Number: bytes of the literal (DiagnosticSink::textAt); else of args
    SourcePos loc;            ///< the literal, the name, the operator, or the function name
    SourcePos start;          ///< the first token of the whole expression
    union {
        double number = 0.0;        ///< Number
        const std::string* ident;   ///< Name, Call (interned)
    };
    const Expr* first = nullptr;  ///< the operands, `count` of them side by side

    Name name() const { return Name(kind == Kind::Name || kind == Kind::Call ? ident : nullptr); }
    ExprList args() const {
        return kind == Kind::Number || kind == Kind::Name ? ExprList() : ExprList(first, count);
    }
};

using ExprPtr = const Expr*;  ///< owned by the program's arena

struct Solid;
using SolidPtr = std::unique_ptr<Solid>;

/// `name value` inside a block; the value is an expression or (for `bound`) a solid.
struct Property {
    Name name;
    SourcePos loc;    ///< of the name
    ExprPtr expr = nullptr;  ///< set unless the value is a solid
    SolidPtr solid;   ///< set when the value is written as `kind { … }`
    SourcePos valueLoc() const;
};

/// A modifier after a solid: `translate v`, `rotate v`, `scale s|v`, `matrix [12 numbers]`,
/// `material NAME`.
struct Modifier {
    enum class Kind : uint8_t { Translate, Rotate, Scale, Matrix, Material };
    Kind kind = Kind::Translate;
    SourcePos loc;  ///< of the keyword
    ExprList args;  ///< one, or twelve for matrix
    Name material;
    SourcePos materialLoc;
};

struct Solid {
    enum class Kind : uint8_t {
        Primitive,  ///< `kind { properties }`; the kind is checked when lowering
        Boolean,    ///< `union|intersection|difference|xor { children }`
        Reference,  ///< the name of a `solid` definition
    };
    Kind kind = Kind::Primitive;
    SourcePos loc;     ///< of the kind keyword or the name
    Name name;         ///< the primitive kind, the Boolean operation, or the referenced name
    std::vector<Property> properties;
    std::vector<SolidPtr> children;
    std::vector<Modifier> modifiers;
};

struct Statement {
    enum class Kind : uint8_t { Let, SolidDef, Object, Material, Camera, Light, Mist, Background, Render, Include };
    Kind kind = Kind::Let;
    /// A definition whose body had a syntax error (already reported): its name exists, so
    /// uses are not reported again, but it is not lowered.
    bool broken = false;
    SourcePos loc;      ///< of the keyword
    std::string name;   ///< let/solid/material name, the light kind, or the include path
    SourcePos nameLoc;
    ExprPtr expr = nullptr;  ///< let, background
    SolidPtr solid;     ///< solid, object
    std::vector<Property> properties;  ///< material, camera, light, mist, render
};

struct Program {
    /// A deque: statements never move once parsed (lowering keeps pointers to them), and
    /// growing it copies nothing.
    std::deque<Statement> statements;
    /// The expressions and names of the statements (one arena per file parsed).
    std::vector<std::unique_ptr<AstArena>> arenas;
};

inline const Expr* ExprList::end() const { return mFirst + mCount; }
inline const Expr& ExprList::operator[](size_t i) const { return mFirst[i]; }

inline SourcePos Property::valueLoc() const {
    if (expr) return expr->start;
    if (solid) return solid->loc;
    return loc;
}

}  // namespace kerf
