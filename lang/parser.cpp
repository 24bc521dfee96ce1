// The recursive-descent parser. Each parse function consumes one construct; on a syntax error
// it reports and throws SyntaxError, which the statement loop catches before resynchronising.
#include "lang/parser.h"
#include "lang/token_window.h"

#include <algorithm>
#include <array>
#include <functional>

namespace kerf {

namespace {

const std::array<const char*, 14> kStatementWords = {
    "let", "solid", "object", "material", "camera", "light", "mist", "background", "render", "include",
    "fn", "assert", "echo", "default"};
/// Words that open a statement but may also stand for a child inside a Boolean body.
const std::array<const char*, 2> kBlockWords = {"for", "if"};
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
        if (t.kind != TokenKind::Identifier ||
            (!contains(kStatementWords, t.text) && !contains(kBlockWords, t.text))) {
            std::string hint = "a statement starts with let, solid, object, material, camera, light, "
                               "mist, background, render, include, fn, for, if, assert, echo or default";
            if (t.kind == TokenKind::Identifier && peek(1).kind == TokenKind::LBrace)
                hint = "to put a solid into the scene write 'object " + t.text + " { … };'";
            fail(t.loc, "expected a statement, found " + describe(t), hint);
        }
        Statement s;
        s.loc = t.pos;
        try {
            parseStatementBody(s);
        } catch (const SyntaxError&) {
            // Keep a broken definition's name, so its uses are not reported as undefined too.
            const bool defines = s.kind == Statement::Kind::Let || s.kind == Statement::Kind::SolidDef ||
                                 s.kind == Statement::Kind::Material || s.kind == Statement::Kind::Function;
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
        if (word == "for" || word == "if") {
            parseBlockStatement(s, word);
        } else if (word == "fn") {
            parseFunction(s);
        } else if (word == "assert") {
            s.kind = Statement::Kind::Assert;
            s.expr = store(parseExpr());
            if (accept(TokenKind::Comma)) {
                Property message;
                message.loc = peek().pos;
                message.expr = store(parseExpr());
                s.properties = list(&message, 1);
            }
            expect(TokenKind::Semicolon, "after the assert statement");
        } else if (word == "echo") {
            s.kind = Statement::Kind::Echo;
            std::vector<Property> values;
            do {
                Property v;
                v.loc = peek().pos;
                v.expr = store(parseExpr());
                values.push_back(v);
            } while (accept(TokenKind::Comma));
            s.properties = list(values);
            expect(TokenKind::Semicolon, "after the echo statement");
        } else if (word == "default") {
            s.kind = Statement::Kind::DefaultMaterial;
            if (!checkWord("material")) fail(peek().loc, "expected 'material' after 'default', found " + describe(peek()));
            next();
            s.nameLoc = peek().pos;
            s.name = expectName("the name of the default material").text;
            expect(TokenKind::Semicolon, "after the default material statement");
        } else if (word == "let") {
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

    /// `for NAME in EXPR { statements }` or `if EXPR { … } else if … else { … }` at statement
    /// level. The nested statements keep their nodes in the scratch arena; the outermost
    /// statement's takeTree moves them all.
    void parseBlockStatement(Statement& s, const std::string& word) {
        NestingGuard guard(*this);
        s.block = std::make_unique<Block>();
        if (word == "for") {
            s.kind = Statement::Kind::For;
            s.nameLoc = peek().pos;
            s.name = expectName("the name of the loop variable").text;
            if (isReservedWord(s.name)) mSink.error(mTokens.at(mPos - 1).loc, "'" + s.name + "' is a reserved word and cannot name a loop variable");
            if (!checkWord("in")) fail(peek().loc, "expected 'in' after the loop variable, found " + describe(peek()));
            next();
            s.expr = store(parseExpr());
            parseStatements(s.block->body);
            return;
        }
        s.kind = Statement::Kind::If;
        s.expr = store(parseExpr());
        parseStatements(s.block->body);
        if (!checkWord("else")) return;
        next();
        s.block->hasElse = true;
        if (checkWord("if")) {
            Statement inner;
            inner.loc = peek().pos;
            next();
            parseBlockStatement(inner, "if");
            s.block->elseBody.push_back(std::move(inner));
        } else {
            parseStatements(s.block->elseBody);
        }
    }

    /// `{ statements }` of a block; an optional ';' may follow.
    void parseStatements(std::vector<Statement>& out) {
        const SourceLoc open = peek().loc;
        expect(TokenKind::LBrace, "to open the block");
        while (!accept(TokenKind::RBrace)) {
            if (check(TokenKind::End))
                fail(peek().loc, "expected '}' to close the block opened at line " + std::to_string(open.line) +
                                     ", found " + describe(peek()));
            if (accept(TokenKind::Semicolon)) continue;
            const Token& t = peek();
            if (t.kind != TokenKind::Identifier ||
                (!contains(kStatementWords, t.text) && !contains(kBlockWords, t.text)))
                fail(t.loc, "expected a statement or '}', found " + describe(t));
            Statement inner;
            inner.loc = t.pos;
            parseStatementBody(inner);
            out.push_back(std::move(inner));
        }
        accept(TokenKind::Semicolon);
    }

    /// `fn NAME(a, b = default, …) = EXPR;`
    void parseFunction(Statement& s) {
        s.kind = Statement::Kind::Function;
        parseDefinedName(s, "function");
        expect(TokenKind::LParen, "after the name of the function");
        std::vector<Property> params;
        if (!accept(TokenKind::RParen)) {
            do {
                const Token& name = expectName("a parameter name");
                Property p;
                p.name = mArena->intern(name.text);
                p.loc = name.pos;
                if (isReservedWord(name.text))
                    mSink.error(name.loc, "'" + name.text + "' is a reserved word and cannot name a parameter");
                if (accept(TokenKind::Equals)) p.expr = store(parseExpr());
                params.push_back(p);
            } while (accept(TokenKind::Comma));
            expect(TokenKind::RParen, "to close the parameters of " + s.name);
        }
        s.properties = list(params);
        expect(TokenKind::Equals, "after the parameters of the function");
        s.expr = store(parseExpr());
        expect(TokenKind::Semicolon, "after the function definition");
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
            if (check(TokenKind::Identifier) && peek(1).kind == TokenKind::LBrace)
                p.solid = store(parseSolid(false));
            else
                p.expr = store(parseExpr());
            properties.push_back(p);
        }
        return list(properties);
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
            fail(t.loc, "expected a solid, found " + describe(t));
        if (peek(1).kind == TokenKind::LParen) {  // a function call that makes a solid
            solid.kind = Solid::Kind::Call;
            solid.name = mArena->intern(t.text);
            Property call;
            call.loc = t.pos;
            call.expr = store(parsePrimary());
            solid.properties = list(&call, 1);
            if (withModifiers) solid.modifiers = parseModifiers();
            return solid;
        }
        solid.name = mArena->intern(next().text);
        if (check(TokenKind::LBrace)) {
            const SourceLoc open = peek().loc;
            next();
            if (contains(kBooleanWords, solid.name)) {
                solid.kind = Solid::Kind::Boolean;
                std::vector<Solid> children;
                while (!accept(TokenKind::RBrace)) {
                    if (check(TokenKind::End) || (peek().firstOnLine && startsStatement()))
                        fail(peek().loc, "expected '}' to close the " + solid.name + " opened at line " +
                                             std::to_string(open.line) + ", found " + describe(peek()));
                    children.push_back(parseChild());
                }
                solid.children = list(children);
            } else {
                solid.kind = Solid::Kind::Primitive;
                solid.properties = parseProperties(open);
            }
        } else {
            solid.kind = Solid::Kind::Reference;
        }
        if (withModifiers) solid.modifiers = parseModifiers();
        return solid;
    }

    /// One child of a Boolean body: a solid, or a `for` or `if` around solids.
    Solid parseChild() {
        if (!checkWord("for") && !checkWord("if")) return parseSolid(true);
        NestingGuard guard(*this);
        Solid block;
        block.loc = peek().pos;
        const bool isFor = next().text == "for";
        block.kind = isFor ? Solid::Kind::For : Solid::Kind::If;
        Property head;
        if (isFor) {
            head.loc = peek().pos;
            const Token& name = expectName("the name of the loop variable");
            head.name = mArena->intern(name.text);
            if (isReservedWord(name.text))
                mSink.error(name.loc, "'" + name.text + "' is a reserved word and cannot name a loop variable");
            if (!checkWord("in")) fail(peek().loc, "expected 'in' after the loop variable, found " + describe(peek()));
            next();
        } else {
            head.loc = peek().pos;
        }
        head.expr = store(parseExpr());
        block.properties = list(&head, 1);
        std::vector<Solid> children = parseChildren(isFor ? "for" : "if");
        if (!isFor && checkWord("else")) {
            Solid otherwise;
            otherwise.kind = Solid::Kind::Else;
            otherwise.loc = next().pos;
            if (checkWord("if")) {
                const Solid inner = parseChild();
                otherwise.children = list(&inner, 1);
            } else {
                otherwise.children = list(parseChildren("else"));
            }
            children.push_back(otherwise);
        }
        block.children = list(children);
        return block;
    }

    std::vector<Solid> parseChildren(const char* what) {
        const SourceLoc open = peek().loc;
        expect(TokenKind::LBrace, std::string("to open the body of ") + what);
        std::vector<Solid> children;
        while (!accept(TokenKind::RBrace)) {
            if (check(TokenKind::End) || (peek().firstOnLine && startsStatement()))
                fail(peek().loc, std::string("expected '}' to close the ") + what + " opened at line " +
                                     std::to_string(open.line) + ", found " + describe(peek()));
            children.push_back(parseChild());
        }
        return children;
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
    // Loosest first: c ? a : b, or, and, not, comparisons, ranges, + -, * /, unary -, ^,
    // postfix [i] and .x, primaries.

    Expr parseExpr() {
        Expr c = parseOr();
        if (!check(TokenKind::Question)) return c;
        NestingGuard guard(*this);  // a ? b : c ? d : … recurses here
        const Token& q = next();
        const Expr a = parseExpr();
        expect(TokenKind::Colon, "between the two values of '?'");
        const Expr b = parseExpr();
        const Expr parts[3] = {c, a, b};
        return node(Expr::Kind::Choose, q, c.start, parts, 3);
    }

    Expr parseOr() {
        Expr lhs = parseAnd();
        while (checkWord("or")) {
            const Token& op = next();
            const Expr rhs = parseAnd();
            lhs = binary(op, lhs, rhs, '|');
        }
        return lhs;
    }

    Expr parseAnd() {
        Expr lhs = parseNot();
        while (checkWord("and")) {
            const Token& op = next();
            const Expr rhs = parseNot();
            lhs = binary(op, lhs, rhs, '&');
        }
        return lhs;
    }

    Expr parseNot() {
        if (!checkWord("not")) return parseComparison();
        NestingGuard guard(*this);
        const Token& op = next();
        const Expr operand = parseNot();
        return node(Expr::Kind::Not, op, op.pos, &operand, 1);
    }

    /// The operator code of a comparison token, or 0. Inside a vector's components '>' and
    /// '>=' close the vector instead (write comparisons there in parentheses).
    char comparisonCode() {
        switch (peek().kind) {
            case TokenKind::Less: return '<';
            case TokenKind::LessEqual: return 'l';
            case TokenKind::Greater: return mInVector ? 0 : '>';
            case TokenKind::GreaterEqual: return mInVector ? 0 : 'g';
            case TokenKind::EqualEqual: return 'e';
            case TokenKind::NotEqual: return 'n';
            default: return 0;
        }
    }

    Expr parseComparison() {
        Expr lhs = parseRange();
        if (const char code = comparisonCode()) {
            const Token& op = next();
            const Expr rhs = parseRange();
            lhs = binary(op, lhs, rhs, code);
            if (comparisonCode())
                fail(peek().loc, "comparisons do not chain", "write 'a < b and b < c'");
        }
        return lhs;
    }

    Expr parseRange() {
        const Expr from = parseAdditive();
        if (!check(TokenKind::DotDot)) return from;
        const Token& op = next();
        Expr parts[3] = {from, parseAdditive(), Expr()};
        size_t n = 2;
        if (checkWord("step")) {
            next();
            parts[2] = parseAdditive();
            n = 3;
        }
        return node(Expr::Kind::Range, op, from.start, parts, n);
    }

    Expr parseAdditive() {
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
        while (check(TokenKind::Star) || check(TokenKind::Slash) || check(TokenKind::Percent)) {
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
        const Expr base = parsePostfix();
        if (check(TokenKind::Caret)) {
            const Token& op = next();
            const Expr exponent = parseUnary();
            return binary(op, base, exponent);  // right associative
        }
        return base;
    }

    /// `e[i]` and `e.x` after a primary.
    Expr parsePostfix() {
        Expr e = parsePrimary();
        for (;;) {
            if (check(TokenKind::LBracket)) {
                const Token& open = next();
                const bool saved = mInVector;
                mInVector = false;
                const Expr parts[2] = {e, parseExpr()};
                mInVector = saved;
                expect(TokenKind::RBracket, "to close the index");
                e = node(Expr::Kind::Index, open, e.start, parts, 2);
            } else if (check(TokenKind::Dot)) {
                const Token& dot = next();
                const Token& member = expectName("a component name (x, y or z) after '.'");
                Expr m = node(Expr::Kind::Member, dot, e.start, &e, 1);
                m.loc = member.pos;
                m.ident = &mArena->intern(member.text).str();
                e = m;
            } else {
                return e;
            }
        }
    }

    void setArgs(Expr& e, const Expr* values, size_t n) {
        e.first = list(values, n).begin();
        e.count = static_cast<uint32_t>(n);
    }

    /// An expression of `kind` over `args`, its depth checked.
    Expr node(Expr::Kind kind, const Token& at, SourcePos start, const Expr* args, size_t n) {
        Expr e;
        e.kind = kind;
        e.loc = at.pos;
        e.start = start;
        int depth = 1;
        for (size_t i = 0; i < n; ++i) depth = std::max(depth, args[i].depth + 1);
        if (depth > kMaxExpressionDepth)
            fail(at.loc, "expression too deeply nested (more than " + std::to_string(kMaxExpressionDepth) +
                             " levels)", "split it with lets");
        e.depth = static_cast<uint16_t>(depth);
        setArgs(e, args, n);
        return e;
    }

    Expr binary(const Token& op, const Expr& lhs, const Expr& rhs, char code = 0) {
        const Expr both[2] = {lhs, rhs};
        Expr e = node(Expr::Kind::Binary, op, lhs.start, both, 2);
        e.op = code ? code : op.text[0];
        return e;
    }

    bool isSolidWord(const std::string& w) {
        static const std::array<const char*, 7> kPrimitives = {"sphere", "box", "cylinder", "cone",
                                                               "torus", "halfspace", "implicit"};
        return contains(kPrimitives, w) || contains(kBooleanWords, w);
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
        } else if (t.kind == TokenKind::String) {
            if (t.text.size() > static_cast<size_t>(kMaxStringLength))
                fail(t.loc, "string longer than " + std::to_string(kMaxStringLength) + " bytes");
            e.kind = Expr::Kind::String;
            e.ident = &mArena->intern(next().text).str();
            return e;
        } else if (t.kind == TokenKind::Identifier && (t.text == "true" || t.text == "false")) {
            e.kind = Expr::Kind::Bool;
            e.number = next().text == "true" ? 1.0 : 0.0;
            return e;
        } else if (t.kind == TokenKind::Identifier && isSolidWord(t.text) && peek(1).kind == TokenKind::LBrace) {
            e.kind = Expr::Kind::SolidValue;
            e.solid = store(parseSolid(true));
            return e;
        } else if (t.kind == TokenKind::Identifier) {
            e.ident = &mArena->intern(next().text).str();
            e.kind = Expr::Kind::Name;
            if (accept(TokenKind::LParen)) {
                e.kind = Expr::Kind::Call;
                const bool saved = mInVector;
                mInVector = false;
                if (!accept(TokenKind::RParen)) {
                    do args.push_back(parseArgument());
                    while (accept(TokenKind::Comma));
                    expect(TokenKind::RParen, "to close the arguments of " + e.name());
                }
                mInVector = saved;
            }
        } else if (t.kind == TokenKind::LParen) {
            next();
            const bool saved = mInVector;
            mInVector = false;
            e = parseExpr();
            mInVector = saved;
            e.start = t.pos;
            expect(TokenKind::RParen, "to close '('");
            return e;
        } else if (t.kind == TokenKind::LBracket) {
            return parseList();
        } else if (t.kind == TokenKind::Less) {
            next();
            const bool saved = mInVector;
            mInVector = true;
            e.kind = Expr::Kind::Vector;
            args.push_back(parseExpr());
            expect(TokenKind::Comma, "after the x component of the vector");
            args.push_back(parseExpr());
            expect(TokenKind::Comma, "after the y component of the vector");
            args.push_back(parseExpr());
            mInVector = saved;
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

    /// An argument of a call: `expr`, or `name = expr`.
    Expr parseArgument() {
        if (!check(TokenKind::Identifier) || peek(1).kind != TokenKind::Equals) return parseExpr();
        const Token& name = next();
        const Token& eq = next();
        const Expr value = parseExpr();
        Expr e = node(Expr::Kind::NamedArg, eq, name.pos, &value, 1);
        e.loc = name.pos;
        e.ident = &mArena->intern(name.text).str();
        return e;
    }

    /// `[a, b, …]` or `[for NAME in EXPR (if COND)?: EXPR]`.
    Expr parseList() {
        NestingGuard guard(*this);
        const Token& open = next();
        const bool saved = mInVector;
        mInVector = false;
        Expr e;
        if (checkWord("for")) {
            next();
            const Token& var = expectName("the name of the loop variable");
            const std::string* ident = &mArena->intern(var.text).str();
            const SourcePos varPos = var.pos;
            if (!checkWord("in")) fail(peek().loc, "expected 'in' after the loop variable, found " + describe(peek()));
            next();
            Expr parts[3] = {parseExpr(), Expr(), Expr()};
            size_t n = 2;
            if (checkWord("if")) {
                next();
                parts[2] = parseExpr();
                n = 3;
            }
            expect(TokenKind::Colon, "before the value of the list comprehension");
            parts[1] = parseExpr();
            expect(TokenKind::RBracket, "to close the list comprehension");
            e = node(Expr::Kind::Comprehension, open, open.pos, parts, n);
            e.ident = ident;
            e.loc = varPos;
        } else {
            std::vector<Expr> items;
            while (!check(TokenKind::RBracket)) {
                items.push_back(parseExpr());
                if (!accept(TokenKind::Comma)) break;
            }
            expect(TokenKind::RBracket, "to close the list");
            e = node(Expr::Kind::List, open, open.pos, items.data(), items.size());
        }
        mInVector = saved;
        return e;
    }

    TokenWindow mTokens;
    DiagnosticSink& mSink;
    AstArena* mArena = nullptr;  // the program's, for expressions and names
    size_t mPos = 0;
    int mNesting = 0;
    int mBraceDepth = 0;
    bool mInVector = false;  // parsing a vector's components: '>' closes it
};

}  // namespace

bool isReservedWord(const std::string& word) {
    static const std::array<const char*, 23> kOther = {
        "sphere", "box", "cylinder", "cone", "torus", "halfspace", "implicit", "pi",
        "union", "intersection", "difference", "xor", "matrix",
        "for", "in", "if", "else", "step", "and", "or", "not", "true", "false"};
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
