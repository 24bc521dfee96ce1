/// @file lang/source.h
/// @brief Model files as text: reading them and checking that they are UTF-8 text, so the
/// lexer never sees binary garbage.
#pragma once

#include "lang/diagnostic.h"
#include "scene/limits.h"

#include <cstdint>
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

/// Reads the file's bytes; nullopt with the reason in `why` if it cannot be opened, is not a
/// regular file (a folder, device, FIFO or socket: /dev/zero would never end, a FIFO would
/// block) or is larger than `maxBytes` (kMaxSourceBytes; tests pass less).
std::optional<std::string> readFileBytes(const std::string& path, std::string& why,
                                         int64_t maxBytes = kMaxSourceBytes);

/// The model file at `path` read as a SourceText (named as written), or nullopt after
/// reporting "cannot read 'PATH': why" to `sink` at the file (both languages' front doors).
std::optional<SourceText> readModelFile(const std::string& path, DiagnosticSink& sink);

/// Why readFileBytes would refuse `path` by what stat() says of it (missing, not a regular
/// file, too large), or an empty string. Does not open the file, so it never blocks.
std::string sourceFileProblem(const std::string& path, int64_t maxBytes = kMaxSourceBytes);

}  // namespace kerf
