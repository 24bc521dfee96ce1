// The lexer: one pass over the bytes, tracking line and column, producing tokens.
#include "lang/lexer.h"

#include <charconv>
#include <cstdio>
#include <limits>

namespace kerf {

std::string describe(TokenKind kind) {
    switch (kind) {
        case TokenKind::Number: return "a number";
        case TokenKind::String: return "a string";
        case TokenKind::Identifier: return "a name";
        case TokenKind::Less: return "'<'";
        case TokenKind::Greater: return "'>'";
        case TokenKind::Comma: return "','";
        case TokenKind::Semicolon: return "';'";
        case TokenKind::LBrace: return "'{'";
        case TokenKind::RBrace: return "'}'";
        case TokenKind::LParen: return "'('";
        case TokenKind::RParen: return "')'";
        case TokenKind::LBracket: return "'['";
        case TokenKind::RBracket: return "']'";
        case TokenKind::Equals: return "'='";
        case TokenKind::Plus: return "'+'";
        case TokenKind::Minus: return "'-'";
        case TokenKind::Star: return "'*'";
        case TokenKind::Slash: return "'/'";
        case TokenKind::Caret: return "'^'";
        case TokenKind::Percent: return "'%'";
        case TokenKind::Dot: return "'.'";
        case TokenKind::DotDot: return "'..'";
        case TokenKind::Question: return "'?'";
        case TokenKind::Colon: return "':'";
        case TokenKind::EqualEqual: return "'=='";
        case TokenKind::NotEqual: return "'!='";
        case TokenKind::LessEqual: return "'<='";
        case TokenKind::GreaterEqual: return "'>='";
        case TokenKind::Error: return "an invalid token";
        case TokenKind::End: return "end of file";
    }
    return "a token";
}

std::string describe(const Token& token) {
    switch (token.kind) {
        case TokenKind::Number:
        case TokenKind::Identifier: return "'" + token.text + "'";
        case TokenKind::String: return "\"" + token.text + "\"";
        default: return describe(token.kind);
    }
}

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isIdentStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool isIdentChar(char c) { return isIdentStart(c) || isDigit(c); }

/// Converts a decimal literal; from_chars is locale independent. On overflow returns +inf
/// (the evaluator reports it as not finite), on underflow 0.
double parseNumber(const std::string& text) {
    double v = 0.0;
    const auto res = std::from_chars(text.data(), text.data() + text.size(), v);
    if (res.ec != std::errc::result_out_of_range) return v;
    // Decide overflow versus underflow from the decimal magnitude of the literal.
    long magnitude = 0;
    const size_t e = text.find_first_of("eE");
    const std::string mantissa = text.substr(0, e);
    const size_t point = mantissa.find('.');
    const size_t intDigits = point == std::string::npos ? mantissa.size() : point;
    const size_t firstNonZero = mantissa.find_first_not_of("0.");
    if (firstNonZero == std::string::npos) return 0.0;
    magnitude = firstNonZero < intDigits ? static_cast<long>(intDigits - firstNonZero)
                                         : -static_cast<long>(firstNonZero - intDigits) + 1;
    if (e != std::string::npos) {
        long exponent = 0;
        std::from_chars(text.data() + e + 1 + (text[e + 1] == '+'), text.data() + text.size(),
                        exponent);
        magnitude += exponent;
    }
    return magnitude > 0 ? std::numeric_limits<double>::infinity() : 0.0;
}

}  // namespace

class Lexer {
public:
    Lexer(const SourceText& source, DiagnosticSink& sink)
        : mSource(source),
          mText(*source.text),
          mSink(sink),
          mFile(sink.sourceIndex(source.name, source.text)) {
        if (mText.compare(0, 3, "\xEF\xBB\xBF") == 0) advance(3);  // UTF-8 byte order mark
    }

