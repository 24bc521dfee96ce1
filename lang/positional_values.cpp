// Looking ahead over POV-Ray's positional values: commas at bracket depth 0 separate them;
// '<' and '>' count as brackets, as in a vector.
#include "lang/positional_values.h"

#include "lang/diagnostic_hints.h"

namespace kerf {

namespace {

/// Runs of white space (line breaks too) as one blank, so a hint stays on one line.
std::string oneLine(const std::string& text) {
    std::string out;
    for (const char c : text) {
        const bool blank = c == ' ' || c == '\t' || c == '\n' || c == '\r';
        if (!blank)
            out += c;
        else if (!out.empty() && out.back() != ' ')
            out += ' ';
    }
    return out;
}

bool endsOperand(TokenKind k) {
    return k == TokenKind::Number || k == TokenKind::Identifier || k == TokenKind::RParen ||
           k == TokenKind::RBracket || k == TokenKind::Greater;
}

int depthChange(TokenKind k) {
    switch (k) {
        case TokenKind::LParen:
        case TokenKind::LBracket:
        case TokenKind::Less:
        case TokenKind::LBrace: return 1;
        case TokenKind::RParen:
        case TokenKind::RBracket:
        case TokenKind::Greater:
        case TokenKind::RBrace: return -1;
        default: return 0;
    }
}

}  // namespace

PositionalValues readPositionalValues(TokenWindow& tokens, size_t first,
                                      const DiagnosticSink& sink) {
    PositionalValues out;
    const auto kind = [&](size_t i) { return tokens.at(i).kind; };
    const TokenKind k0 = kind(first);
    const bool startsValue = k0 == TokenKind::Number || k0 == TokenKind::Less ||
                             k0 == TokenKind::Minus || k0 == TokenKind::Plus ||
                             k0 == TokenKind::LParen || k0 == TokenKind::LBracket ||
                             (k0 == TokenKind::Identifier && kind(first + 1) == TokenKind::Comma);
    if (!startsValue) return out;
    int depth = 0;
    size_t start = first;  // of the current value
    size_t i = first;
    for (;; ++i) {
        const TokenKind k = kind(i);
        const bool stop =
            k == TokenKind::End || k == TokenKind::Semicolon ||
            (depth == 0 && (k == TokenKind::RBrace || k == TokenKind::Comma ||
                            (k == TokenKind::Identifier && i > start && endsOperand(kind(i - 1)))));
        if (!stop) {
            depth += depthChange(k);
            continue;
        }
        if (i > start) {
            const Token& last = tokens.at(i - 1);
            const SourcePos from = tokens.at(start).pos;
            out.values.push_back(
                oneLine(sink.textAt(from, last.pos.offset + last.length - from.offset)));
        }
        if (k != TokenKind::Comma) break;
        start = i + 1;
    }
    // The words after the values, up to the block's end: POV-Ray's flags such as `open`.
    for (depth = 0; kind(i) != TokenKind::End && kind(i) != TokenKind::Semicolon; ++i) {
        if (depth == 0 && kind(i) == TokenKind::RBrace) break;
        if (depth == 0 && kind(i) == TokenKind::Identifier && isForeignFlag(tokens.at(i).text)) {
            out.flag = tokens.at(i).text;
            break;
        }
        depth += kind(i) == TokenKind::LBrace ? 1 : kind(i) == TokenKind::RBrace ? -1 : 0;
    }
    return out;
}

}  // namespace kerf
