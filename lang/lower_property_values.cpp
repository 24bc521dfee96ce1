// Lowering: reading a block's properties as values of the kind a caller wants (number,
// vector, integer in a range, boolean, one of a set of words), each with its own message.
#include "lang/lower.h"

#include "lang/diagnostic_hints.h"
#include "lang/names.h"

#include <algorithm>
#include <cmath>

namespace kerf {

std::optional<Value> Lowering::propertyValue(const PropertyBlock& block, const std::string& name) {
    const Property* p = block.find(name);
    const PropertyType type = block.spec(name).type;
    const auto expected = [&]() -> std::string {
        switch (type) {
            case PropertyType::Number: return "a number";
            case PropertyType::Vector: return "a vector";
            case PropertyType::NumberOrVector: return "a number or a vector";
            case PropertyType::Solid: return "a solid";
            case PropertyType::Function: return "a function of x, y, z";
            case PropertyType::Bool: return "true or false";
            case PropertyType::Word: return "a name";
        }
        return "a value";
    };
    const std::string subject = "property '" + name + "' of " + block.what();
    if (p->solid) {
        error(p->solid->loc, subject + " expects " + expected() + ", got a solid");
        return std::nullopt;
    }
    const auto v = evaluate(*p->expr, nullptr);
    if (!v) return std::nullopt;
    const bool ok = type == PropertyType::Bool
                        ? v->type == Value::Type::Bool
                        : (v->type == Value::Type::Number && type != PropertyType::Vector) ||
                              (v->type == Value::Type::Vector && type != PropertyType::Number);
    if (!ok) {
        error(p->expr->start, subject + " expects " + expected() + ", got " + typeName(v->type));
        return std::nullopt;
    }
    return v;
}

bool Lowering::readNumber(const PropertyBlock& block, const std::string& name, double& out) {
    if (!block.find(name)) return true;
    const auto v = propertyValue(block, name);
    if (v) out = v->number;
    return v.has_value();
}

bool Lowering::readVector(const PropertyBlock& block, const std::string& name, Vec3& out) {
    if (!block.find(name)) return true;
    const auto v = propertyValue(block, name);
    if (v) out = v->vector;
    return v.has_value();
}

bool Lowering::readInteger(const PropertyBlock& block, const std::string& name, int lo, int hi,
                           int& out) {
    double v = out;
    if (!readNumber(block, name, v)) return false;
    if (v != std::floor(v) || v < lo || v > hi) {
        error(block.find(name)->valueLoc(),
              block.what() + " " + name + " must be an integer from " + std::to_string(lo) +
                  " to " + std::to_string(hi) + ", got " + formatNumber(v));
        return false;
    }
    out = static_cast<int>(v);
    return true;
}

bool Lowering::readBool(const PropertyBlock& block, const std::string& name, bool& out) {
    if (!block.find(name)) return true;
    const auto v = propertyValue(block, name);
    if (v) out = v->truth();
    return v.has_value();
}

bool Lowering::readWord(const PropertyBlock& block, const std::string& name,
                        const std::vector<std::string>& choices, std::string& out) {
    const Property* p = block.find(name);
    if (!p) return true;
    const std::string list = joinNames(choices);
    const std::string subject = "property '" + name + "' of " + block.what();
    if (p->solid || p->expr->kind != Expr::Kind::Name) {
        error(p->solid ? p->solid->loc : p->expr->start, subject + " expects one of " + list,
              "write e.g. '" + name + " " + choices.front() + "'");
        return false;
    }
    const std::string& word = *p->expr->ident;
    if (std::find(choices.begin(), choices.end(), word) == choices.end()) {
        const std::string hint = didYouMean(word, choices);
        error(p->expr->loc, "unknown " + name + " '" + word + "' in " + block.what(),
              hint.empty() ? name + " is one of " + list : hint);
        return false;
    }
    out = word;
    return true;
}

}  // namespace kerf
