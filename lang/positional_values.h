/// @file lang/positional_values.h
/// @brief POV-Ray's positional values at the start of a block (`sphere { <0, 0, 0>, 1 }`),
/// read without consuming them, for the hint that shows kerf's form with the user's own values
/// (lang/diagnostic_hints.h). Kept out of the parser: it only looks ahead.
#pragma once

#include <string>
#include <vector>

#include "lang/diagnostic.h"
#include "lang/token_window.h"

namespace kerf {

struct PositionalValues {
    /// The source text of each comma-separated value (white space runs as one blank); empty
    /// when the block starts with a property name.
    std::vector<std::string> values;
    /// The first of POV-Ray's flags after the values (`open`, `sturm`), or empty.
    std::string flag;
};

/// Reads the block whose first token (after its '{') is token `first` of `tokens`: values up
/// to the closing brace, a ';', or the first keyword after a value (`open`, `pigment`).
/// `sink` holds the source text the values are copied from.
PositionalValues readPositionalValues(TokenWindow& tokens, size_t first,
                                      const DiagnosticSink& sink);

}  // namespace kerf
