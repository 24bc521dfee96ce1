/// @file app/model_loader.h
/// @brief Reading a model file for a command: checks it can be read, compiles it and prints
/// the diagnostics, so `render` and `check` report problems the same way.
#pragma once

#include "assets/asset_cache.h"
#include "lang/sequence_frame.h"
#include "scene/scene.h"

#include <iosfwd>
#include <optional>
#include <string>

namespace kerf::app {

/// Compiles the model at `path` (an OpenSCAD .csg export when its extension is .csg,
/// lang/openscad_csg.h; else a .kerf model). On failure prints to `err` either `kerf: error: cannot
/// read model file …` or the compiler's diagnostics, and returns nullopt (the caller exits with
/// kExitUsage). Warnings are printed too when the model compiles.
/// `quiet` leaves out the model's echo lines (errors and warnings are always printed).
/// `frame` sets the predefined `frame` and `time` of a .kerf model (`kerf render --frames`).
/// Assets (meshes, volumes, textures, fonts) come from `assets`, which keeps them for the next
/// compile; its inputs() then list the files this compile read.
std::optional<Scene> loadModel(const std::string& path, std::ostream& err, AssetCache& assets,
                               bool quiet = false, SequenceFrame frame = {});
/// The same with processAssets().
std::optional<Scene> loadModel(const std::string& path, std::ostream& err, bool quiet = false,
                               SequenceFrame frame = {});

/// The asset cache the commands of this process compile with: the frames of a sequence
/// (app/frame_sequence.h) share every unchanged mesh, volume, texture and font.
AssetCache& processAssets();

}  // namespace kerf::app
