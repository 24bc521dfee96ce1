/// @file lang/parser_impl.h
/// @brief The recursive-descent parser's state and its small token helpers, shared by
/// parser.cpp (statements, blocks, solids) and parse_expr.cpp (expressions). Internal to lang/.
#pragma once

#include "lang/diagnostic_hints.h"
#include "lang/parser.h"
#include "lang/positional_values.h"
#include "lang/token_window.h"

#include <algorithm>
#include <array>
#include <functional>
#include <string>
#include <vector>

namespace kerf::parser_detail {

inline const std::array<const char*, 15> kStatementWords = {
    "let",    "solid",   "object", "material", "camera", "light",   "mist",   "background",
    "render", "include", "fn",     "assert",   "echo",   "default", "section"};
/// Words that open a statement but may also stand for a child inside a Boolean body.
inline const std::array<const char*, 2> kBlockWords = {"for", "if"};
inline const std::array<const char*, 4> kBooleanWords = {"union", "intersection", "difference",
                                                         "xor"};
inline const std::array<const char*, 8> kModifierWords = {
    "translate", "rotate", "scale", "matrix", "material", "move", "spin", "interior"};

template <size_t N>
inline bool contains(const std::array<const char*, N>& words, const std::string& w) {
    return std::any_of(words.begin(), words.end(), [&](const char* s) { return w == s; });
}

struct SyntaxError {};

class Parser {
public:
    Parser(std::function<Token()> source, DiagnosticSink& sink)
        : mTokens(std::move(source)), mSink(sink) {}

    Program run() {
        Program program;
        program.arenas.push_back(std::make_unique<AstArena>());
        mArena = program.arenas.back().get();
        while (peek().kind != TokenKind::End) {
            mTokens.dropBefore(mPos > 0 ? mPos - 1
                                        : 0);  // keep the previous token: afterPrevious()
            mArena->reset();  // the last statement's nodes were moved to its own block
            if (accept(TokenKind::Semicolon)) continue;  // an empty statement
            const size_t before = mPos;
            try {
                parseStatement(program);
            } catch (const SyntaxError&) {
                mNesting = 0;
                synchronize();
                if (mPos == before) next();  // always make progress
            }
        }
        return program;
    }

private:
    // ---- the arena: nodes are built as values, then copied into it side by side ----
    template <class T>
    const T* store(const T& node) {
        return mArena->copy(&node, 1);
    }
    template <class T>
    ArenaList<T> list(const T* values, size_t n) {
        return ArenaList<T>(mArena->copy(values, n), static_cast<uint32_t>(n));
    }
    template <class T>
    ArenaList<T> list(const std::vector<T>& values) {
        return list(values.data(), values.size());
    }

    // ---- token access ----
    const Token& peek(size_t ahead = 0) { return mTokens.at(mPos + ahead); }
    bool check(TokenKind k) { return peek().kind == k; }
    bool checkWord(const char* w) { return check(TokenKind::Identifier) && peek().text == w; }
    const Token& next() {
        const Token& t = mTokens.at(mPos);
        if (t.kind == TokenKind::LBrace) ++mBraceDepth;
        if (t.kind == TokenKind::RBrace) --mBraceDepth;
        if (t.kind != TokenKind::End) ++mPos;
        return t;
    }
    bool accept(TokenKind k) {
        if (!check(k)) return false;
        next();
        return true;
    }

    /// Reports (unless the lexer already reported the token here) and abandons the statement.
    [[noreturn]] void fail(const SourceLoc& at, std::string message, std::string hint = {}) {
        if (!check(TokenKind::Error)) mSink.error(at, std::move(message), std::move(hint));
        throw SyntaxError{};
    }
    /// Just after the previous token: where a missing ';' belongs.
    SourceLoc afterPrevious() {
        if (mPos == 0) return peek().loc;
        const Token& previous = mTokens.at(mPos - 1);
        SourceLoc at = previous.loc;
        at.col += previous.length;
        return at;
    }
    const Token& expect(TokenKind k, const std::string& context) {
        if (check(k)) return next();
        const SourceLoc at = k == TokenKind::Semicolon ? afterPrevious() : peek().loc;
        fail(at, "expected " + describe(k) + " " + context + ", found " + describe(peek()));
    }
    const Token& expectName(const std::string& context) {
        if (check(TokenKind::Identifier)) return next();
        fail(peek().loc, "expected " + context + ", found " + describe(peek()));
    }

    /// Counts one level of recursion; deeper than kMaxNesting is an error.
    struct NestingGuard {
        Parser& p;
        explicit NestingGuard(Parser& parser) : p(parser) {
            if (++p.mNesting > kMaxNesting)
                p.fail(p.peek().loc,
                       "nesting too deep (more than " + std::to_string(kMaxNesting) + " levels)",
                       "split the model into named solids or lets");
        }
        ~NestingGuard() { --p.mNesting; }
    };

    bool startsStatement() {
        if (!check(TokenKind::Identifier) || !contains(kStatementWords, peek().text)) return false;
        if (peek().text == "material")  // `material m {` defines; `material m` alone is a modifier
            return peek(1).kind == TokenKind::Identifier && peek(2).kind == TokenKind::LBrace;
        return true;
    }

