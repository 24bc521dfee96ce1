// Lowering, part 2: expressions. Outside implicit functions they fold to numbers and vectors
// at compile time; inside `implicit { f … }` (field != null) x, y, z are free and the result
// is a node of an ExprGraph, with constant subexpressions still folded.
#include "lang/lower.h"

#include "csg/tape/noise.h"
#include "lang/diagnostic_hints.h"
#include "lang/names.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <unordered_map>

namespace kerf {

namespace {

struct Function {
    const char* name;
    int arity;
    Op op;  // for the functions that map to one graph operation
};

const std::array<Function, 20> kFunctions = {{
    {"sin", 1, Op::Sin},     {"cos", 1, Op::Cos},     {"tan", 1, Op::Tan},
    {"asin", 1, Op::Asin},   {"acos", 1, Op::Acos},   {"atan", 1, Op::Atan},
    {"sqrt", 1, Op::Sqrt},   {"abs", 1, Op::Abs},     {"exp", 1, Op::Exp},
    {"log", 1, Op::Log},     {"floor", 1, Op::Floor}, {"ceil", 1, Op::Ceil},
    {"atan2", 2, Op::Atan2}, {"pow", 2, Op::Pow},     {"min", 2, Op::Min},
    {"max", 2, Op::Max},     {"clamp", 3, Op::Min},   {"mix", 3, Op::Add},
    {"noise", 3, Op::Noise}, {"pi", 0, Op::Const},  // pi is not callable
}};

/// The built-in functions of values (lower_values.cpp's builtinValue), not of x, y, z.
const char* const kValueBuiltins[] = {"len", "dot", "cross",  "length", "normalize",
                                      "deg", "rad", "random", "str"};

/// The math functions by name (their index in kFunctions), and the value built-ins as -1.
/// One hash instead of a string compare per built-in: calls are the inner loop of models.
const std::unordered_map<std::string, int>& builtinIndex() {
    static const std::unordered_map<std::string, int> kIndex = [] {
        std::unordered_map<std::string, int> index;
        for (size_t i = 0; i < kFunctions.size(); ++i)
            if (kFunctions[i].arity > 0) index.emplace(kFunctions[i].name, static_cast<int>(i));
        for (const char* b : kValueBuiltins) index.emplace(b, -1);
        return index;
    }();
    return kIndex;
}

double applyConstant(Op op, double a, double b) {
    switch (op) {
        case Op::Neg: return -a;
        case Op::Sin: return std::sin(a);
        case Op::Cos: return std::cos(a);
        case Op::Tan: return std::tan(a);
        case Op::Asin: return std::asin(a);
        case Op::Acos: return std::acos(a);
        case Op::Atan: return std::atan(a);
        case Op::Sqrt: return std::sqrt(a);
        case Op::Abs: return std::fabs(a);
        case Op::Exp: return std::exp(a);
        case Op::Log: return std::log(a);
        case Op::Floor: return std::floor(a);
        case Op::Ceil: return std::ceil(a);
        case Op::Add: return a + b;
        case Op::Sub: return a - b;
        case Op::Mul: return a * b;
        case Op::Div: return a / b;
        case Op::Pow: return std::pow(a, b);
        case Op::Atan2: return std::atan2(a, b);
        case Op::Min: return std::min(a, b);
        case Op::Max: return std::max(a, b);
        default: return a;
    }
}

Op operatorOp(char op) {
    switch (op) {
        case '+': return Op::Add;
        case '-': return Op::Sub;
        case '*': return Op::Mul;
        case '/': return Op::Div;
        default: return Op::Pow;
    }
}

/// The graph node of a number or field operand.
ExprId asField(const Value& v, ExprGraph& graph) {
    return v.type == Value::Type::Field ? v.field : graph.constant(v.number);
}

/// a^b in the graph: an integer constant exponent becomes PowInt (exact for negative bases).
ExprId powerField(ExprGraph& graph, const Value& a, const Value& b) {
    const ExprId base = asField(a, graph);
    if (b.type == Value::Type::Number && b.number == std::floor(b.number) &&
        std::fabs(b.number) <= 64) {
        const int n = static_cast<int>(b.number);
        if (n == 0) return graph.constant(1.0);
        if (n == 1) return base;
        if (n > 0) return graph.powInt(base, n);
        return graph.binary(Op::Div, graph.constant(1.0), graph.powInt(base, -n));
    }
    return graph.binary(Op::Pow, base, asField(b, graph));
}

}  // namespace

bool isBuiltinFunction(const std::string& name) {
    for (const Function& f : kFunctions)
        if (f.arity > 0 && name == f.name) return true;
    for (const char* b :
         {"len", "dot", "cross", "length", "normalize", "deg", "rad", "random", "str"})
        if (name == b) return true;
    return false;
}

std::optional<Value> Lowering::finite(Value v, SourcePos at, const std::string& what) {
    return finiteLazy(std::move(v), at, [&] { return what; });
}

bool Lowering::isFinite(const Value& v) {
    return v.type == Value::Type::Number ? std::isfinite(v.number)
           : v.type == Value::Type::Vector
               ? std::isfinite(v.vector.x) && std::isfinite(v.vector.y) && std::isfinite(v.vector.z)
               : true;
}

std::optional<Value> Lowering::evaluate(const Expr& e, ExprGraph* field) {
    if (!enter(e.loc)) return std::nullopt;
    struct Leave {
        int& depth;
        ~Leave() { --depth; }
    } leave{mDepth};

    switch (e.kind) {
        case Expr::Kind::Number:
            return finiteLazy(Value::ofNumber(e.number), e.loc, [&] {
                return mSink.textAt(e.loc, e.count) + " is too large for a double";
            });
        case Expr::Kind::Name: return evaluateName(e, field);
        case Expr::Kind::Call: return evaluateCall(e, field);
        case Expr::Kind::Vector: {
            Vec3 v{0.0};
            bool ok = true;
            for (int i = 0; i < 3; ++i) {
                const auto c = evaluate(e.args()[i], field);
                if (!c) {
                    ok = false;
                } else if (c->type != Value::Type::Number) {
                    error(e.args()[i].start,
                          "a vector component must be a number, got " + typeName(c->type));
                    ok = false;
                } else {
                    v[i] = c->number;
                }
            }
            if (!ok) return std::nullopt;
            return Value::ofVector(v);
        }
        case Expr::Kind::Negate: {
            const auto a = evaluate(e.args()[0], field);
            if (!a) return std::nullopt;
            if (a->type == Value::Type::Number) return Value::ofNumber(-a->number);
            if (a->type == Value::Type::Vector) return Value::ofVector(-a->vector);
            if (a->type == Value::Type::Field)
                return Value::ofField(field->unary(Op::Neg, a->field));
            error(e.loc, "cannot negate " + typeName(a->type));
            return std::nullopt;
        }
        case Expr::Kind::Binary: {
            if (e.op == '&' || e.op == '|') return logic(e, field);
            const auto a = evaluate(e.args()[0], field);
            const auto b = evaluate(e.args()[1], field);
            if (!a || !b) return std::nullopt;
            if (std::strchr("<>lgen", e.op)) return compare(e.op, *a, *b, e.loc);
            return arithmetic(e.op, *a, *b, e.loc, field);
        }
        default: return evaluateValue(e, field);
    }
    return std::nullopt;
}

std::optional<Value> Lowering::arithmetic(char op, const Value& a, const Value& b, SourcePos at,
                                          ExprGraph* field) {
    using T = Value::Type;
    const auto mistyped = [&]() -> std::optional<Value> {
        std::string hint;
        if (a.type == T::Vector && b.type == T::Vector && (op == '*' || op == '/'))
            hint = "vectors multiply only by numbers";
        error(at,
              "cannot apply '" + std::string(1, op) + "' to " + typeName(a.type) + " and " +
                  typeName(b.type),
              hint);
        return std::nullopt;
    };
    if (op == '+' && a.type == b.type && (a.type == T::String || a.type == T::List))
        return concatenate(a, b, at);
    const auto plain = [](T t) { return t == T::Number || t == T::Vector || t == T::Field; };
    if (!plain(a.type) || !plain(b.type)) return mistyped();
    if (op ==
        '%') {  // floored: the result has the sign of b, so i % 2 is 0 or 1 for every integer i
        if (a.type != T::Number || b.type != T::Number) return mistyped();
        if (b.number == 0) {
            error(at, "remainder of a division by 0: " + formatNumber(a.number) + " % 0");
            return std::nullopt;
        }
        const double r = a.number - b.number * std::floor(a.number / b.number);
        return finiteLazy(Value::ofNumber(r), at,
                          [&] { return formatNumber(a.number) + " % " + formatNumber(b.number); });
    }
    if (a.type == T::Number && b.type == T::Number) {
        const double r = applyConstant(operatorOp(op), a.number, b.number);
        return finiteLazy(Value::ofNumber(r), at, [&] {
            return formatNumber(a.number) + " " + op + " " + formatNumber(b.number) + " = " +
                   formatNumber(r);
        });
    }
    if (a.type == T::Field || b.type == T::Field) {
        if (a.type == T::Vector || b.type == T::Vector) return mistyped();
        if (op == '^') return Value::ofField(powerField(*field, a, b));
        return Value::ofField(
            field->binary(operatorOp(op), asField(a, *field), asField(b, *field)));
    }
    Vec3 r;
    if (a.type == T::Vector && b.type == T::Vector && (op == '+' || op == '-'))
        r = op == '+' ? a.vector + b.vector : a.vector - b.vector;
    else if (a.type == T::Number && b.type == T::Vector && op == '*')
        r = a.number * b.vector;
    else if (a.type == T::Vector && b.type == T::Number && (op == '*' || op == '/'))
        r = op == '*' ? a.vector * b.number : a.vector / b.number;
    else
        return mistyped();
    return finiteLazy(Value::ofVector(r), at, [&] { return "the result is " + formatVector(r); });
}

std::optional<double> Lowering::numberValue(const Expr& e, const char* what) {
    const auto v = evaluate(e, nullptr);
    if (!v) return std::nullopt;
    if (v->type != Value::Type::Number) {
        error(e.start, std::string(what) + " must be a number, got " + typeName(v->type));
        return std::nullopt;
    }
    return v->number;
}

std::optional<Value> Lowering::evaluateName(const Expr& e, ExprGraph* field) {
    if (const Value* v = local(e.name())) return *v;
    if (field && (e.name() == "x" || e.name() == "y" || e.name() == "z"))
        return Value::ofField(e.name() == "x"   ? field->x()
                              : e.name() == "y" ? field->y()
                                                : field->z());
    if (e.name() == "pi") return Value::ofNumber(M_PI);
    if (mLets.count(e.name())) return letValue(e.name(), e.loc);
    if (mSolids.count(e.name())) {
        NodePtr node = solidByName(e.name(), e.loc);
        if (!node) return std::nullopt;
        return Value::ofSolid(node);
    }
    if (mFunctions.count(e.name())) {
        error(e.loc, "'" + e.name() + "' is a function, not a value",
              "call it: " + e.name() + "(…)");
        return std::nullopt;
    }
    if (mMaterials.count(e.name())) {
        error(e.loc, "'" + e.name() + "' is a material, not a number or vector");
        return std::nullopt;
    }
    // The sequence's frame and time come last: any name the model defines hides them.
    if (e.name() == "frame") return Value::ofNumber(double(mSequenceFrame.frame));
    if (e.name() == "time") return Value::ofNumber(mSequenceFrame.time);
    std::vector<std::string> candidates{"pi", "frame", "time"};
    for (const auto& [name, entry] : mLets) candidates.push_back(name);
    for (size_t i = mFrameBase; i < mLocals.size(); ++i) candidates.push_back(mLocals[i].first);
    std::string hint = didYouMean(e.name(), candidates);
    if (!field && (e.name() == "x" || e.name() == "y" || e.name() == "z"))
        hint = "x, y and z exist only inside the f of an implicit solid";
    error(e.loc, "undefined name '" + e.name() + "'", hint);
    return std::nullopt;
}

std::optional<Value> Lowering::letValue(const std::string& name, SourcePos use) {
    LetEntry& entry = mLets[name];
    switch (entry.state) {
        case State::Done: return entry.value;
        case State::Failed: return std::nullopt;
        case State::Busy: error(use, cycleMessage("let", mBusyLets, name)); return std::nullopt;
        case State::Pending: break;
    }
    if (entry.def->broken) {
        entry.state = State::Failed;
        return std::nullopt;
    }
    entry.state = State::Busy;
    mBusyLets.push_back(name);
    // A top-level let sees the top level only, wherever it is first used.
    const size_t frameBase = std::exchange(mFrameBase, mLocals.size());
    const auto v = evaluate(*entry.def->expr, nullptr);  // lets are constants, even inside f
    mFrameBase = frameBase;
    mBusyLets.pop_back();
    LetEntry& done = mLets[name];
    done.state = v ? State::Done : State::Failed;
    if (v) done.value = *v;
    return v;
}

std::optional<Value> Lowering::evaluateCall(const Expr& e, ExprGraph* field) {
    if (const auto user = mFunctions.find(e.name()); user != mFunctions.end())
        return callFunction(*user->second, e, field);
    for (const Expr& a : e.args()) {
        if (a.kind == Expr::Kind::NamedArg) {
            error(a.loc, "the built-in function '" + e.name() + "' takes no named arguments");
            return std::nullopt;
        }
    }
    const auto& index = builtinIndex();
    const auto builtin = index.find(e.name());
    if (builtin != index.end() && builtin->second < 0) return callValueBuiltin(e, field);
    if (builtin == index.end()) {
        reportUnknownFunction(e);
        return std::nullopt;
    }
    const Function& fn = kFunctions[builtin->second];
    if (static_cast<int>(e.args().size()) != fn.arity) {
        error(e.loc, "'" + e.name() + "' takes " + std::to_string(fn.arity) + " argument" +
                         (fn.arity == 1 ? "" : "s") + ", got " + std::to_string(e.args().size()));
        return std::nullopt;
    }
    std::vector<Value> args;
    bool ok = true;
    for (const Expr& a : e.args()) {
        const auto v = evaluate(a, field);
        if (v) args.push_back(*v);
        ok = ok && v.has_value();
    }
    if (!ok) return std::nullopt;
    return applyMathFunction(e, builtin->second, args, field);
}

std::optional<Value> Lowering::callValueBuiltin(const Expr& e, ExprGraph* field) {
    std::vector<Value> args;
    for (const Expr& a : e.args()) {
        auto v = evaluate(a, field);
        if (!v) return std::nullopt;
        if (v->type == Value::Type::Field) {
            error(a.start, "'" + e.name() + "' cannot take a function of x, y, z");
            return std::nullopt;
        }
        args.push_back(std::move(*v));
    }
    bool handled = false;
    return builtinValue(e, args, handled);
}

void Lowering::reportUnknownFunction(const Expr& e) {
    std::vector<std::string> names;
    for (const Function& f : kFunctions)
        if (f.arity > 0) names.emplace_back(f.name);
    for (const char* b : kValueBuiltins) names.emplace_back(b);
    for (const auto& [name, def] : mFunctions) names.push_back(name);
    std::string hint = callSyntaxHint(e.name());  // OpenSCAD's cube([…]) and the like
    if (hint.empty()) hint = didYouMean(e.name(), names);
    error(e.loc, "unknown function '" + e.name() + "'",
          hint.empty() ? "the functions are " + joinNames(names) : hint);
}

std::optional<Value> Lowering::applyMathFunction(const Expr& e, int function,
                                                 const std::vector<Value>& args, ExprGraph* field) {
    const Function& fn = kFunctions[function];
    const std::string name = e.name();
    if (name == "mix") {  // a + (b - a)·t, which also mixes vectors
        const auto d = arithmetic('-', args[1], args[0], e.loc, field);
        const auto s = d ? arithmetic('*', *d, args[2], e.loc, field) : std::nullopt;
        return s ? arithmetic('+', args[0], *s, e.loc, field) : std::nullopt;
    }
    if (name == "pow") return arithmetic('^', args[0], args[1], e.loc, field);
    for (size_t i = 0; i < args.size(); ++i) {
        if (args[i].type != Value::Type::Number && args[i].type != Value::Type::Field) {
            error(e.args()[i].start,
                  "'" + name + "' expects a number, got " + typeName(args[i].type));
            return std::nullopt;
        }
    }
    const auto apply = [&](Op op, const Value& a, const Value& b) -> std::optional<Value> {
        if (a.type == Value::Type::Number && b.type == Value::Type::Number) {
            const double r = applyConstant(op, a.number, b.number);
            return finiteLazy(Value::ofNumber(r), e.loc, [&] {
                std::string call = name + "(" + formatNumber(a.number);
                if (fn.arity > 1) call += ", " + formatNumber(b.number);
                return call + ") = " + formatNumber(r);
            });
        }
        if (fn.arity == 1) return Value::ofField(field->unary(op, a.field));
        return Value::ofField(field->binary(op, asField(a, *field), asField(b, *field)));
    };
    if (name == "noise") {  // gradient noise at (a, b, c), seed 0 (csg/tape/noise.h)
        if (args[0].type == Value::Type::Number && args[1].type == Value::Type::Number &&
            args[2].type == Value::Type::Number)
            return Value::ofNumber(
                gradientNoise(Vec3(args[0].number, args[1].number, args[2].number), 0));
        return Value::ofField(field->noise(asField(args[0], *field), asField(args[1], *field),
                                           asField(args[2], *field), 0));
    }
    if (name == "clamp") {  // min(max(a, lo), hi)
        const auto lower = apply(Op::Max, args[0], args[1]);
        return lower ? apply(Op::Min, *lower, args[2]) : std::nullopt;
    }
    return apply(fn.op, args[0], fn.arity > 1 ? args[1] : Value::ofNumber(0.0));
}

}  // namespace kerf
