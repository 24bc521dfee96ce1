// SourcePos, the 8-byte position the syntax tree keeps: DiagnosticSink::locate must give the
// line and column the lexer counted itself, so moving the tree to offsets changes no message.
#include "lang/lexer.h"

#include <catch2/catch.hpp>

using namespace kerf;

namespace {

void requireSamePlaces(const std::string& text) {
    DiagnosticSink sink;
    const SourceText source{std::make_shared<const std::string>("p.kerf"),
                            std::make_shared<const std::string>(text)};
    const std::vector<Token> tokens = tokenize(source, sink);
    for (const Token& t : tokens) {
        const SourceLoc at = sink.locate(t.pos);
        INFO("token " << describe(t) << " at offset " << t.pos.offset);
        REQUIRE(at.file == source.name);
        CHECK(at.line == t.loc.line);
        CHECK(at.col == t.loc.col);
    }
}

}  // namespace

TEST_CASE("SourcePos: locate gives the lexer's line and column") {
    SECTION("tabs, CRLF, comments, a byte order mark, UTF-8 in comments") {
        requireSamePlaces(
            "\xEF\xBB\xBF"
            "let a = 1;\r\n\tlet b =\t<1, 2, 3>; // caf\xC3\xA9\n/* x\n y */ let c = a;");
    }
    SECTION("the end of a file without a final newline, and of one with blank lines after") {
        requireSamePlaces("let a = 1");
        requireSamePlaces("let a = 1;\n\n\n");
        requireSamePlaces("");
    }
    SECTION("an unterminated comment (an Error token at its start)") {
        requireSamePlaces("let a = 1;\n  /* never closed\n");
    }
}

TEST_CASE("SourcePos: positions of two files are told apart") {
    DiagnosticSink sink;
    const SourceText a{std::make_shared<const std::string>("a.kerf"),
                       std::make_shared<const std::string>("let a = 1;")};
    const SourceText b{std::make_shared<const std::string>("b.kerf"),
                       std::make_shared<const std::string>("\n\nlet b = 2;")};
    const Token ta = tokenize(a, sink)[1];
    const Token tb = tokenize(b, sink)[1];
    CHECK(*sink.locate(ta.pos).file == "a.kerf");
    CHECK(*sink.locate(tb.pos).file == "b.kerf");
    CHECK(sink.locate(tb.pos).line == 3);
    CHECK(sink.locate(tb.pos).col == 5);
    // The same file lexed again keeps its index (found, not remembered twice).
    CHECK(tokenize(a, sink)[1].pos.file == ta.pos.file);
    // No position: no file, line 0, as diagnostics without a place print.
    CHECK(sink.locate(SourcePos{}).line == 0);
}