    /// Skips to the end of the broken statement: past a ';' at statement level, or to the next
    /// statement keyword at statement level or at the start of a line inside braces.
    void synchronize() {
        while (!check(TokenKind::End)) {
            if (mBraceDepth <= 0) {
                if (check(TokenKind::Semicolon) || check(TokenKind::RBrace)) {
                    next();
                    break;
                }
                if (startsStatement()) break;
            } else if (peek().firstOnLine && startsStatement()) {
                break;
            }
            next();
        }
        mBraceDepth = 0;
    }

    // ---- habits from other modellers (lang/diagnostic_hints.h) ----
    /// The hint for another modeller's word where a statement or a solid belongs, or empty.
    std::string foreignHint(const Token& t);
    /// Past the balanced block that starts here (or to the end of the file).
    void skipBlock();
    /// `KIND { properties } modifiers`: a solid texture, kept as a Primitive solid.
    Solid parsePattern();

    // ---- statements, blocks and solids (parser.cpp) ----
    void parseStatement(Program& program);
    void parseStatementBody(Statement& s);
    /// The statements of parseStatementBody that take more than a line: `assert EXPR [,
    /// MESSAGE];`, `echo EXPR, …;`, `object SOLID [no_shadow];` and `background EXPR;` or
    /// `background gradient { … }`.
    void parseAssert(Statement& s);
    void parseEcho(Statement& s);
    void parseObject(Statement& s);
    void parseBackground(Statement& s);
    /// `for NAME in EXPR { statements }` or `if EXPR { … } else if … else { … }` at statement
    /// level. The nested statements keep their nodes in the scratch arena; the outermost
    /// statement's takeTree moves them all.
    void parseBlockStatement(Statement& s, const std::string& word);
    /// `{ statements }` of a block; an optional ';' may follow.
    void parseStatements(std::vector<Statement>& out);
    /// `fn NAME(a, b = default, …) = EXPR;`
    void parseFunction(Statement& s);
    void parseDefinedName(Statement& s, const std::string& what);
    /// `{ name value … }`; an optional ';' may follow the block.
    void parseBlock(ArenaList<Property>& properties);
    ArenaList<Property> parseProperties(const SourceLoc& open);
    /// A solid as a value; its children, properties and modifiers are already in the arena.
    Solid parseSolid(bool withModifiers);
    /// One child of a Boolean body: a solid, or a `for` or `if` around solids.
    Solid parseChild();
    /// True at `mesh` followed by a file name: a string, a name, or an expression in parentheses.
    bool startsMesh();
    /// `mesh FILE (smooth BOOL)? modifiers`: a Primitive named "mesh" whose properties are
    /// file and smooth.
    Solid parseMesh(bool withModifiers);
    /// True at `volume` followed by a file name in quotes (parse_volume.cpp).
    bool startsVolume();
    /// `volume "FILE" (grid NAME)? modifiers`: a Primitive named "volume" whose properties are
    /// file and grid (lowered by lower_volume.cpp).
    Solid parseVolume(bool withModifiers);
    /// True at `surface` or `clip` followed by a solid (parse_surfaces.cpp).
    bool startsSurfaceOp();
    /// `surface SOLID` or `clip SURFACE by SOLID`: a Primitive named "surface" or "clip"
    /// whose children are its operands; modifiers after the clip's solid are the clip's.
    Solid parseSurfaceOp(bool withModifiers);
    std::vector<Solid> parseChildren(const char* what);
    ArenaList<Modifier> parseModifiers();
    /// `[a, b, …]` with commas, or `[a b …]` separated by blanks, where each entry is a single
    /// term (so `[1 -1 …]` is two entries).
    void parseMatrix(Modifier& m);
    bool bracketHasCommas();
    // Expressions are built as values and their operands copied into the arena side by side.
    // Loosest first: c ? a : b, or, and, not, comparisons, ranges, + -, * /, unary -, ^,
    // postfix [i] and .x, primaries.

    // ---- expressions (parse_expr.cpp) ----
    Expr parseExpr();
    Expr parseOr();
    Expr parseAnd();
    Expr parseNot();
    /// The operator code of a comparison token, or 0. Inside a vector's components '>' and
    /// '>=' close the vector instead (write comparisons there in parentheses).
    char comparisonCode();
    Expr parseComparison();
    Expr parseRange();
    Expr parseAdditive();
    Expr parseTerm();
    /// Unary minus binds looser than '^', as in mathematics: -2^2 = -4.
    Expr parseUnary();
    /// `e[i]` and `e.x` after a primary.
    Expr parsePostfix();
    void setArgs(Expr& e, const Expr* values, size_t n);
    /// An expression of `kind` over `args`, its depth checked.
    Expr node(Expr::Kind kind, const Token& at, SourcePos start, const Expr* args, size_t n);
    Expr binary(const Token& op, const Expr& lhs, const Expr& rhs, char code = 0);
    bool isSolidWord(const std::string& w);
    Expr parsePrimary();
    /// An argument of a call: `expr`, or `name = expr`.
    Expr parseArgument();
    /// `[a, b, …]` or `[for NAME in EXPR (if COND)?: EXPR]`.
    Expr parseList();

    TokenWindow mTokens;
    DiagnosticSink& mSink;
    AstArena* mArena = nullptr;  // the program's, for expressions and names
    size_t mPos = 0;
    int mNesting = 0;
    int mBraceDepth = 0;
    bool mInVector = false;  // parsing a vector's components: '>' closes it
};

}  // namespace kerf::parser_detail
