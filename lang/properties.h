/// @file lang/properties.h
/// @brief Checks the `name value` pairs of a block against what the block accepts: unknown
/// names, repeated names and missing required names are reported here; values are evaluated
/// by the Lowering.
#pragma once

#include "lang/ast.h"

#include <string>
#include <vector>

namespace kerf {

/// Word: a bare name from a fixed list (`sampler jittered`, `falloff none`), not evaluated.
enum class PropertyType { Number, Vector, NumberOrVector, Solid, Function, Bool, Word };

struct PropertySpec {
    const char* name;
    PropertyType type;
    bool required = false;
};

/// The properties of one block, matched to their specs.
class PropertyBlock {
public:
    /// `what` names the block in messages ("sphere", "camera"); missing properties are reported
    /// at `blockLoc`.
    PropertyBlock(const ArenaList<Property>& properties, std::vector<PropertySpec> specs,
                  std::string what, SourcePos blockLoc, DiagnosticSink& sink);

    /// False when a property was unknown, repeated or missing.
    bool ok() const { return mOk; }
    /// The property given for this spec name, or null.
    const Property* find(const std::string& name) const;
    const PropertySpec& spec(const std::string& name) const;
    const std::string& what() const { return mWhat; }
    SourcePos blockLoc() const { return mBlockLoc; }

private:
    std::vector<PropertySpec> mSpecs;
    std::vector<const Property*> mFound;  // parallel to mSpecs
    std::string mWhat;
    SourcePos mBlockLoc;
    bool mOk = true;
};

}  // namespace kerf
