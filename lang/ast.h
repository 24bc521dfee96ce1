/// @file lang/ast.h
/// @brief The syntax tree of a model file, as the parser builds it: plain data, every node
/// with the SourcePos that diagnostics point at. No meaning is checked here (lower.h does that).
///
/// A model can hold millions of nodes, so the tree is laid out for memory (docs/robustness.md,
/// "Parse memory"): positions are 8-byte offsets (DiagnosticSink::locate finds line and
/// column); expressions (40 bytes) and solids are values in the program's arena, each node's
/// operands, children, properties and modifiers stored side by side; names are interned there.
#pragma once

#include "lang/ast_arena.h"
#include "lang/diagnostic.h"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace kerf {

/// Nodes side by side in the arena: the operands of an expression, the children, properties
/// and modifiers of a solid. Read like a const std::vector.
template <class T>
class ArenaList {
public:
    ArenaList() = default;
    ArenaList(const T* first, uint32_t count) : mFirst(first), mCount(count) {}
    const T* begin() const { return mFirst; }
    const T* end() const { return mFirst + mCount; }
    size_t size() const { return mCount; }
    bool empty() const { return mCount == 0; }
    const T& operator[](size_t i) const { return mFirst[i]; }
    const T& at(size_t i) const {
        if (i >= mCount) throw std::out_of_range("ArenaList::at");
        return mFirst[i];
    }

private:
    const T* mFirst = nullptr;
    uint32_t mCount = 0;
};

struct Expr;
using ExprList = ArenaList<Expr>;

/// An arithmetic expression. Trivially copyable: it lives in the arena and is never destroyed.
struct Expr {
    enum class Kind : uint8_t {
        Number,  ///< `number`
        Vector,  ///< `<args[0], args[1], args[2]>`
        Name,    ///< `name`: a let, pi, or x/y/z inside an implicit function
        Negate,  ///< `-args[0]`
        Binary,  ///< `args[0] op args[1]`, op one of + - * / % ^, comparisons < > l(<=) g(>=)
                 ///< e(==) n(!=), and the short-circuit logic & (and) | (or)
        Call,    ///< `name(args…)`; a named argument is a NamedArg in args
        Bool,    ///< `true` / `false` (number 1 or 0)
        String,  ///< `"text"` (ident: the text, interned)
        List,    ///< `[args…]`
        Not,     ///< `not args[0]`
        Choose,  ///< `args[0] ? args[1] : args[2]`
        Index,   ///< `args[0][args[1]]`
        Member,  ///< `args[0].ident` (x, y or z)
        Range,   ///< `args[0] .. args[1]`, `step args[2]` when there are three
        Comprehension,  ///< `[for ident in args[0] (if args[2])?: args[1]]`
        SolidValue,     ///< a solid written where a value goes: `sphere { … }`
        NamedArg,       ///< `ident = args[0]`, only as an argument of a Call
    };
    Kind kind = Kind::Number;
    char op = 0;
    uint16_t depth = 1;  ///< height of this subtree, bounded by the parser (kMaxExpressionDepth)
    uint32_t count = 0;  ///< Number: bytes of the literal (DiagnosticSink::textAt); else of args
    SourcePos loc;       ///< the literal, the name, the operator, or the function name
    SourcePos start;     ///< the first token of the whole expression
    union {
        double number = 0.0;  ///< Number
        const std::string*
            ident;  ///< Name, Call, String, Member, Comprehension, NamedArg (interned)
        const struct Solid* solid;  ///< SolidValue
    };
    const Expr* first = nullptr;  ///< the operands, `count` of them side by side

    bool hasIdent() const {
        return kind == Kind::Name || kind == Kind::Call || kind == Kind::String ||
               kind == Kind::Member || kind == Kind::Comprehension || kind == Kind::NamedArg;
    }
    Name name() const { return Name(hasIdent() ? ident : nullptr); }
    ExprList args() const {
        return kind == Kind::Number || kind == Kind::Name || kind == Kind::Bool ||
                       kind == Kind::String || kind == Kind::SolidValue
                   ? ExprList()
                   : ExprList(first, count);
    }
};

using ExprPtr = const Expr*;  ///< owned by the program's arena

struct Solid;
using SolidPtr = const Solid*;  ///< owned by the program's arena

/// `name value` inside a block; the value is an expression or (for `bound`) a solid.
struct Property {
    Name name;
    SourcePos loc;             ///< of the name
    ExprPtr expr = nullptr;    ///< set unless the value is a solid
    SolidPtr solid = nullptr;  ///< set when the value is written as `kind { … }`
    SourcePos valueLoc() const;
};

