// Tokens, their values and their positions, from literal strings.
#include "lang/lexer.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace kerf;

namespace {

std::vector<Token> lex(const std::string& text, DiagnosticSink& sink) {
    const SourceText source{std::make_shared<const std::string>("t.kerf"),
                            std::make_shared<const std::string>(text)};
    return tokenize(source, sink);
}

}  // namespace

TEST_CASE("tokenize") {
    DiagnosticSink sink;

    SECTION("numbers in every form") {
        const auto t = lex("1 0.5 2e-3 .5 1E2 3. 1e+1", sink);
        REQUIRE(t.size() == 8);
        const double expected[] = {1.0, 0.5, 2e-3, 0.5, 100.0, 3.0, 10.0};
        for (int i = 0; i < 7; ++i) {
            CHECK(t[i].kind == TokenKind::Number);
            CHECK(t[i].number == expected[i]);
        }
        CHECK(t[7].kind == TokenKind::End);
        CHECK(sink.errorCount() == 0);
    }

    SECTION("overflowing literals become inf, underflowing ones 0") {
        const auto t = lex("1e400 1e-400 0.000001e-320 999e306", sink);
        CHECK(std::isinf(t[0].number));
        CHECK(t[1].number == 0.0);
        CHECK(t[2].number == 0.0);
        CHECK(std::isinf(t[3].number));
    }

    SECTION("punctuation, names and strings with positions") {
        const auto t = lex("let a_1 = <1, 2>;\n  include \"x.kerf\" { } ( ) [ ] + - * / ^", sink);
        const TokenKind kinds[] = {
            TokenKind::Identifier, TokenKind::Identifier, TokenKind::Equals, TokenKind::Less,
            TokenKind::Number,     TokenKind::Comma,      TokenKind::Number, TokenKind::Greater,
            TokenKind::Semicolon,  TokenKind::Identifier, TokenKind::String, TokenKind::LBrace,
            TokenKind::RBrace,     TokenKind::LParen,     TokenKind::RParen, TokenKind::LBracket,
            TokenKind::RBracket,   TokenKind::Plus,       TokenKind::Minus,  TokenKind::Star,
            TokenKind::Slash,      TokenKind::Caret,      TokenKind::End};
        REQUIRE(t.size() == std::size(kinds));
        for (size_t i = 0; i < t.size(); ++i) CHECK(t[i].kind == kinds[i]);
        CHECK(t[1].text == "a_1");
        CHECK(t[1].loc.line == 1);
        CHECK(t[1].loc.col == 5);
        CHECK(t[9].loc.line == 2);
        CHECK(t[9].loc.col == 3);
        CHECK(t[9].firstOnLine);
        CHECK_FALSE(t[10].firstOnLine);
        CHECK(t[10].text == "x.kerf");
        CHECK(t[10].length == 8);
        CHECK(sink.errorCount() == 0);
    }

    SECTION("comments are skipped, positions count bytes") {
        const auto t = lex("/* a\n b */ x // y\n\t// z\nz", sink);
        REQUIRE(t.size() == 3);
        CHECK(t[0].text == "x");
        CHECK(t[0].loc.line == 2);
        CHECK(t[0].loc.col == 7);
        CHECK(t[1].text == "z");
        CHECK(t[1].loc.line == 4);
        CHECK(t[1].loc.col == 1);
    }

    SECTION("end of file sits just after the last token") {
        const auto t = lex("a bc  \n\n", sink);
        REQUIRE(t.size() == 3);
        CHECK(t[2].kind == TokenKind::End);
        CHECK(t[2].loc.line == 1);
        CHECK(t[2].loc.col == 5);
    }

    SECTION("errors leave an Error token and lexing goes on") {
        const auto t = lex("a # b \"open\nc /* never closed", sink);
        REQUIRE(sink.errorCount() == 3);
        CHECK(sink.diagnostics()[0].message == "unexpected character '#'");
        CHECK(sink.diagnostics()[0].loc.col == 3);
        CHECK(sink.diagnostics()[1].message == "unterminated string");
        CHECK(sink.diagnostics()[1].loc.col == 7);
        CHECK(sink.diagnostics()[2].message == "unterminated comment");
        CHECK(sink.diagnostics()[2].loc.line == 2);
        CHECK(sink.diagnostics()[2].loc.col == 3);
        const TokenKind kinds[] = {
            TokenKind::Identifier, TokenKind::Error, TokenKind::Identifier, TokenKind::Error,
            TokenKind::Identifier, TokenKind::Error, TokenKind::End};
        REQUIRE(t.size() == std::size(kinds));
        for (size_t i = 0; i < t.size(); ++i) CHECK(t[i].kind == kinds[i]);
    }

    SECTION("malformed numbers") {
        lex("2e+ 3x", sink);
        REQUIRE(sink.errorCount() == 2);
        CHECK(sink.diagnostics()[0].message == "malformed number '2e+'");
        CHECK(sink.diagnostics()[1].message == "unexpected letters after the number '3'");
        CHECK(sink.diagnostics()[1].loc.col == 6);
    }
}