    /// The next token; after the last one, End (again and again).
    Token next() {
        if (!mDone) {
            const SourceLoc commentStart = loc();
            const SourcePos commentStartPos = pos();
            skipBlanksAndComments();
            if (mCommentError) {  // the rest of the file was an unterminated comment
                mDone = true;
                mAny = true;
                Token bad;
                bad.kind = TokenKind::Error;
                bad.loc = commentStart;
                bad.pos = commentStartPos;
                return bad;
            }
            if (mPos < mText.size()) {
                Token t;
                t.firstOnLine = !mLineHasToken;
                if (!lexToken(t)) t.kind = TokenKind::Error;
                mLineHasToken = true;
                mLastEnd = loc();
                mLastEndPos = pos();
                mAny = true;
                return t;
            }
            mDone = true;
        }
        Token end;
        end.kind = TokenKind::End;
        end.loc = mAny ? mLastEnd : loc();
        end.pos = mAny ? mLastEndPos : pos();
        end.firstOnLine = true;
        return end;
    }

private:
    SourceLoc loc() const { return SourceLoc{mSource.name, mLine, mCol}; }
    SourcePos pos() const { return SourcePos{static_cast<uint32_t>(mPos), mFile}; }
    char peek(size_t ahead = 0) const {
        return mPos + ahead < mText.size() ? mText[mPos + ahead] : '\0';
    }
    void advance(size_t n = 1) {
        for (size_t i = 0; i < n && mPos < mText.size(); ++i, ++mPos) {
            if (mText[mPos] == '\n') {
                ++mLine;
                mCol = 1;
                mLineHasToken = false;
            } else {
                ++mCol;
            }
        }
    }