/// A modifier after a solid: `translate v`, `rotate v`, `scale s|v`, `matrix [12 numbers]`,
/// `material NAME`, `displace PATTERN by DEPTH`.
struct Modifier {
    /// Move and Spin: motion over scene time (csg/tree/motion.h), `move <v>`, `spin <degrees>`.
    /// Displace: the solid's surface moved by a pattern (args[0] is the depth).
    /// Interior: `interior MATERIAL`, the material of a back side (csg/primitives/surfaces.h).
    enum class Kind : uint8_t {
        Translate,
        Rotate,
        Scale,
        Matrix,
        Material,
        Move,
        Spin,
        Displace,
        Interior
    };
    Kind kind = Kind::Translate;
    SourcePos loc;  ///< of the keyword
    ExprList args;  ///< one, or twelve for matrix
    Name material;
    SourcePos materialLoc;
    SolidPtr pattern = nullptr;  ///< Displace's pattern, read as a pattern is in a material
};

/// A solid as written. Trivially copyable like Expr: its lists are in the arena.
struct Solid {
    enum class Kind : uint8_t {
        Primitive,  ///< `kind { properties }`; the kind is checked when lowering
        Boolean,    ///< `union|intersection|difference|xor { children }`
        Reference,  ///< the name of a `solid` definition, or of a let or local holding a solid
        Call,       ///< a function call that makes a solid: properties[0].expr is the call
        For,        ///< `for NAME in EXPR { children }`: properties[0] holds NAME and EXPR
        If,         ///< `if EXPR { children }`: properties[0].expr is the condition; an else
                    ///< part is a last child of kind Else
        Else,       ///< `else { children }` (an `else if` is one If child)
    };
    Kind kind = Kind::Primitive;
    SourcePos loc;  ///< of the kind keyword or the name
    Name name;      ///< the primitive kind, the Boolean operation, or the referenced name
    ArenaList<Property> properties;
    ArenaList<Solid> children;
    ArenaList<Modifier> modifiers;
};

struct Statement;
class TreeCopier;

/// The statements inside a top-level `for` or `if` (and its else part).
struct Block {
    std::vector<Statement> body;
    std::vector<Statement> elseBody;
    bool hasElse = false;
};

struct Statement {
    enum class Kind : uint8_t {
        Let,
        SolidDef,
        Object,
        Material,
        Camera,
        Light,
        Mist,
        Background,
        Render,
        Include,
        For,              ///< name: the variable, expr: the range or list, block->body
        If,               ///< expr: the condition, block->body and block->elseBody
        Function,         ///< `fn name(params) = expr;` params are properties (expr: the default)
        Assert,           ///< expr: the condition, properties[0].expr: the message (optional)
        Echo,             ///< properties: the values printed, each expr
        DefaultMaterial,  ///< name: the material
        Section,          ///< properties: point, normal, color (a section plane)
    };
    Kind kind = Kind::Let;
    /// A definition whose body had a syntax error (already reported): its name exists, so
    /// uses are not reported again, but it is not lowered.
    bool broken = false;
    SourcePos loc;     ///< of the keyword
    std::string name;  ///< let/solid/material name, the light kind, or the include path
    SourcePos nameLoc;
    ExprPtr expr = nullptr;          ///< let, background
    SolidPtr solid = nullptr;        ///< solid, object
    ArenaList<Property> properties;  ///< material, camera, light, mist, render, section
    std::unique_ptr<Block> block;    ///< for, if
    /// The statement's own nodes (expr, solid, properties and all below), in one exact-size
    /// block, so that lowering can free them statement by statement (releaseTree).
    std::unique_ptr<std::max_align_t[]> tree;

    /// Moves the statement's nodes out of a scratch arena into its own block; `bound` is at
    /// least their total size (the bytes the scratch arena handed out for this statement).
    void takeTree(size_t bound);
    /// The same, for a statement nested in a block: its nodes go into the enclosing
    /// statement's block through `copier` (ast.cpp).
    void moveTreeWith(TreeCopier& copier);
    /// Frees the nodes; what stays (kind, names, positions, broken) still serves messages.
    void releaseTree();
};

struct Program {
    /// A deque: statements never move once parsed (lowering keeps pointers to them), and
    /// growing it copies nothing.
    std::deque<Statement> statements;
    /// The names the statements use (one arena per file parsed; its blocks are the parser's
    /// scratch space, the nodes themselves live in each Statement::tree).
    std::vector<std::unique_ptr<AstArena>> arenas;
};

inline SourcePos Property::valueLoc() const {
    if (expr) return expr->start;
    if (solid) return solid->loc;
    return loc;
}

}  // namespace kerf
