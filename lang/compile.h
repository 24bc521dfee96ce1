/// @file lang/compile.h
/// @brief The front door of lang/: a model file in, a Scene out (or diagnostics).
#pragma once

#include "lang/diagnostic.h"
#include "lang/eval_limits.h"
#include "lang/sequence_frame.h"
#include "scene/scene.h"

#include <optional>
#include <string>

namespace kerf {

/// Reads, parses and lowers a model file (following its includes). On any error returns
/// nullopt with every error found reported to `sink`. `frame` gives the predefined names
/// `frame` and `time` their values (lang/sequence_frame.h).
std::optional<Scene> compileFile(const std::string& path, DiagnosticSink& sink,
                                 EvalLimits limits = {}, SequenceFrame frame = {});

/// The same for text in memory; `name` is used in diagnostics and to resolve includes
/// (relative to its folder).
std::optional<Scene> compileString(const std::string& text, const std::string& name,
                                   DiagnosticSink& sink, EvalLimits limits = {},
                                   SequenceFrame frame = {});

}  // namespace kerf