    void skipBlanksAndComments() {
        while (mPos < mText.size()) {
            const char c = peek();
            if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f') {
                advance();
            } else if (c == '/' && peek(1) == '/') {
                while (mPos < mText.size() && peek() != '\n') advance();
            } else if (c == '/' && peek(1) == '*') {
                const SourceLoc start = loc();
                advance(2);
                while (mPos < mText.size() && !(peek() == '*' && peek(1) == '/')) advance();
                if (mPos >= mText.size()) {
                    mSink.error(start, "unterminated comment", "a '/*' comment ends with '*/'");
                    mCommentError = true;  // the caller leaves an Error token
                    return;
                }
                advance(2);
            } else {
                return;
            }
        }
    }

    /// Lexes one token at mPos; false (with a diagnostic) if the characters there are not one.
    bool lexToken(Token& t) {
        t.loc = loc();
        t.pos = pos();
        const size_t start = mPos;
        const char c = peek();
        if (isDigit(c) || (c == '.' && isDigit(peek(1)))) return lexNumber(t, start);
        if (isIdentStart(c)) {
            while (isIdentChar(peek())) advance();
            t.kind = TokenKind::Identifier;
            t.text = mText.substr(start, mPos - start);
            t.length = static_cast<int>(mPos - start);
            return true;
        }
        if (c == '"') return lexString(t, start);
        if (const TokenKind pair = twoCharacters(c, peek(1)); pair != TokenKind::End) {
            advance(2);
            t.kind = pair;
            t.text = mText.substr(start, 2);
            t.length = 2;
            return true;
        }
        const TokenKind kind = punctuation(c);
        if (kind != TokenKind::End) {
            advance();
            t.kind = kind;
            t.text = std::string(1, c);
            t.length = 1;
            return true;
        }
        reportStray(t.loc);
        return false;
    }

    bool lexNumber(Token& t, size_t start) {
        while (isDigit(peek())) advance();
        if (peek() == '.' && peek(1) != '.') {  // 1..5 is a range, not 1. then .5
            advance();
            while (isDigit(peek())) advance();
        }
        if (peek() == 'e' || peek() == 'E') {
            const size_t sign = (peek(1) == '+' || peek(1) == '-') ? 1 : 0;
            if (!isDigit(peek(1 + sign))) {
                advance(1 + sign);
                mSink.error(t.loc, "malformed number '" + mText.substr(start, mPos - start) + "'",
                            "an exponent needs digits, as in 2e-3");
                return false;
            }
            advance(1 + sign);
            while (isDigit(peek())) advance();
        }
        if (isIdentStart(peek())) {  // 3x: a number running into a name
            const SourceLoc at = loc();
            const std::string number = mText.substr(start, mPos - start);
            while (isIdentChar(peek())) advance();
            mSink.error(at, "unexpected letters after the number '" + number + "'",
                        "write a space or '*' between a number and a name, as in 3*x");
            return false;
        }
        t.kind = TokenKind::Number;
        t.text = mText.substr(start, mPos - start);
        t.number = parseNumber(t.text);
        t.length = static_cast<int>(mPos - start);
        return true;
    }

    bool lexString(Token& t, size_t start) {
        advance();  // opening quote
        while (mPos < mText.size() && peek() != '"' && peek() != '\n') advance();
        if (peek() != '"') {
            mSink.error(t.loc, "unterminated string", "a string ends with '\"' on the same line");
            return false;
        }
        t.kind = TokenKind::String;
        t.text = mText.substr(start + 1, mPos - start - 1);
        advance();
        t.length = static_cast<int>(mPos - start);
        return true;
    }

    static TokenKind twoCharacters(char a, char b) {
        if (a == '.' && b == '.') return TokenKind::DotDot;
        if (b != '=') return TokenKind::End;
        switch (a) {
            case '=': return TokenKind::EqualEqual;
            case '!': return TokenKind::NotEqual;
            case '<': return TokenKind::LessEqual;
            case '>': return TokenKind::GreaterEqual;
            default: return TokenKind::End;
        }
    }

    static TokenKind punctuation(char c) {
        switch (c) {
            case '.': return TokenKind::Dot;
            case '?': return TokenKind::Question;
            case ':': return TokenKind::Colon;
            case '<': return TokenKind::Less;
            case '>': return TokenKind::Greater;
            case ',': return TokenKind::Comma;
            case ';': return TokenKind::Semicolon;
            case '{': return TokenKind::LBrace;
            case '}': return TokenKind::RBrace;
            case '(': return TokenKind::LParen;
            case ')': return TokenKind::RParen;
            case '[': return TokenKind::LBracket;
            case ']': return TokenKind::RBracket;
            case '=': return TokenKind::Equals;
            case '+': return TokenKind::Plus;
            case '-': return TokenKind::Minus;
            case '*': return TokenKind::Star;
            case '/': return TokenKind::Slash;
            case '^': return TokenKind::Caret;
            case '%': return TokenKind::Percent;
            default: return TokenKind::End;
        }
    }

    /// Reports the character at mPos (a whole UTF-8 sequence) and skips it.
    void reportStray(const SourceLoc& at) {
        const unsigned char c = static_cast<unsigned char>(peek());
        size_t n = 1;
        if (c >= 0xC0) n = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : 2;
        std::string shown;
        if (c >= 0x20 && c < 0x7F) {
            shown = "'" + std::string(1, static_cast<char>(c)) + "'";
        } else if (c >= 0x80) {
            shown = "'" + mText.substr(mPos, n) + "'";
        } else {
            char buf[8];
            std::snprintf(buf, sizeof buf, "0x%02X", c);
            shown = buf;
        }
        mSink.error(at, "unexpected character " + shown);
        advance(n);
    }

    const SourceText& mSource;
    const std::string& mText;
    DiagnosticSink& mSink;
    uint32_t mFile;  // the sink's index of this file, for SourcePos
    size_t mPos = 0;
    int mLine = 1;
    int mCol = 1;
    bool mLineHasToken = false;
    bool mCommentError = false;  // an unterminated comment ran to the end: leave an Error token
    bool mDone = false;          // at the end: only End from now on
    bool mAny = false;           // a token other than End was returned
    SourceLoc mLastEnd;
    SourcePos mLastEndPos;
};

TokenStream::TokenStream(const SourceText& source, DiagnosticSink& sink)
    : mLexer(std::make_unique<Lexer>(source, sink)) {}
TokenStream::~TokenStream() = default;
Token TokenStream::next() { return mLexer->next(); }

std::vector<Token> tokenize(const SourceText& source, DiagnosticSink& sink) {
    TokenStream stream(source, sink);
    std::vector<Token> tokens;
    do tokens.push_back(stream.next());
    while (tokens.back().kind != TokenKind::End);
    return tokens;
}

}  // namespace kerf
