/// @file lang/diagnostic_hints.h
/// @brief The hints for mistakes people make when they come from another modeller: solid and
/// property names from POV-Ray or OpenSCAD (merge, plane, cube, open, pigment), POV-Ray's
/// positional values (`sphere { <0, 0, 0>, 1 }`) and OpenSCAD's call syntax (`cube(1)`).
/// Only the tables and the text live here; the parser and the lowering decide when to use them.
#pragma once

#include <string>
#include <vector>

namespace kerf {

/// kerf's primitive solids and its Booleans, in the order messages list them.
const std::vector<std::string>& primitiveKinds();
const std::vector<std::string>& booleanKinds();
/// True for a primitive or a Boolean.
bool isSolidKind(const std::string& name);
/// circle, rect, polygon, path, offset: 2-D profiles, written inside extrude and revolve.
bool isProfileKind(const std::string& name);

/// The hint for a name used as a solid that kerf does not know: a near-miss spelling
/// (edit distance at most 2), or what kerf has instead of another modeller's solid, then the
/// list of solids.
/// With POV-Ray's positional `values` in the block, a solid that has a kerf equivalent is
/// shown in kerf's form with those values.
std::string unknownSolidHint(const std::string& name, const std::vector<std::string>& values = {});

/// What kerf has instead of another modeller's solid (merge → "use 'union': …"), or empty.
std::string foreignSolidHint(const std::string& name);

/// kerf's solid for another modeller's solid of the same meaning (plane → halfspace, merge →
/// union), or empty.
std::string kerfSolidFor(const std::string& foreign);

/// A note on a property another modeller has and kerf does not (open, sturm, pigment,
/// contained_by), or empty.
std::string foreignPropertyNote(const std::string& property);

/// POV-Ray's flags, written without a value (open, sturm, hollow …).
bool isForeignFlag(const std::string& property);

/// kerf's form of a primitive written with POV-Ray's positional values, the user's values
/// filled in when there are as many as POV-Ray takes, placeholders otherwise; empty for a
/// kind with no positional form.
std::string namedForm(const std::string& kind, const std::vector<std::string>& values);

/// The hint for POV-Ray's positional values in a kerf primitive: kerf's form with them, and
/// the note on a POV-Ray `flag` written after them (e.g. open), if any.
std::string positionalHint(const std::string& kind, const std::vector<std::string>& values,
                           const std::string& flag);

/// The hint for OpenSCAD's call syntax `name(…)` where kerf expects a solid or a statement,
/// or empty when `name` is none of OpenSCAD's solids, Booleans or transforms.
std::string callSyntaxHint(const std::string& name);

/// The hint for a statement word of another modeller (light_source, global_settings), or empty.
std::string foreignStatementHint(const std::string& word);

/// Why the bound of an implicit must be a box written in place (the hint of that error).
std::string implicitBoundHint();

}  // namespace kerf
