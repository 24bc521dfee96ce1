/// @file lang/parser.h
/// @brief Hand-written recursive-descent parser: tokens in, a Program out. After a syntax
/// error it skips to the next statement and goes on, so one run reports several errors.
/// Nesting deeper than kMaxNesting levels is an error, not a stack overflow.
#pragma once

#include "lang/ast.h"
#include "lang/lexer.h"
#include "scene/limits.h"  // kMaxNesting, kMaxExpressionDepth

#include <vector>

namespace kerf {

/// Parses the tokens of one file (the last must be End). Syntax errors go to `sink`; the
/// statements that parsed are returned either way.
Program parse(const std::vector<Token>& tokens, DiagnosticSink& sink);
/// The same, lexing as it goes and keeping only the current statement's tokens.
Program parse(TokenStream& tokens, DiagnosticSink& sink);

/// True for words that cannot name a let, solid or material (keywords of the language).
bool isReservedWord(const std::string& word);

}  // namespace kerf
