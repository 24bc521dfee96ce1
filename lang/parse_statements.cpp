// The statement parsers: a statement's keyword decides its form (definitions, objects, loops,
// conditions, functions, assert, echo, settings blocks); their bodies use the block, property
// and solid parsers of parser.cpp.
#include "lang/parser_impl.h"
#include "lang/solid_kinds.h"

namespace kerf {
namespace parser_detail {

void Parser::parseStatement(Program& program) {
    const Token& t = peek();
    if (t.kind != TokenKind::Identifier ||
        (!contains(kStatementWords, t.text) && !contains(kBlockWords, t.text))) {
        std::string hint =
            "a statement starts with let, solid, object, material, camera, light, "
            "mist, background, render, section, include, fn, for, if, assert, echo or default";
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
        const bool defines =
            s.kind == Statement::Kind::Let || s.kind == Statement::Kind::SolidDef ||
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

void Parser::parseStatementBody(Statement& s) {
    const std::string word = next().text;
    if (word == "for" || word == "if") {
        parseBlockStatement(s, word);
    } else if (word == "fn") {
        parseFunction(s);
    } else if (word == "assert") {
        parseAssert(s);
    } else if (word == "echo") {
        parseEcho(s);
    } else if (word == "default") {
        s.kind = Statement::Kind::DefaultMaterial;
        if (!checkWord("material"))
            fail(peek().loc, "expected 'material' after 'default', found " + describe(peek()));
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
        parseObject(s);
    } else if (word == "material") {
        s.kind = Statement::Kind::Material;
        parseDefinedName(s, "material");
        parseBlock(s.properties);
    } else if (word == "light") {
        s.kind = Statement::Kind::Light;
        s.nameLoc = peek().pos;
        const Token& kind = expectName("a light kind (point, directional, area or sphere)");
        s.name = kind.text;
        parseBlock(s.properties);
    } else if (word == "camera" || word == "mist" || word == "render" || word == "section") {
        s.kind = word == "camera"   ? Statement::Kind::Camera
                 : word == "mist"   ? Statement::Kind::Mist
                 : word == "render" ? Statement::Kind::Render
                                    : Statement::Kind::Section;
        parseBlock(s.properties);
    } else if (word == "background") {
        parseBackground(s);
    } else {  // include
        s.kind = Statement::Kind::Include;
        s.nameLoc = peek().pos;
        s.name = expect(TokenKind::String, "after include (the file name in quotes)").text;
        expect(TokenKind::Semicolon, "after the include statement");
    }
}

void Parser::parseAssert(Statement& s) {
    s.kind = Statement::Kind::Assert;
    s.expr = store(parseExpr());
    if (accept(TokenKind::Comma)) {
        Property message;
        message.loc = peek().pos;
        message.expr = store(parseExpr());
        s.properties = list(&message, 1);
    }
    expect(TokenKind::Semicolon, "after the assert statement");
}

void Parser::parseEcho(Statement& s) {
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
}

void Parser::parseObject(Statement& s) {
    s.kind = Statement::Kind::Object;
    s.solid = store(parseSolid(true));
    if (checkWord("no_shadow")) {  // the object casts no shadow
        s.nameLoc = peek().pos;
        s.name = next().text;
    }
    expect(TokenKind::Semicolon, "after the object statement");
}

void Parser::parseBackground(Statement& s) {
    s.kind = Statement::Kind::Background;
    if (checkWord("gradient") && peek(1).kind == TokenKind::LBrace) {  // a gradient sky
        s.nameLoc = peek().pos;
        s.name = next().text;
        parseBlock(s.properties);
    } else {
        s.expr = store(parseExpr());
        expect(TokenKind::Semicolon, "after the background statement");
    }
}

void Parser::parseBlockStatement(Statement& s, const std::string& word) {
    NestingGuard guard(*this);
    s.block = std::make_unique<Block>();
    if (word == "for") {
        s.kind = Statement::Kind::For;
        s.nameLoc = peek().pos;
        s.name = expectName("the name of the loop variable").text;
        if (isReservedWord(s.name))
            mSink.error(mTokens.at(mPos - 1).loc,
                        "'" + s.name + "' is a reserved word and cannot name a loop variable");
        if (!checkWord("in"))
            fail(peek().loc, "expected 'in' after the loop variable, found " + describe(peek()));
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

void Parser::parseStatements(std::vector<Statement>& out) {
    const SourceLoc open = peek().loc;
    expect(TokenKind::LBrace, "to open the block");
    while (!accept(TokenKind::RBrace)) {
        if (check(TokenKind::End))
            fail(peek().loc, "expected '}' to close the block opened at line " +
                                 std::to_string(open.line) + ", found " + describe(peek()));
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

void Parser::parseFunction(Statement& s) {
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
                mSink.error(name.loc,
                            "'" + name.text + "' is a reserved word and cannot name a parameter");
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

void Parser::parseDefinedName(Statement& s, const std::string& what) {
    const Token& name = expectName("the name of the " + what);
    s.name = name.text;
    s.nameLoc = name.pos;
    if (isReservedWord(name.text) ||
        (what == "let" && (name.text == "x" || name.text == "y" || name.text == "z")))
        mSink.error(name.loc, "'" + name.text + "' is a reserved word and cannot name a " + what);
}

}  // namespace parser_detail
}  // namespace kerf
