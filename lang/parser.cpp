// The recursive-descent parser. Each parse function consumes one construct; on a syntax error
// it reports and throws SyntaxError, which the statement loop catches before resynchronising.
#include "lang/parser.h"
#include "lang/diagnostic_hints.h"
#include "lang/positional_values.h"
#include "lang/token_window.h"

#include <algorithm>
#include <array>
#include <functional>

namespace kerf {

namespace {

const std::array<const char*, 10> kStatementWords = {
    "let", "solid", "object", "material", "camera", "light", "mist", "background", "render", "include"};
const std::array<const char*, 4> kBooleanWords = {"union", "intersection", "difference", "xor"};
const std::array<const char*, 5> kModifierWords = {"translate", "rotate", "scale", "matrix", "material"};

template <size_t N>
bool contains(const std::array<const char*, N>& words, const std::string& w) {
    return std::any_of(words.begin(), words.end(), [&](const char* s) { return w == s; });
}

struct SyntaxError {};

class Parser {
public:
    Parser(std::function<Token()> source, DiagnosticSink& sink) : mTokens(std::move(source)), mSink(sink) {}

    Program run() {
        Program program;
        program.arenas.push_back(std::make_unique<AstArena>());
        mArena = program.arenas.back().get();
        while (peek().kind != TokenKind::End) {
            mTokens.dropBefore(mPos > 0 ? mPos - 1 : 0);  // keep the previous token: afterPrevious()
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
    const T* store(const T& node) { return mArena->copy(&node, 1); }
    template <class T>
    ArenaList<T> list(const T* values, size_t n) {
        return ArenaList<T>(mArena->copy(values, n), static_cast<uint32_t>(n));
    }
    template <class T>
    ArenaList<T> list(const std::vector<T>& values) { return list(values.data(), values.size()); }

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
                p.fail(p.peek().loc, "nesting too deep (more than " + std::to_string(kMaxNesting) + " levels)",
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

    // ---- statements ----
    void parseStatement(Program& program) {
        const Token& t = peek();
        if (t.kind != TokenKind::Identifier || !contains(kStatementWords, t.text)) {
            std::string hint = "a statement starts with let, solid, object, material, camera, light, "
                               "mist, background, render or include";
            if (t.kind == TokenKind::Identifier && peek(1).kind == TokenKind::LBrace)
                hint = "to put a solid into the scene write 'object " + t.text + " { … };'";
            if (const std::string foreign = foreignHint(t); !foreign.empty()) hint = foreign;
            fail(t.loc, "expected a statement, found " + describe(t), hint);
        }
        Statement s;
        s.loc = t.pos;
        try {
            parseStatementBody(s);
        } catch (const SyntaxError&) {
            // Keep a broken definition's name, so its uses are not reported as undefined too.
            const bool defines = s.kind == Statement::Kind::Let || s.kind == Statement::Kind::SolidDef ||
                                 s.kind == Statement::Kind::Material;
            if (defines && !s.name.empty()) {
                s.broken = true;
                s.takeTree(mArena->handedOut());
                program.statements.push_back(std::move(s));
            }
            throw;
        }
        s.takeTree(mArena->handedOut());
        program.statements.push_back(std::move(s));
    }

    void parseStatementBody(Statement& s) {
        const std::string word = next().text;
        if (word == "let") {
            s.kind = Statement::Kind::Let;
            parseDefinedName(s, "let");
            expect(TokenKind::Equals, "after the name of the let");
            s.expr = store(parseExpr());
            expect(TokenKind::Semicolon, "after the let statement");
        } else if (word == "solid") {
            s.kind = Statement::Kind::SolidDef;
            parseDefinedName(s, "solid");
            expect(TokenKind::Equals, "after the name of the solid");
            s.solid = store(parseSolid(true));
            expect(TokenKind::Semicolon, "after the solid statement");
        } else if (word == "object") {
            s.kind = Statement::Kind::Object;
            s.solid = store(parseSolid(true));
            expect(TokenKind::Semicolon, "after the object statement");
        } else if (word == "material") {
            s.kind = Statement::Kind::Material;
            parseDefinedName(s, "material");
            parseBlock(s.properties);
        } else if (word == "light") {
            s.kind = Statement::Kind::Light;
            s.nameLoc = peek().pos;
            const Token& kind = expectName("a light kind (point or directional)");
            s.name = kind.text;
            parseBlock(s.properties);
        } else if (word == "camera" || word == "mist" || word == "render") {
            s.kind = word == "camera" ? Statement::Kind::Camera
                     : word == "mist" ? Statement::Kind::Mist : Statement::Kind::Render;
            parseBlock(s.properties);
        } else if (word == "background") {
            s.kind = Statement::Kind::Background;
            s.expr = store(parseExpr());
            expect(TokenKind::Semicolon, "after the background statement");
        } else {  // include
            s.kind = Statement::Kind::Include;
            s.nameLoc = peek().pos;
            s.name = expect(TokenKind::String, "after include (the file name in quotes)").text;
            expect(TokenKind::Semicolon, "after the include statement");
        }
    }

    void parseDefinedName(Statement& s, const std::string& what) {
        const Token& name = expectName("the name of the " + what);
        s.name = name.text;
        s.nameLoc = name.pos;
        if (isReservedWord(name.text) || (what == "let" && (name.text == "x" || name.text == "y" || name.text == "z")))
            mSink.error(name.loc, "'" + name.text + "' is a reserved word and cannot name a " + what);
    }

    /// `{ name value … }`; an optional ';' may follow the block.
    void parseBlock(ArenaList<Property>& properties) {
        const SourceLoc open = peek().loc;
        expect(TokenKind::LBrace, "to open the block");
        properties = parseProperties(open);
        accept(TokenKind::Semicolon);
    }

    ArenaList<Property> parseProperties(const SourceLoc& open) {
        std::vector<Property> properties;
        while (!accept(TokenKind::RBrace)) {
            if (check(TokenKind::End) || (peek().firstOnLine && startsStatement()))
                fail(peek().loc, "expected '}' to close the block opened at line " + std::to_string(open.line) +
                                     ", found " + describe(peek()));
            const Token& name = expectName("a property name or '}'");
            Property p;
            p.name = mArena->intern(name.text);
            p.loc = name.pos;
            // A property without a value (POV-Ray's `open`), or with a block for a value
            // (`pigment { … }`), is left to the block's check, which knows whether the name is a
            // property at all; the block is skipped.
            const bool noValue = check(TokenKind::RBrace) || check(TokenKind::End) || check(TokenKind::LBrace) ||
                                 (isForeignFlag(p.name) && check(TokenKind::Identifier));
            if (check(TokenKind::LBrace)) skipBlock();
            if (!noValue && check(TokenKind::Identifier) && peek(1).kind == TokenKind::LBrace)
                p.solid = store(parseSolid(false));
            else if (!noValue)
                p.expr = store(parseExpr());
            properties.push_back(p);
        }
        return list(properties);
    }

    // ---- habits from other modellers (lang/diagnostic_hints.h) ----
    /// The hint for another modeller's word where a statement or a solid belongs, or empty.
    std::string foreignHint(const Token& t) {
        if (t.kind != TokenKind::Identifier) return {};
        if (peek(1).kind == TokenKind::LParen) return callSyntaxHint(t.text);
        if (const std::string solid = foreignSolidHint(t.text); !solid.empty() && peek(1).kind == TokenKind::LBrace)
            return solid + "; a solid is put into the scene with 'object …;'";  // POV-Ray's `plane { … }`
        return foreignStatementHint(t.text);
    }

    /// Past the balanced block that starts here (or to the end of the file).
    void skipBlock() {
        int depth = 0;
        do {
            depth += check(TokenKind::LBrace) ? 1 : check(TokenKind::RBrace) ? -1 : 0;
            next();
        } while (depth > 0 && !check(TokenKind::End));
    }

    // ---- solids ----
    /// A solid as a value; its children, properties and modifiers are already in the arena.
    Solid parseSolid(bool withModifiers) {
        NestingGuard guard(*this);
        Solid solid;
        const Token& t = peek();
        solid.loc = t.pos;
        if (t.kind != TokenKind::Identifier || contains(kModifierWords, t.text) ||
            (contains(kStatementWords, t.text) && peek(1).kind != TokenKind::LBrace))
            fail(t.loc, "expected a solid, found " + describe(t), foreignHint(t));
        solid.name = mArena->intern(next().text);
        if (check(TokenKind::LParen) && isSolidKind(solid.name))  // OpenSCAD's sphere(1)
            fail(peek().loc, "expected '{' after '" + solid.name + "', found '('", callSyntaxHint(solid.name));
        if (check(TokenKind::LBrace)) {
            const SourceLoc open = peek().loc;
            next();
            if (!isSolidKind(solid.name))  // else its contents (solids, POV-Ray values) read as properties
                fail(t.loc, "unknown solid '" + solid.name + "'",
                     unknownSolidHint(solid.name, readPositionalValues(mTokens, mPos, mSink).values));
            if (contains(kBooleanWords, solid.name)) {
                solid.kind = Solid::Kind::Boolean;
                std::vector<Solid> children;
                while (!accept(TokenKind::RBrace)) {
                    if (check(TokenKind::End) || (peek().firstOnLine && startsStatement()))
                        fail(peek().loc, "expected '}' to close the " + solid.name + " opened at line " +
                                             std::to_string(open.line) + ", found " + describe(peek()));
                    children.push_back(parseSolid(true));
                }
                solid.children = list(children);
            } else {
                solid.kind = Solid::Kind::Primitive;
                if (const PositionalValues p = readPositionalValues(mTokens, mPos, mSink); !p.values.empty())
                    fail(peek().loc, "expected a property name in " + solid.name + ", found " + describe(peek()),
                         positionalHint(solid.name, p.values, p.flag));
                solid.properties = parseProperties(open);
            }
        } else {
            solid.kind = Solid::Kind::Reference;
        }
        if (withModifiers) solid.modifiers = parseModifiers();
        return solid;
    }

    ArenaList<Modifier> parseModifiers() {
        std::vector<Modifier> modifiers;
        while (check(TokenKind::Identifier)) {
            const std::string& word = peek().text;
            Modifier m;
            m.loc = peek().pos;
            if (word == "translate" || word == "rotate" || word == "scale") {
                m.kind = word == "translate" ? Modifier::Kind::Translate
                         : word == "rotate" ? Modifier::Kind::Rotate : Modifier::Kind::Scale;
                next();
                const Expr arg = parseExpr();
                m.args = list(&arg, 1);
            } else if (word == "matrix") {
                m.kind = Modifier::Kind::Matrix;
                next();
                parseMatrix(m);
            } else if (word == "material" && peek(1).kind != TokenKind::Identifier) {
                fail(peek(1).loc, "expected a material name after 'material', found " + describe(peek(1)));
            } else if (word == "material" && peek(2).kind != TokenKind::LBrace) {
                m.kind = Modifier::Kind::Material;
                next();
                m.materialLoc = peek().pos;
                m.material = mArena->intern(next().text);
            } else {
                break;
            }
            modifiers.push_back(m);
        }
        return list(modifiers);
    }

    /// `[a, b, …]` with commas, or `[a b …]` separated by blanks, where each entry is a single
    /// term (so `[1 -1 …]` is two entries).
    void parseMatrix(Modifier& m) {
        const SourceLoc open = peek().loc;
        expect(TokenKind::LBracket, "after matrix");
        const bool commas = bracketHasCommas();
        std::vector<Expr> entries;
        while (!accept(TokenKind::RBracket)) {
            if (check(TokenKind::End) || check(TokenKind::Semicolon) || check(TokenKind::RBrace))
                fail(peek().loc, "expected ']' to close the matrix opened at line " + std::to_string(open.line) +
                                     ", found " + describe(peek()));
            if (commas && !entries.empty()) expect(TokenKind::Comma, "between matrix entries");
            entries.push_back(commas ? parseExpr() : parseUnary());
        }
        m.args = list(entries);
    }

    bool bracketHasCommas() {
        int depth = 0;
        for (size_t i = mPos;; ++i) {
            switch (mTokens.at(i).kind) {
                case TokenKind::LParen: case TokenKind::LBracket: case TokenKind::Less: ++depth; break;
                case TokenKind::RParen: case TokenKind::Greater: --depth; break;
                case TokenKind::RBracket: if (depth-- == 0) return false; break;
                case TokenKind::Comma: if (depth == 0) return true; break;
                case TokenKind::Semicolon: case TokenKind::RBrace: case TokenKind::End: return false;
                default: break;
            }
        }
        return false;
    }

    // ---- expressions ----
    // Expressions are built as values and their operands copied into the arena side by side.


    Expr parseExpr() {
        Expr lhs = parseTerm();
        while (check(TokenKind::Plus) || check(TokenKind::Minus)) {
            const Token& op = next();
            const Expr rhs = parseTerm();
            lhs = binary(op, lhs, rhs);
        }
        return lhs;
    }

    Expr parseTerm() {
        Expr lhs = parseUnary();
        while (check(TokenKind::Star) || check(TokenKind::Slash)) {
            const Token& op = next();
            const Expr rhs = parseUnary();
            lhs = binary(op, lhs, rhs);
        }
        return lhs;
    }

    /// Unary minus binds looser than '^', as in mathematics: -2^2 = -4.
    Expr parseUnary() {
        NestingGuard guard(*this);
        if (check(TokenKind::Minus)) {
            Expr e;
            e.kind = Expr::Kind::Negate;
            e.loc = e.start = next().pos;
            const Expr operand = parseUnary();
            e.depth = static_cast<uint16_t>(operand.depth + 1);
            setArgs(e, &operand, 1);
            return e;
        }
        const Expr base = parsePrimary();
        if (check(TokenKind::Caret)) {
            const Token& op = next();
            const Expr exponent = parseUnary();
            return binary(op, base, exponent);  // right associative
        }
        return base;
    }

    void setArgs(Expr& e, const Expr* values, size_t n) {
        e.first = list(values, n).begin();
        e.count = static_cast<uint32_t>(n);
    }

    Expr binary(const Token& op, const Expr& lhs, const Expr& rhs) {
        Expr e;
        e.kind = Expr::Kind::Binary;
        e.loc = op.pos;
        e.start = lhs.start;
        e.op = op.text[0];
        const int depth = std::max(lhs.depth, rhs.depth) + 1;
        if (depth > kMaxExpressionDepth)
            fail(op.loc, "expression too deeply nested (more than " + std::to_string(kMaxExpressionDepth) +
                             " levels)", "split it with lets");
        e.depth = static_cast<uint16_t>(depth);
        const Expr both[2] = {lhs, rhs};
        setArgs(e, both, 2);
        return e;
    }

    Expr parsePrimary() {
        Expr e;
        const Token& t = peek();
        e.loc = e.start = t.pos;
        std::vector<Expr> args;
        if (t.kind == TokenKind::Number) {
            e.kind = Expr::Kind::Number;
            e.number = t.number;
            e.count = static_cast<uint32_t>(t.length);
            next();
            return e;
        } else if (t.kind == TokenKind::Identifier) {
            e.ident = &mArena->intern(next().text).str();
            e.kind = Expr::Kind::Name;
            if (accept(TokenKind::LParen)) {
                e.kind = Expr::Kind::Call;
                if (!accept(TokenKind::RParen)) {
                    do args.push_back(parseExpr());
                    while (accept(TokenKind::Comma));
                    expect(TokenKind::RParen, "to close the arguments of " + e.name());
                }
            }
        } else if (t.kind == TokenKind::LParen) {
            next();
            e = parseExpr();
            e.start = t.pos;
            expect(TokenKind::RParen, "to close '('");
            return e;
        } else if (t.kind == TokenKind::Less) {
            next();
            e.kind = Expr::Kind::Vector;
            args.push_back(parseExpr());
            expect(TokenKind::Comma, "after the x component of the vector");
            args.push_back(parseExpr());
            expect(TokenKind::Comma, "after the y component of the vector");
            args.push_back(parseExpr());
            expect(TokenKind::Greater, "to close the vector");
        } else {
            fail(t.loc, "expected an expression, found " + describe(t));
        }
        int depth = 1;
        for (const Expr& a : args) depth = std::max(depth, a.depth + 1);
        e.depth = static_cast<uint16_t>(depth);
        setArgs(e, args.data(), args.size());
        return e;
    }

    TokenWindow mTokens;
    DiagnosticSink& mSink;
    AstArena* mArena = nullptr;  // the program's, for expressions and names
    size_t mPos = 0;
    int mNesting = 0;
    int mBraceDepth = 0;
};

}  // namespace

bool isReservedWord(const std::string& word) {
    static const std::array<const char*, 13> kOther = {
        "sphere", "box", "cylinder", "cone", "torus", "halfspace", "implicit", "pi",
        "union", "intersection", "difference", "xor", "matrix"};
    return contains(kStatementWords, word) || contains(kModifierWords, word) || contains(kOther, word);
}

Program parse(const std::vector<Token>& tokens, DiagnosticSink& sink) {
    size_t i = 0;
    return Parser([&]() { return tokens[std::min(i++, tokens.size() - 1)]; }, sink).run();
}

Program parse(TokenStream& tokens, DiagnosticSink& sink) {
    return Parser([&]() { return tokens.next(); }, sink).run();
}

}  // namespace kerf
