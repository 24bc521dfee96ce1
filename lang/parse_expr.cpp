// The recursive-descent parser: expressions, loosest first (c ? a : b, or, and, not,
// comparisons, ranges, + -, * / %, unary -, ^, postfix [i] and .x, primaries). Expressions are
// built as values and their operands copied into the arena side by side.
#include "lang/parser_impl.h"
#include "lang/solid_kinds.h"

namespace kerf::parser_detail {

// Expressions are built as values and their operands copied into the arena side by side.
// Loosest first: c ? a : b, or, and, not, comparisons, ranges, + -, * /, unary -, ^,
// postfix [i] and .x, primaries.
Expr Parser::parseExpr() {
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

Expr Parser::parseOr() {
    Expr lhs = parseAnd();
    while (checkWord("or")) {
        const Token& op = next();
        const Expr rhs = parseAnd();
        lhs = binary(op, lhs, rhs, '|');
    }
    return lhs;
}

Expr Parser::parseAnd() {
    Expr lhs = parseNot();
    while (checkWord("and")) {
        const Token& op = next();
        const Expr rhs = parseNot();
        lhs = binary(op, lhs, rhs, '&');
    }
    return lhs;
}

Expr Parser::parseNot() {
    if (!checkWord("not")) return parseComparison();
    NestingGuard guard(*this);
    const Token& op = next();
    const Expr operand = parseNot();
    return node(Expr::Kind::Not, op, op.pos, &operand, 1);
}

char Parser::comparisonCode() {
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

Expr Parser::parseComparison() {
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

Expr Parser::parseRange() {
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

Expr Parser::parseAdditive() {
    Expr lhs = parseTerm();
    while (check(TokenKind::Plus) || check(TokenKind::Minus)) {
        const Token& op = next();
        const Expr rhs = parseTerm();
        lhs = binary(op, lhs, rhs);
    }
    return lhs;
}

Expr Parser::parseTerm() {
    Expr lhs = parseUnary();
    while (check(TokenKind::Star) || check(TokenKind::Slash) || check(TokenKind::Percent)) {
        const Token& op = next();
        const Expr rhs = parseUnary();
        lhs = binary(op, lhs, rhs);
    }
    return lhs;
}

Expr Parser::parseUnary() {
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

Expr Parser::parsePostfix() {
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

void Parser::setArgs(Expr& e, const Expr* values, size_t n) {
    e.first = list(values, n).begin();
    e.count = static_cast<uint32_t>(n);
}

Expr Parser::node(Expr::Kind kind, const Token& at, SourcePos start, const Expr* args, size_t n) {
    Expr e;
    e.kind = kind;
    e.loc = at.pos;
    e.start = start;
    int depth = 1;
    for (size_t i = 0; i < n; ++i) depth = std::max(depth, args[i].depth + 1);
    if (depth > kMaxExpressionDepth)
        fail(at.loc,
             "expression too deeply nested (more than " + std::to_string(kMaxExpressionDepth) +
                 " levels)",
             "split it with lets");
    e.depth = static_cast<uint16_t>(depth);
    setArgs(e, args, n);
    return e;
}

Expr Parser::binary(const Token& op, const Expr& lhs, const Expr& rhs, char code) {
    const Expr both[2] = {lhs, rhs};
    Expr e = node(Expr::Kind::Binary, op, lhs.start, both, 2);
    e.op = code ? code : op.text[0];
    return e;
}

bool Parser::isSolidWord(const std::string& w) {
    const SolidKind* kind = findSolidKind(w);  // lang/solid_kinds.cpp
    return kind && kind->has(kSolidValue);
}

Expr Parser::parsePrimary() {
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
    } else if (startsMesh()) {  // `mesh "file"` as a value
        e.kind = Expr::Kind::SolidValue;
        e.solid = store(parseSolid(true));
        return e;
    } else if (t.kind == TokenKind::Identifier && isSolidWord(t.text) &&
               peek(1).kind == TokenKind::LBrace) {
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

Expr Parser::parseArgument() {
    if (!check(TokenKind::Identifier) || peek(1).kind != TokenKind::Equals) return parseExpr();
    const Token& name = next();
    const Token& eq = next();
    const Expr value = parseExpr();
    Expr e = node(Expr::Kind::NamedArg, eq, name.pos, &value, 1);
    e.loc = name.pos;
    e.ident = &mArena->intern(name.text).str();
    return e;
}

Expr Parser::parseList() {
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
        if (!checkWord("in"))
            fail(peek().loc, "expected 'in' after the loop variable, found " + describe(peek()));
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
}  // namespace kerf::parser_detail
