/// @file lang/compile.h
/// @brief The front door of lang/: a model file in, a Scene out (or diagnostics).
#pragma once

#include "lang/diagnostic.h"
#include "lang/eval_limits.h"
#include "lang/sequence_frame.h"
#include "scene/assets.h"
#include "scene/scene.h"

#include <optional>
#include <string>

namespace kerf {

/// Reads, parses and lowers a model file (following its includes). On any error returns
/// nullopt with every error found reported to `sink`. `frame` gives the predefined names
/// `frame` and `time` their values (lang/sequence_frame.h). The meshes, volumes, textures and
/// fonts the model names come from `assets` (scene/assets.h; assets/asset_cache.h keeps them
/// between compiles).
std::optional<Scene> compileFile(const std::string& path, DiagnosticSink& sink,
                                 AssetProvider& assets, EvalLimits limits = {},
                                 SequenceFrame frame = {});
/// The same without assets: a model that names an asset file is an error there.
std::optional<Scene> compileFile(const std::string& path, DiagnosticSink& sink,
                                 EvalLimits limits = {}, SequenceFrame frame = {});

/// The same for text in memory; `name` is used in diagnostics and to resolve includes
/// (relative to its folder).
std::optional<Scene> compileString(const std::string& text, const std::string& name,
                                   DiagnosticSink& sink, AssetProvider& assets,
                                   EvalLimits limits = {}, SequenceFrame frame = {});
std::optional<Scene> compileString(const std::string& text, const std::string& name,
                                   DiagnosticSink& sink, EvalLimits limits = {},
                                   SequenceFrame frame = {});

}  // namespace kerf
