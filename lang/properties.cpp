// Matching a block's properties to its specs, with the errors users make most.
#include "lang/properties.h"

#include "lang/diagnostic_hints.h"
#include "lang/names.h"

#include <stdexcept>

namespace kerf {

namespace {

/// A value of the type, as a hint shows it.
const char* exampleValue(PropertyType type) {
    switch (type) {
        case PropertyType::Number: return "1";
        case PropertyType::Vector: return "<x, y, z>";
        case PropertyType::NumberOrVector: return "1' or '<x, y, z>";
        case PropertyType::Solid: return "box { min … max … }";
        case PropertyType::Function: return "x^2 + y^2 + z^2 - 1";
        case PropertyType::Bool: return "true";
        case PropertyType::Word: return "a name";
    }
    return "…";
}

}  // namespace

PropertyBlock::PropertyBlock(const ArenaList<Property>& properties, std::vector<PropertySpec> specs,
                             std::string what, SourcePos blockLoc, DiagnosticSink& sink)
    : mSpecs(std::move(specs)),
      mFound(mSpecs.size(), nullptr),
      mWhat(std::move(what)),
      mBlockLoc(blockLoc) {
    std::vector<std::string> valid;
    for (const PropertySpec& s : mSpecs) valid.emplace_back(s.name);
    std::vector<bool> named(mSpecs.size(), false);  // given, with or without a value
    for (const Property& p : properties) {
        size_t i = 0;
        while (i < mSpecs.size() && p.name != mSpecs[i].name) ++i;
        if (i == mSpecs.size()) {
            std::string hint = didYouMean(p.name, valid);
            if (hint.empty()) hint = foreignPropertyNote(p.name);
            hint += (hint.empty()         ? ""
                     : hint.back() == '?' ? " "
                                          : "; ") +
                    mWhat + " takes: " + joinNames(valid);
            sink.error(p.loc, "unknown property '" + p.name + "' in " + mWhat, hint);
            mOk = false;
        } else if (!p.expr && !p.solid) {  // the parser found no value after the name
            sink.error(p.loc, "property '" + p.name + "' of " + mWhat + " has no value",
                       "write its value after the name: '" + p.name + " " +
                           exampleValue(mSpecs[i].type) + "'");
            named[i] = true;
            mOk = false;
        } else if (mFound[i]) {
            sink.error(p.loc, "property '" + p.name + "' given twice in " + mWhat,
                       "first given at line " + std::to_string(sink.locate(mFound[i]->loc).line) +
                           ", column " + std::to_string(sink.locate(mFound[i]->loc).col));
            mOk = false;
        } else {
            mFound[i] = &p;
        }
    }
    for (size_t i = 0; i < mSpecs.size(); ++i) {
        if (mSpecs[i].required && !mFound[i] && !named[i]) {
            sink.error(mBlockLoc,
                       mWhat + " needs the property '" + std::string(mSpecs[i].name) + "'");
            mOk = false;
        }
    }
}

const Property* PropertyBlock::find(const std::string& name) const {
    for (size_t i = 0; i < mSpecs.size(); ++i)
        if (name == mSpecs[i].name) return mFound[i];
    return nullptr;
}

const PropertySpec& PropertyBlock::spec(const std::string& name) const {
    for (const PropertySpec& s : mSpecs)
        if (name == s.name) return s;
    throw std::logic_error("PropertyBlock::spec: no property " + name);
}

}  // namespace kerf
