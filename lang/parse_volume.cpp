// Parsing `volume "FILE" (grid NAME)?`: a Primitive named "volume" whose properties are the file
// and the grid's name, lowered by lower_volume.cpp. Only a string after `volume` starts one, so
// `volume` stays free as a variable or function name.
#include "lang/parser_impl.h"

namespace kerf::parser_detail {

bool Parser::startsVolume() { return checkWord("volume") && peek(1).kind == TokenKind::String; }

Solid Parser::parseVolume(bool withModifiers) {
    NestingGuard guard(*this);
    Solid volume;
    volume.kind = Solid::Kind::Primitive;
    volume.loc = peek().pos;
    volume.name = mArena->intern(next().text);
    std::vector<Property> properties(1);
    properties[0].name = mArena->intern("file");
    properties[0].loc = peek().pos;
    properties[0].expr = store(parsePrimary());
    if (checkWord("grid")) {
        Property grid;
        grid.name = mArena->intern("grid");
        grid.loc = next().pos;
        if (check(TokenKind::Semicolon) || check(TokenKind::RBrace) || check(TokenKind::End))
            fail(peek().loc,
                 "expected the grid's name in quotes after 'grid', found " + describe(peek()));
        grid.expr = store(parsePrimary());
        properties.push_back(grid);
    }
    volume.properties = list(properties);
    if (withModifiers) volume.modifiers = parseModifiers();
    if (withModifiers && checkWord("grid"))
        fail(peek().loc, "'grid' after the modifiers of a volume",
             "write it right after the file name: volume \"smoke.vdb\" grid \"surface\" translate "
             "…");
    return volume;
}

}  // namespace kerf::parser_detail
