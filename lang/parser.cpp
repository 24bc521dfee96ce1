// The recursive-descent parser: blocks, properties and solids. Each parse function consumes one
// construct; on a syntax error it reports and throws SyntaxError, which the statement loop
// catches before resynchronising. Statements are in parse_statements.cpp, expressions in
// parse_expr.cpp, modifiers in parse_modifiers.cpp.
#include "lang/parser_impl.h"
#include "lang/solid_kinds.h"

namespace kerf {

namespace parser_detail {

void Parser::parseBlock(ArenaList<Property>& properties) {
    const SourceLoc open = peek().loc;
    expect(TokenKind::LBrace, "to open the block");
    properties = parseProperties(open);
    accept(TokenKind::Semicolon);
}

ArenaList<Property> Parser::parseProperties(const SourceLoc& open) {
    std::vector<Property> properties;
    while (!accept(TokenKind::RBrace)) {
        if (check(TokenKind::End) || (peek().firstOnLine && startsStatement()))
            fail(peek().loc, "expected '}' to close the block opened at line " +
                                 std::to_string(open.line) + ", found " + describe(peek()));
        const Token& name = expectName("a property name or '}'");
        Property p;
        p.name = mArena->intern(name.text);
        p.loc = name.pos;
        // A material's `pattern KIND { … }` or `bump KIND { … }`, or a pattern as a pattern's
        // entry: `a pattern KIND { … }` (scene/pattern.h).
        const bool patternProperty = name.text == "pattern" || name.text == "bump";
        if ((patternProperty || (checkWord("pattern") && peek(1).kind == TokenKind::Identifier)) &&
            (patternProperty ? peek(1) : peek(2)).kind == TokenKind::LBrace) {
            if (!patternProperty) next();
            p.solid = store(parsePattern());
            properties.push_back(p);
            continue;
        }
        // mist's `density volume "smoke.vdb" [grid "name"]`: a fog volume, kept as a
        // Primitive named volume with file (and grid) properties for lowerMist.
        if (name.text == "density" && checkWord("volume") && peek(1).kind == TokenKind::String) {
            Solid fog;
            fog.kind = Solid::Kind::Primitive;
            fog.loc = peek().pos;
            fog.name = mArena->intern(next().text);
            std::vector<Property> fogProps(1);
            fogProps[0].name = mArena->intern("file");
            fogProps[0].loc = peek().pos;
            fogProps[0].expr = store(parsePrimary());
            if (checkWord("grid") && peek(1).kind == TokenKind::String) {
                Property grid;
                grid.name = mArena->intern("grid");
                grid.loc = next().pos;
                grid.expr = store(parsePrimary());
                fogProps.push_back(grid);
            }
            fog.properties = list(fogProps);
            p.solid = store(fog);
            properties.push_back(p);
            continue;
        }
        // A property without a value (POV-Ray's `open`), or with a block for a value
        // (`pigment { … }`), is left to the block's check, which knows whether the name is a
        // property at all; the block is skipped.
        const bool noValue =
            check(TokenKind::RBrace) || check(TokenKind::End) || check(TokenKind::LBrace) ||
            (isForeignFlag(p.name) && check(TokenKind::Identifier) && !checkWord("true") &&
             !checkWord("false"));  // `open true` has a value
        if (check(TokenKind::LBrace)) skipBlock();
        if (!noValue && check(TokenKind::Identifier) && peek(1).kind == TokenKind::LBrace)
            p.solid = store(parseSolid(false));
        else if (!noValue)
            p.expr = store(parseExpr());
        properties.push_back(p);
    }
    return list(properties);
}

Solid Parser::parsePattern() {
    NestingGuard guard(*this);
    Solid pattern;
    pattern.kind = Solid::Kind::Primitive;  // read as a pattern where a material takes one
    pattern.loc = peek().pos;
    pattern.name = mArena->intern(expectName("a pattern kind").text);
    const SourceLoc open = peek().loc;
    expect(TokenKind::LBrace, "to open the pattern");
    pattern.properties = parseProperties(open);
    pattern.modifiers = parseModifiers();
    return pattern;
}

std::string Parser::foreignHint(const Token& t) {
    if (t.kind != TokenKind::Identifier) return {};
    if (peek(1).kind == TokenKind::LParen) return callSyntaxHint(t.text);
    if (const std::string solid = foreignSolidHint(t.text);
        !solid.empty() && peek(1).kind == TokenKind::LBrace)
        return solid +
               "; a solid is put into the scene with 'object …;'";  // POV-Ray's `plane { … }`
    return foreignStatementHint(t.text);
}

void Parser::skipBlock() {
    int depth = 0;
    do {
        depth += check(TokenKind::LBrace) ? 1 : check(TokenKind::RBrace) ? -1 : 0;
        next();
    } while (depth > 0 && !check(TokenKind::End));
}

Solid Parser::parseSolid(bool withModifiers) {
    NestingGuard guard(*this);
    Solid solid;
    const Token& t = peek();
    solid.loc = t.pos;
    if (t.kind != TokenKind::Identifier || contains(kModifierWords, t.text) ||
        (contains(kStatementWords, t.text) && peek(1).kind != TokenKind::LBrace))
        fail(t.loc, "expected a solid, found " + describe(t), foreignHint(t));
    if (startsMesh()) return parseMesh(withModifiers);
    if (startsVolume()) return parseVolume(withModifiers);
    if (startsSurfaceOp()) return parseSurfaceOp(withModifiers);
    if (peek(1).kind == TokenKind::LParen && isSolidKind(t.text))  // OpenSCAD's sphere(1)
        fail(peek(1).loc, "expected '{' after '" + t.text + "', found '('", callSyntaxHint(t.text));
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
    const SourceLoc nameLoc = t.loc;  // t may not outlive the look-ahead below
    solid.name = mArena->intern(next().text);
    if (check(TokenKind::LBrace)) {
        const SourceLoc open = peek().loc;
        next();
        if (!isSolidKind(
                solid.name)) {  // else its contents (solids, POV-Ray values) read as properties
            const std::string hint =
                unknownSolidHint(solid.name, readPositionalValues(mTokens, mPos, mSink).values);
            fail(nameLoc, "unknown solid '" + solid.name + "'", hint);
        }
        if (contains(kBooleanWords, solid.name)) {
            solid.kind = Solid::Kind::Boolean;
            std::vector<Solid> children;
            while (!accept(TokenKind::RBrace)) {
                if (check(TokenKind::End) || (peek().firstOnLine && startsStatement()))
                    fail(peek().loc, "expected '}' to close the " + solid.name +
                                         " opened at line " + std::to_string(open.line) +
                                         ", found " + describe(peek()));
                children.push_back(parseChild());
            }
            solid.children = list(children);
        } else {
            solid.kind = Solid::Kind::Primitive;
            if (const PositionalValues p = readPositionalValues(mTokens, mPos, mSink);
                !p.values.empty()) {
                const std::string hint = positionalHint(solid.name, p.values, p.flag);
                fail(peek().loc,
                     "expected a property name in " + solid.name + ", found " + describe(peek()),
                     hint);
            }
            solid.properties = parseProperties(open);
        }
    } else {
        solid.kind = Solid::Kind::Reference;
    }
    if (withModifiers) solid.modifiers = parseModifiers();
    return solid;
}

bool Parser::startsMesh() {
    if (!checkWord("mesh")) return false;
    const Token& file = peek(1);
    return file.kind == TokenKind::String || file.kind == TokenKind::LParen ||
           (file.kind == TokenKind::Identifier && !contains(kModifierWords, file.text) &&
            !contains(kStatementWords, file.text) && file.text != "smooth" &&
            file.text != "displace" && file.text != "no_shadow");
}

Solid Parser::parseMesh(bool withModifiers) {
    NestingGuard guard(*this);
    Solid mesh;
    mesh.kind = Solid::Kind::Primitive;  // lowered by lowerMesh (lower_mesh.cpp)
    mesh.loc = peek().pos;
    mesh.name = mArena->intern(next().text);
    std::vector<Property> properties(1);
    properties[0].name = mArena->intern("file");
    properties[0].loc = peek().pos;
    properties[0].expr = store(parsePrimary());
    if (checkWord("smooth")) {
        Property smooth;
        smooth.name = mArena->intern("smooth");
        smooth.loc = next().pos;
        if (check(TokenKind::Semicolon) || check(TokenKind::RBrace) || check(TokenKind::End))
            fail(peek().loc, "expected true or false after 'smooth', found " + describe(peek()));
        smooth.expr = store(parsePrimary());
        properties.push_back(smooth);
    }
    mesh.properties = list(properties);
    if (withModifiers) mesh.modifiers = parseModifiers();
    if (withModifiers && checkWord("smooth"))
        fail(peek().loc, "'smooth' after the modifiers of a mesh",
             "write it right after the file name: mesh \"part.stl\" smooth false translate …");
    return mesh;
}

Solid Parser::parseChild() {
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
            mSink.error(name.loc,
                        "'" + name.text + "' is a reserved word and cannot name a loop variable");
        if (!checkWord("in"))
            fail(peek().loc, "expected 'in' after the loop variable, found " + describe(peek()));
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

std::vector<Solid> Parser::parseChildren(const char* what) {
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

}  // namespace parser_detail

using parser_detail::contains;
using parser_detail::kModifierWords;
using parser_detail::kStatementWords;
using parser_detail::Parser;

bool isReservedWord(const std::string& word) {
    static const std::array<const char*, 12> kOther = {
        "pi", "matrix", "for", "in", "if", "else", "step", "and", "or", "not", "true", "false"};
    if (const SolidKind* kind = findSolidKind(word); kind && kind->has(kReserved))
        return true;  // lang/solid_kinds.cpp
    return contains(kStatementWords, word) || contains(kModifierWords, word) ||
           contains(kOther, word);
}

Program parse(const std::vector<Token>& tokens, DiagnosticSink& sink) {
    size_t i = 0;
    return Parser([&]() { return tokens[std::min(i++, tokens.size() - 1)]; }, sink).run();
}

Program parse(TokenStream& tokens, DiagnosticSink& sink) {
    return Parser([&]() { return tokens.next(); }, sink).run();
}

}  // namespace kerf
