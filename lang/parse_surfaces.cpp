// Parsing the surface operators `surface SOLID` and `clip SURFACE by SOLID`. Each is a
// Primitive named for its keyword whose children are its operands (lower_surfaces.cpp).
#include "lang/parser_impl.h"

namespace kerf::parser_detail {

bool Parser::startsSurfaceOp() {
    if (!checkWord("surface") && !checkWord("clip")) return false;
    const Token& next = peek(1);
    return next.kind == TokenKind::Identifier && !contains(kModifierWords, next.text) &&
           !contains(kStatementWords, next.text);
}

Solid Parser::parseSurfaceOp(bool withModifiers) {
    NestingGuard guard(*this);
    Solid op;
    op.kind = Solid::Kind::Primitive;
    op.loc = peek().pos;
    op.name = mArena->intern(next().text);
    std::vector<Solid> operands;
    if (op.name == "surface") {
        // Modifiers after the solid are the solid's; on its boundary they mean the same.
        operands.push_back(parseSolid(withModifiers));
    } else {
        operands.push_back(parseSolid(true));
        if (!checkWord("by"))
            fail(peek().loc,
                 "expected 'by SOLID' after the surface that clip cuts, found " + describe(peek()),
                 "write 'clip disc { … } by box { … }'");
        next();
        // The modifiers after the solid move the whole clip (surface and solid together).
        operands.push_back(parseSolid(false));
        if (withModifiers) op.modifiers = parseModifiers();
    }
    op.children = list(operands);
    return op;
}

}  // namespace kerf::parser_detail
