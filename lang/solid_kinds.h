/// @file lang/solid_kinds.h
/// @brief The language's side of the kinds of solid: one row per keyword, read by the parser
/// (reserved words, `word { … }` as a solid value), the lowering (dispatch, "needs a block")
/// and the diagnostic hints (the list of solids, POV-Ray's positional forms). The csg side of
/// a kind (traits, name) is csg/tree/kind_registry.h.
#pragma once

#include "csg/tree/node_kind.h"
#include "lang/ast.h"
#include "lang/properties.h"

#include <string>
#include <vector>

namespace kerf {

class Lowering;

/// Where a keyword takes part, as bit flags of SolidKind::uses.
enum SolidUse : unsigned {
    kReserved = 1u << 0,    ///< cannot name a let, a parameter or a loop variable
    kSolidValue = 1u << 1,  ///< `word { … }` in an expression is a solid (Parser::isSolidWord)
    kNeedsBlock = 1u << 2,  ///< the bare word as a solid is "needs a block", not a lookup
    kListed = 1u << 3,      ///< in the messages' list of solids (diagnostic_hints.h)
    kBoolean = 1u << 4,     ///< a Boolean: its block lists solids
};

/// The check a tabled property's value must pass.
enum class PropertyCheck { None, Positive };

/// A property of a tabled kind: its name, type, default and check.
struct SolidProperty {
    const char* name;
    PropertyType type;  ///< Number, Vector or Bool
    bool required = false;
    double number = 0.0;  ///< the default of a Number or Bool (nonzero: true)
    Vec3 vector{0.0};     ///< the default of a Vector
    PropertyCheck check = PropertyCheck::None;
};

/// A property's value after lowering (the member its type names).
struct PropertyValue {
    double number = 0.0;
    Vec3 vector{0.0};
    bool flag = false;
};
using PropertyValues = std::vector<PropertyValue>;  ///< parallel to SolidKind::properties

/// One kind of solid as the language knows it.
struct SolidKind {
    const char* keyword;
    NodeKind node;  ///< the node kind it makes (csg/tree/kind_registry.h)
    unsigned uses;  ///< SolidUse flags
    /// Tabled kinds: the properties, a check of the whole block (an error message, or empty;
    /// may be null) and the factory. Custom kinds leave these empty and name `lower`.
    std::vector<SolidProperty> properties = {};
    std::string (*problem)(const PropertyValues&) = nullptr;
    NodePtr (*make)(const PropertyValues&) = nullptr;
    NodePtr (Lowering::*lower)(const Solid&) = nullptr;  ///< custom lowering, or null
    /// POV-Ray's positional form: kerf's property for each value in POV-Ray's order, and the
    /// placeholders shown when the count does not match; empty for none.
    std::vector<const char*> positionalNames = {};
    std::vector<const char*> positionalPlaceholders = {};

    bool has(SolidUse use) const { return (uses & use) != 0; }
};

/// Every row, in the order messages list the kinds.
const std::vector<SolidKind>& solidKinds();
/// The row of a keyword, or null.
const SolidKind* findSolidKind(const std::string& keyword);
/// The keywords of the rows with `use`, in table order (Booleans excluded unless asked for).
std::vector<std::string> solidKeywords(SolidUse use, bool booleans = false);

/// The error for an axis `from`–`to` that is not usable, or empty: an endpoint or their
/// difference not finite, or no length. `what` names the solid in the message.
std::string axisProblem(const char* what, const Vec3& from, const Vec3& to);

}  // namespace kerf
