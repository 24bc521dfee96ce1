/// @file lang/lexer.h
/// @brief Splits model text into tokens, each with its SourceLoc. Comments and white space are
/// dropped; malformed input (unterminated comments or strings, stray characters) is reported to
/// the sink and skipped, so the parser still sees the rest of the file.
#pragma once

#include "lang/diagnostic.h"
#include "lang/source.h"

#include <memory>
#include <string>
#include <vector>

namespace kerf {

enum class TokenKind {
    Number,
    String,
    Identifier,
    Less,
    Greater,
    Comma,
    Semicolon,
    LBrace,
    RBrace,
    LParen,
    RParen,
    LBracket,
    RBracket,
    Equals,
    Plus,
    Minus,
    Star,
    Slash,
    Caret,
    Percent,
    Dot,
    DotDot,
    Question,
    Colon,
    EqualEqual,
    NotEqual,
    LessEqual,
    GreaterEqual,
    Error,  ///< characters the lexer already reported; the parser stays silent about them
    End,
};

struct Token {
    TokenKind kind = TokenKind::End;
    std::string text;     ///< identifier name, string contents (unquoted), or the spelling
    double number = 0.0;  ///< for numbers; +inf when the literal overflows a double
    SourceLoc loc;
    SourcePos pos;             ///< the same place, as the syntax tree keeps it
    int length = 0;            ///< bytes the token spans in the source (all tokens are on one line)
    bool firstOnLine = false;  ///< nothing but white space or comments before it on its line
};

/// A readable name for a token kind, e.g. "';'" or "a number", for "expected …" messages.
std::string describe(TokenKind kind);
/// A readable description of a token, e.g. "'foo'" or "end of file".
std::string describe(const Token& token);

class Lexer;

/// The tokens of a text, lexed as they are asked for: a parser that drops the tokens of the
/// statements it has finished holds only a statement's worth, not the whole file's (tokens
/// took 30 bytes of memory per byte of a model). Errors go to the sink as they are met.
class TokenStream {
public:
    TokenStream(const SourceText& source, DiagnosticSink& sink);  ///< both must outlive it
    ~TokenStream();
    /// The next token; End, again and again, after the last.
    Token next();

private:
    std::unique_ptr<Lexer> mLexer;
};

/// Tokenizes the whole text. The last token is always End, placed just after the last
/// non-blank character. Errors go to `sink` and leave an Error token in the stream.
std::vector<Token> tokenize(const SourceText& source, DiagnosticSink& sink);

}  // namespace kerf
