/// @file app/option_text.h
/// @brief The pieces of command-line option values the commands share: whole numbers, "x,y,z"
/// triples and "axis=value" specs. Each returns nothing on bad text; the command names the
/// option in its own message.
#pragma once

#include "csg/types.h"

#include <optional>
#include <string>
#include <utility>

namespace kerf::app {

/// The whole of `text` as a number (strtod: "nan" and "inf" parse; callers that need a finite
/// value check it), or nothing when the text is empty or has more after the number.
std::optional<double> parseWholeNumber(const std::string& text);

/// The whole of `text` as a number, else UsageError "OPTION must be a number (got 'TEXT')".
double numberOption(const std::string& option, const std::string& text);

/// "A,B,C" as three finite numbers, or nothing.
std::optional<Vec3> parseTriple(const std::string& text);

/// "x=REST", "y=REST" or "z=REST" with REST not empty: the axis (0, 1, 2) and REST.
std::optional<std::pair<int, std::string>> parseAxisSpec(const std::string& spec);

}  // namespace kerf::app
