// Parsing the modifiers that follow a solid (translate, rotate, scale, matrix, material, …),
// and the matrix literal's rows.
#include "lang/parser_impl.h"

namespace kerf::parser_detail {

ArenaList<Modifier> Parser::parseModifiers() {
    std::vector<Modifier> modifiers;
    while (check(TokenKind::Identifier)) {
        const std::string& word = peek().text;
        Modifier m;
        m.loc = peek().pos;
        if (word == "translate" || word == "rotate" || word == "scale" || word == "move" ||
            word == "spin") {
            m.kind = word == "translate" ? Modifier::Kind::Translate
                     : word == "rotate"  ? Modifier::Kind::Rotate
                     : word == "scale"   ? Modifier::Kind::Scale
                     : word == "move"    ? Modifier::Kind::Move
                                         : Modifier::Kind::Spin;
            next();
            const Expr arg = parseExpr();
            m.args = list(&arg, 1);
        } else if (word == "matrix") {
            m.kind = Modifier::Kind::Matrix;
            next();
            parseMatrix(m);
        } else if (word == "displace") {
            // `displace KIND { … } transforms by DEPTH`
            m.kind = Modifier::Kind::Displace;
            next();
            if (peek().kind != TokenKind::Identifier || peek(1).kind != TokenKind::LBrace)
                fail(peek().loc,
                     "expected a pattern after 'displace' (displace noise { … } by 0.1), found " +
                         describe(peek()));
            m.pattern = store(parsePattern());
            if (!checkWord("by"))
                fail(peek().loc, "expected 'by DEPTH' after the displacement's pattern, found " +
                                     describe(peek()));
            next();
            const Expr arg = parseExpr();
            m.args = list(&arg, 1);
        } else if (word == "interior") {  // `interior MATERIAL` (csg/primitives/surfaces.h)
            m.kind = Modifier::Kind::Interior;
            next();
            if (peek().kind != TokenKind::Identifier)
                fail(peek().loc,
                     "expected a material name after 'interior', found " + describe(peek()));
            m.materialLoc = peek().pos;
            m.material = mArena->intern(next().text);
        } else if (word == "material" && peek(1).kind != TokenKind::Identifier) {
            fail(peek(1).loc,
                 "expected a material name after 'material', found " + describe(peek(1)));
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

void Parser::parseMatrix(Modifier& m) {
    const SourceLoc open = peek().loc;
    expect(TokenKind::LBracket, "after matrix");
    const bool commas = bracketHasCommas();
    std::vector<Expr> entries;
    while (!accept(TokenKind::RBracket)) {
        if (check(TokenKind::End) || check(TokenKind::Semicolon) || check(TokenKind::RBrace))
            fail(peek().loc, "expected ']' to close the matrix opened at line " +
                                 std::to_string(open.line) + ", found " + describe(peek()));
        if (commas && !entries.empty()) expect(TokenKind::Comma, "between matrix entries");
        entries.push_back(commas ? parseExpr() : parseUnary());
    }
    m.args = list(entries);
}

bool Parser::bracketHasCommas() {
    int depth = 0;
    for (size_t i = mPos;; ++i) {
        switch (mTokens.at(i).kind) {
            case TokenKind::LParen:
            case TokenKind::LBracket:
            case TokenKind::Less: ++depth; break;
            case TokenKind::RParen:
            case TokenKind::Greater: --depth; break;
            case TokenKind::RBracket:
                if (depth-- == 0) return false;
                break;
            case TokenKind::Comma:
                if (depth == 0) return true;
                break;
            case TokenKind::Semicolon:
            case TokenKind::RBrace:
            case TokenKind::End: return false;
            default: break;
        }
    }
    return false;
}

}  // namespace kerf::parser_detail
