// Lowering, part 5: the values beyond numbers and vectors. Booleans, strings and lists,
// comparisons and short-circuit logic, indexing, ranges (walked as a + i·step, so no error
// accumulates), list comprehensions and the built-in functions on these values.
#include "lang/lower.h"

#include "csg/normalize.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace kerf {

namespace {

const char* comparisonSpelling(char op) {
    switch (op) {
        case '<': return "<";
        case '>': return ">";
        case 'l': return "<=";
        case 'g': return ">=";
        case 'e': return "==";
        default: return "!=";
    }
}

bool equalValues(const Value& a, const Value& b) {
    if (a.type != b.type) return false;
    switch (a.type) {
        case Value::Type::Number:
        case Value::Type::Bool: return a.number == b.number;
        case Value::Type::Vector: return a.vector == b.vector;
        case Value::Type::String: return a.string() == b.string();
        case Value::Type::Solid: return a.solid == b.solid;
        case Value::Type::Field: return a.field == b.field;
        case Value::Type::List:
            if (a.list().size() != b.list().size()) return false;
            for (size_t i = 0; i < a.list().size(); ++i)
                if (!equalValues(a.list()[i], b.list()[i])) return false;
            return true;
    }
    return false;
}

/// A 64-bit mix (splitmix64's finaliser): every input bit affects every output bit.
uint64_t mix64(uint64_t z) {
    z += 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/// The number of values of `from .. to step step`: those from + k·step, k ≥ 0, not past `to`.
/// `to` counts when it is within 1e-9 of a step of a value (0 .. 0.3 step 0.1 has four
/// values although 0.3 / 0.1 = 2.9999999999999996 in doubles).
int64_t rangeCount(double from, double to, double step) {
    const double steps = (to - from) / step;
    if (steps < -1e-9) return 0;
    const double n = std::floor(steps + 1e-9);
    return n >= 9e15 ? INT64_MAX : static_cast<int64_t>(n) + 1;
}

}  // namespace

std::optional<Value> Lowering::evaluateValue(const Expr& e, ExprGraph* field) {
    switch (e.kind) {
        case Expr::Kind::Bool: return Value::ofBool(e.number != 0.0);
        case Expr::Kind::String: return Value::ofString(e.name());
        case Expr::Kind::List: return listOf(e, field);
        case Expr::Kind::Range: {
            ValueList items;
            bool ok = iterate(e, std::string(), e.loc, [&]() {
                if (static_cast<int64_t>(items.size()) >= mLimits.listLength) {
                    error(e.loc,
                          "list longer than " + std::to_string(mLimits.listLength) + " elements");
                    return false;
                }
                items.push_back(mLocals.back().second);
                return true;
            });
            if (!ok) return std::nullopt;
            return Value::ofList(std::move(items));
        }
        case Expr::Kind::Comprehension: return comprehension(e, field);
        case Expr::Kind::Not: {
            const auto a = evaluate(e.args()[0], field);
            if (!a) return std::nullopt;
            if (a->type != Value::Type::Bool) {
                error(e.args()[0].start, "'not' expects a boolean, got " + typeName(a->type));
                return std::nullopt;
            }
            return Value::ofBool(!a->truth());
        }
        case Expr::Kind::Choose: {
            const auto c = evaluate(e.args()[0], field);
            if (!c) return std::nullopt;
            if (c->type != Value::Type::Bool) {
                error(e.args()[0].start,
                      "the condition of '?' must be a boolean, got " + typeName(c->type),
                      "compare it, as in n > 0 ? a : b");
                return std::nullopt;
            }
            return evaluate(e.args()[c->truth() ? 1 : 2], field);
        }
        case Expr::Kind::Index: return index(e, field);
        case Expr::Kind::Member: return member(e, field);
        case Expr::Kind::SolidValue: {
            NodePtr node = lowerSolid(*e.solid);
            if (!node) return std::nullopt;
            return Value::ofSolid(node);
        }
        case Expr::Kind::NamedArg:
            error(e.loc, "a named argument '" + e.name() + " = …' is allowed only in a call");
            return std::nullopt;
        default: break;
    }
    return std::nullopt;
}

std::optional<Value> Lowering::logic(const Expr& e, ExprGraph* field) {
    const char* word = e.op == '&' ? "and" : "or";
    const auto operand = [&](const Expr& x) -> std::optional<Value> {
        auto v = evaluate(x, field);
        if (v && v->type != Value::Type::Bool) {
            error(x.start,
                  std::string("'") + word + "' expects booleans, got " + typeName(v->type));
            return std::nullopt;
        }
        return v;
    };
    const auto a = operand(e.args()[0]);
    if (!a) return std::nullopt;
    // Short circuit: the right side is not evaluated (nor checked) when the left decides.
    if (e.op == '&' && !a->truth()) return a;
    if (e.op == '|' && a->truth()) return a;
    return operand(e.args()[1]);
}

std::optional<Value> Lowering::compare(char op, const Value& a, const Value& b, SourcePos at) {
    using T = Value::Type;
    const std::string spelling = comparisonSpelling(op);
    if (a.type == T::Field || b.type == T::Field) {
        error(at,
              "cannot compare " + typeName(a.type) + " and " + typeName(b.type) + " with '" +
                  spelling + "'",
              "inside f, write conditions with min and max");
        return std::nullopt;
    }
    if (op == 'e' || op == 'n') {
        if (a.type != b.type) {
            error(at, "cannot compare " + typeName(a.type) + " and " + typeName(b.type) +
                          " with '" + spelling + "'");
            return std::nullopt;
        }
        return Value::ofBool(equalValues(a, b) == (op == 'e'));
    }
    if (a.type == T::Number && b.type == T::Number) {
        const double x = a.number, y = b.number;
        return Value::ofBool(op == '<' ? x < y : op == '>' ? x > y : op == 'l' ? x <= y : x >= y);
    }
    if (a.type == T::String && b.type == T::String) {
        const int c = a.string().compare(b.string());
        return Value::ofBool(op == '<' ? c < 0 : op == '>' ? c > 0 : op == 'l' ? c <= 0 : c >= 0);
    }
    error(at,
          "cannot compare " + typeName(a.type) + " and " + typeName(b.type) + " with '" + spelling +
              "'",
          "'<', '<=', '>' and '>=' compare two numbers or two strings");
    return std::nullopt;
}

std::optional<Value> Lowering::concatenate(const Value& a, const Value& b, SourcePos at) {
    if (a.type == Value::Type::String && b.type == Value::Type::String) {
        if (static_cast<int64_t>(a.string().size() + b.string().size()) > kMaxStringLength) {
            error(at, "string longer than " + std::to_string(kMaxStringLength) + " bytes");
            return std::nullopt;
        }
        return Value::ofString(a.string() + b.string());
    }
    if (static_cast<int64_t>(a.list().size() + b.list().size()) > mLimits.listLength) {
        error(at, "list longer than " + std::to_string(mLimits.listLength) + " elements");
        return std::nullopt;
    }
    ValueList items = a.list();
    items.insert(items.end(), b.list().begin(), b.list().end());
    return Value::ofList(std::move(items));
}

std::optional<Value> Lowering::listOf(const Expr& e, ExprGraph* field) {
    if (static_cast<int64_t>(e.args().size()) > mLimits.listLength) {
        error(e.loc, "list longer than " + std::to_string(mLimits.listLength) + " elements");
        return std::nullopt;
    }
    ValueList items;
    items.reserve(e.args().size());
    for (const Expr& a : e.args()) {
        auto v = evaluate(a, field);
        if (!v) return std::nullopt;
        items.push_back(std::move(*v));
    }
    return Value::ofList(std::move(items));
}

std::optional<Value> Lowering::comprehension(const Expr& e, ExprGraph* field) {
    ValueList items;
    const bool filtered = e.args().size() == 3;
    const bool ok = iterate(e.args()[0], e.name(), e.loc, [&]() {
        if (filtered) {
            const auto c = evaluate(e.args()[2], field);
            if (!c) return false;
            if (c->type != Value::Type::Bool) {
                error(e.args()[2].start,
                      "the condition of a list comprehension must be a boolean, got " +
                          typeName(c->type));
                return false;
            }
            if (!c->truth()) return true;
        }
        auto v = evaluate(e.args()[1], field);
        if (!v) return false;
        if (static_cast<int64_t>(items.size()) >= mLimits.listLength) {
            error(e.start, "list longer than " + std::to_string(mLimits.listLength) + " elements");
            return false;
        }
        items.push_back(std::move(*v));
        return true;
    });
    if (!ok) return std::nullopt;
    return Value::ofList(std::move(items));
}

bool Lowering::countIteration(SourcePos at) {
    if (++mIterations <= mLimits.iterations) return true;
    if (!mLimitReported) {
        mLimitReported = true;
        error(at,
              "more than " + std::to_string(mLimits.iterations) +
                  " loop iterations and function calls in this model",
              "the limit keeps a runaway loop from hanging; see docs/language.md, Limits");
    }
    return false;
}

bool Lowering::iterate(const Expr& range, const std::string& var, SourcePos varLoc,
                       const std::function<bool()>& body) {
    const size_t mark = mLocals.size();
    const auto run = [&](Value v) {
        mLocals.resize(mark);
        pushLocal(var, std::move(v));
        const bool go = countIteration(varLoc) && body();
        mLocals.resize(mark);
        return go;
    };
    if (range.kind == Expr::Kind::Range) {
        double bounds[3] = {0.0, 0.0, 1.0};
        for (size_t i = 0; i < range.args().size(); ++i) {
            const auto v = evaluate(range.args()[i], nullptr);
            if (!v) return false;
            if (v->type != Value::Type::Number) {
                error(range.args()[i].start, std::string("the ") +
                                                 (i == 0   ? "start"
                                                  : i == 1 ? "end"
                                                           : "step") +
                                                 " of a range must be a number, got " +
                                                 typeName(v->type));
                return false;
            }
            bounds[i] = v->number;
        }
        const auto [from, to, step] = bounds;
        if (!(step != 0.0) || !std::isfinite(step)) {
            error(range.args().size() == 3 ? range.args()[2].start : range.loc,
                  "the step of a range must be a finite number other than 0, got " +
                      formatNumber(step));
            return false;
        }
        const int64_t n = rangeCount(from, to, step);
        for (int64_t k = 0; k < n; ++k)
            if (!run(Value::ofNumber(from + static_cast<double>(k) * step))) return false;
        return true;
    }
    const auto v = evaluate(range, nullptr);
    if (!v) return false;
    if (v->type != Value::Type::List) {
        error(range.start, "a loop goes over a range or a list, got " + typeName(v->type),
              "write a range as 0 .. n - 1");
        return false;
    }
    const auto items = v->items;  // keeps the list alive while the body runs
    for (const Value& item : *items)
        if (!run(item)) return false;
    return true;
}

std::optional<Value> Lowering::index(const Expr& e, ExprGraph* field) {
    const auto a = evaluate(e.args()[0], field);
    const auto i = evaluate(e.args()[1], field);
    if (!a || !i) return std::nullopt;
    if (a->type != Value::Type::List && a->type != Value::Type::Vector &&
        a->type != Value::Type::String) {
        error(e.loc, "cannot index " + typeName(a->type),
              "only lists, vectors and strings have elements");
        return std::nullopt;
    }
    if (i->type != Value::Type::Number) {
        error(e.args()[1].start, "an index must be a number, got " + typeName(i->type));
        return std::nullopt;
    }
    const size_t size = a->type == Value::Type::List     ? a->list().size()
                        : a->type == Value::Type::Vector ? 3
                                                         : a->string().size();
    const double k = i->number;
    if (k != std::floor(k) || k < 0 || k >= static_cast<double>(size)) {
        error(e.args()[1].start,
              "index " + formatNumber(k) + " is out of range for " + typeName(a->type) + " of " +
                  std::to_string(size) + " element" + (size == 1 ? "" : "s"),
              "indices are whole numbers from 0 to len - 1");
        return std::nullopt;
    }
    const size_t at = static_cast<size_t>(k);
    if (a->type == Value::Type::List) return a->list()[at];
    if (a->type == Value::Type::Vector) return Value::ofNumber(a->vector[static_cast<int>(at)]);
    return Value::ofString(a->string().substr(at, 1));
}

std::optional<Value> Lowering::member(const Expr& e, ExprGraph* field) {
    const auto a = evaluate(e.args()[0], field);
    if (!a) return std::nullopt;
    const std::string& name = e.name();
    const int axis = name == "x" ? 0 : name == "y" ? 1 : name == "z" ? 2 : -1;
    if (axis < 0) {
        error(e.loc, "unknown component '." + name + "'",
              "a vector's components are .x, .y and .z");
        return std::nullopt;
    }
    if (a->type != Value::Type::Vector) {
        error(e.loc, "'." + name + "' needs a vector, got " + typeName(a->type));
        return std::nullopt;
    }
    return Value::ofNumber(a->vector[axis]);
}

std::optional<Value> Lowering::builtinValue(const Expr& e, const std::vector<Value>& args,
                                            bool& handled) {
    static const struct {
        const char* name;
        int arity;
    } kBuiltins[] = {{"len", 1}, {"dot", 2}, {"cross", 2},  {"length", 1}, {"normalize", 1},
                     {"deg", 1}, {"rad", 1}, {"random", 2}, {"str", -1}};
    const std::string& name = e.name();
    int arity = -2;
    for (const auto& b : kBuiltins)
        if (name == b.name) arity = b.arity;
    handled = arity != -2;
    if (!handled) return std::nullopt;
    if (arity >= 0 && static_cast<int>(args.size()) != arity) {
        error(e.loc, "'" + name + "' takes " + std::to_string(arity) + " argument" +
                         (arity == 1 ? "" : "s") + ", got " + std::to_string(args.size()));
        return std::nullopt;
    }
    const auto expect = [&](size_t i, Value::Type t) { return expectArgument(e, args, i, t); };
    using T = Value::Type;
    if (name == "len") {
        const Value& a = args[0];
        if (a.type == T::List) return Value::ofNumber(static_cast<double>(a.list().size()));
        if (a.type == T::String) return Value::ofNumber(static_cast<double>(a.string().size()));
        if (a.type == T::Vector) return Value::ofNumber(3);
        error(e.args()[0].start,
              "'len' expects a list, a string or a vector, got " + typeName(a.type));
        return std::nullopt;
    }
    if (name == "dot" || name == "cross") {
        if (!expect(0, T::Vector) || !expect(1, T::Vector)) return std::nullopt;
        if (name == "dot")
            return finite(Value::ofNumber(glm::dot(args[0].vector, args[1].vector)), e.loc, "dot");
        return finite(Value::ofVector(glm::cross(args[0].vector, args[1].vector)), e.loc, "cross");
    }
    if (name == "length") {
        if (!expect(0, T::Vector)) return std::nullopt;
        return finite(Value::ofNumber(glm::length(args[0].vector)), e.loc, "length");
    }
    if (name == "normalize") {
        if (!expect(0, T::Vector)) return std::nullopt;
        const Vec3& v = args[0].vector;
        if (v == Vec3(0.0) || !std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
            error(e.args()[0].start,
                  "cannot normalize " + formatVector(v) + ": it has no direction");
            return std::nullopt;
        }
        return Value::ofVector(normalizeSafe(v));
    }
    if (name == "deg" || name == "rad") {
        if (!expect(0, T::Number)) return std::nullopt;
        return Value::ofNumber(name == "deg" ? args[0].number * (180.0 / M_PI)
                                             : args[0].number * (M_PI / 180.0));
    }
    if (name == "random") return randomValue(e, args);
    return joinedString(e, args);
}

bool Lowering::expectArgument(const Expr& e, const std::vector<Value>& args, size_t i,
                              Value::Type t) {
    if (args[i].type == t) return true;
    error(e.args()[i].start,
          "'" + e.name() + "' expects " + typeName(t) + ", got " + typeName(args[i].type));
    return false;
}

std::optional<Value> Lowering::randomValue(const Expr& e, const std::vector<Value>& args) {
    // Integer hashing only, no library distribution: the same stream on every machine.
    for (size_t i = 0; i < 2; ++i) {
        if (!expectArgument(e, args, i, Value::Type::Number)) return std::nullopt;
        const double v = args[i].number;
        if (v != std::floor(v) || std::fabs(v) > 9007199254740992.0) {
            error(e.args()[i].start, std::string("random's ") + (i == 0 ? "seed" : "index") +
                                         " must be a whole number of at most 2^53, got " +
                                         formatNumber(v));
            return std::nullopt;
        }
    }
    const uint64_t seed = static_cast<uint64_t>(static_cast<int64_t>(args[0].number));
    const uint64_t i = static_cast<uint64_t>(static_cast<int64_t>(args[1].number));
    const uint64_t h = mix64(mix64(seed) ^ i);
    return Value::ofNumber(static_cast<double>(h >> 11) * 0x1.0p-53);  // 53 bits in [0, 1)
}

std::optional<Value> Lowering::joinedString(const Expr& e, const std::vector<Value>& args) {
    using T = Value::Type;
    // str(a, b, …): the values written out and joined, for messages.
    std::string out;
    for (const Value& a : args) out += a.type == T::String ? a.string() : show(a);
    if (static_cast<int64_t>(out.size()) > kMaxStringLength) {
        error(e.loc, "string longer than " + std::to_string(kMaxStringLength) + " bytes");
        return std::nullopt;
    }
    return Value::ofString(std::move(out));
}

namespace {

/// The shortest text that reads back as the same double (whole numbers below 2^53 as
/// integers), so echo shows exactly what a value is: 0.1 * 3 prints 0.30000000000000004.
std::string exactNumber(double v) {
    char buf[32];
    if (v == std::floor(v) && std::fabs(v) < 9007199254740992.0) {
        std::snprintf(buf, sizeof buf, "%.0f", v == 0 ? 0.0 : v);  // no "-0"
        return buf;
    }
    for (int precision = 1; precision <= 17; ++precision) {
        std::snprintf(buf, sizeof buf, "%.*g", precision, v);
        if (std::strtod(buf, nullptr) == v) break;
    }
    return buf;
}

}  // namespace

std::string Lowering::show(const Value& v) const {
    switch (v.type) {
        case Value::Type::Number: return exactNumber(v.number);
        case Value::Type::Vector:
            return "<" + exactNumber(v.vector.x) + ", " + exactNumber(v.vector.y) + ", " +
                   exactNumber(v.vector.z) + ">";
        case Value::Type::Bool: return v.truth() ? "true" : "false";
        case Value::Type::String: return "\"" + v.string() + "\"";
        case Value::Type::Field: return "<function of x, y, z>";
        case Value::Type::Solid:
            return v.solid && v.solid != emptySolid()
                       ? std::string("<") + nodeKindName(v.solid->kind()) + ">"
                       : "<empty solid>";
        case Value::Type::List: {
            std::string out = "[";
            for (size_t i = 0; i < v.list().size(); ++i) {
                if (i) out += ", ";
                if (out.size() > 1000) return out + "…]";
                out += show(v.list()[i]);
            }
            return out + "]";
        }
    }
    return "?";
}

}  // namespace kerf
