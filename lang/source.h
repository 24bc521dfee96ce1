/// @file lang/source.h
/// @brief Model files as text: reading them and checking that they are UTF-8 text, so the
/// lexer never sees binary garbage.
#pragma once

#include "lang/diagnostic.h"

#include <memory>
#include <optional>
#include <string>

namespace kerf {

/// One source file: the name used in diagnostics and its whole text.
struct SourceText {
    std::shared_ptr<const std::string> name;
    std::shared_ptr<const std::string> text;
};

/// The 1-based line and byte column of byte `offset` in `text`.
SourceLoc locationOf(const SourceText& source, size_t offset);

/// Checks that the text is valid UTF-8 without NUL bytes or control characters other than
/// tab, newline, carriage return, vertical tab and form feed. Reports the first bad byte to
/// `sink` (one diagnostic) and returns false if there is one.
bool checkSourceText(const SourceText& source, DiagnosticSink& sink);

/// Reads the file's bytes; nullopt if it cannot be opened or is not a regular file, with the
/// reason in `why`.
std::optional<std::string> readFileBytes(const std::string& path, std::string& why);

}  // namespace kerf
