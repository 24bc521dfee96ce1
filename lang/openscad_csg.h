/// @file lang/openscad_csg.h
/// @brief OpenSCAD's exported CSG trees (`openscad -o model.csg model.scad`) read into a Scene.
/// A .csg file is OpenSCAD's language restricted to module instantiations whose arguments are
/// literals, so it is read by its own small parser (openscad_parse.cpp) into the tree below,
/// then lowered (openscad_lower.cpp) onto kerf's exact primitives: spheres, cylinders and
/// circles are traced exactly, `$fn`/`$fa`/`$fs` are ignored (one note says how many facets
/// OpenSCAD would have used). OpenSCAD is z-up and kerf y-up: the model is turned by one
/// rotation, (x, y, z) ↦ (x, z, −y), documented in docs/openscad.md.
#pragma once

#include "lang/diagnostic.h"
#include "scene/assets.h"
#include "scene/scene.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace kerf {

/// A literal argument: undef, a boolean, a number, a string or a vector of values.
struct ScadValue {
    enum class Kind : uint8_t { Undef, Bool, Number, String, Vector };
    Kind kind = Kind::Undef;
    bool boolean = false;
    double number = 0.0;
    std::string text;
    std::vector<ScadValue> items;
    SourcePos pos;
};

struct ScadArg {
    std::string name;  ///< empty for a positional argument
    ScadValue value;
    SourcePos pos;  ///< where the argument starts (its name, or its value)
};

/// One module instantiation: `name(args) { children }` or `name(args);`.
struct ScadCall {
    std::string name;
    SourcePos pos;
    /// OpenSCAD's modifier character written before the call: '%' (background: not part of
    /// the model), '*' (disabled), '#' (highlight) or '!' (root), or 0.
    char modifier = 0;
    std::vector<ScadArg> args;
    std::vector<ScadCall> children;

    /// The argument called `name`, else the positional one at `position` (−1: none), or null.
    const ScadArg* arg(const std::string& name, int position = -1) const;
};

/// Parses a .csg text into its top-level calls; syntax errors go to `sink` (parsing goes on
/// at the next statement so several are reported). `file` is the sink's index of the text.
std::vector<ScadCall> parseOpenScadCsg(const std::string& text, uint32_t file,
                                       DiagnosticSink& sink);

/// Reads, parses and lowers a .csg file. On any error returns nullopt with every error found
/// reported to `sink`; notes and warnings are reported either way.
/// Fonts (text) and polyhedra's meshes come from `assets`; without it, none can be had.
std::optional<Scene> compileOpenScadFile(const std::string& path, DiagnosticSink& sink,
                                         AssetProvider& assets);
std::optional<Scene> compileOpenScadFile(const std::string& path, DiagnosticSink& sink);

/// The same for text in memory; `name` is used in diagnostics.
std::optional<Scene> compileOpenScadString(const std::string& text, const std::string& name,
                                           DiagnosticSink& sink, AssetProvider& assets);
std::optional<Scene> compileOpenScadString(const std::string& text, const std::string& name,
                                           DiagnosticSink& sink);

/// True when `path` names an OpenSCAD CSG file (its extension is .csg, in any case).
bool isOpenScadCsgPath(const std::string& path);

}  // namespace kerf
