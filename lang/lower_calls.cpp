// Lowering, part 6: calls of user functions. Arguments bind to parameters by position, then
// by name, then from defaults; the body runs in a frame that sees its parameters and the top
// level only (lexical scope: functions are defined at the top level). A call with the same
// argument values as an earlier one returns the earlier result, so a solid made twice is one
// shared subtree. Errors inside a call carry the chain of calls as notes (Lowering::error).
#include "lang/lower.h"

#include "lang/names.h"

#include <cstring>

namespace kerf {

namespace {

/// Appends the exact bits of a value to a memo key (no rounding: 0.1 and 0.1000000000000001
/// are different arguments). False for values that cannot be keyed (functions of x, y, z).
bool appendKey(const Value& v, std::string& key) {
    const auto bits = [&](double d) {
        char raw[sizeof d];
        std::memcpy(raw, &d, sizeof d);
        key.append(raw, sizeof d);
    };
    key += static_cast<char>('0' + static_cast<int>(v.type));
    switch (v.type) {
        case Value::Type::Number:
        case Value::Type::Bool: bits(v.number); return true;
        case Value::Type::Vector:
            bits(v.vector.x);
            bits(v.vector.y);
            bits(v.vector.z);
            return true;
        case Value::Type::String:
            key += std::to_string(v.string().size()) + ':' + v.string();
            return true;
        case Value::Type::Solid: {
            const void* p = v.solid.get();
            key.append(reinterpret_cast<const char*>(&p), sizeof p);
            return true;
        }
        case Value::Type::List:
            key += std::to_string(v.list().size()) + '[';
            for (const Value& item : v.list())
                if (!appendKey(item, key)) return false;
            return true;
        case Value::Type::Field: return false;
    }
    return false;
}

}  // namespace

const Value* Lowering::local(const std::string& name) const {
    for (size_t i = mLocals.size(); i-- > mFrameBase;)
        if (mLocals[i].first == name) return &mLocals[i].second;
    return nullptr;
}

std::optional<Value> Lowering::callFunction(const Statement& fn, const Expr& call,
                                            ExprGraph* field) {
    if (fn.broken) return std::nullopt;  // its syntax error is reported
    const SourceLoc at = mSink.locate(call.loc);
    if (static_cast<int>(mCalls.size()) >= mLimits.callDepth) {
        if (!mLimitReported) {
            mLimitReported = true;
            error(call.loc,
                  "recursion deeper than " + std::to_string(mLimits.callDepth) + " in call to " +
                      fn.name + " at line " + std::to_string(at.line),
                  "a recursive function needs a case that stops, e.g. level == 0 ? … : …");
        }
        return std::nullopt;
    }
    std::vector<std::optional<Value>> bound(fn.properties.size());
    if (!bindArguments(fn, call, field, bound)) return std::nullopt;
    return runCall(fn, call, field, bound);
}

std::optional<size_t> Lowering::namedSlot(const Statement& fn, const Expr& a,
                                          const std::vector<std::optional<Value>>& bound) {
    const ArenaList<Property>& params = fn.properties;
    size_t slot = params.size();
    for (size_t i = 0; i < params.size(); ++i)
        if (params[i].name.str() == a.name().str()) slot = i;
    if (slot == params.size()) {
        std::vector<std::string> names;
        for (const Property& p : params) names.push_back(p.name);
        std::string hint = didYouMean(a.name(), names);
        error(a.loc, "'" + fn.name + "' has no parameter '" + a.name() + "'",
              hint.empty() ? (names.empty() ? "it takes no arguments"
                                            : "its parameters are " + joinNames(names))
                           : hint);
        return std::nullopt;
    }
    if (bound[slot]) {
        error(a.loc, "argument '" + a.name() + "' given twice in call to " + fn.name);
        return std::nullopt;
    }
    return slot;
}

bool Lowering::bindArguments(const Statement& fn, const Expr& call, ExprGraph* field,
                             std::vector<std::optional<Value>>& bound) {
    // Bind the arguments, evaluated in the caller's scope.
    const ArenaList<Property>& params = fn.properties;
    bool named = false;
    size_t position = 0;
    for (const Expr& a : call.args()) {
        size_t slot = 0;
        if (a.kind == Expr::Kind::NamedArg) {
            named = true;
            const std::optional<size_t> found = namedSlot(fn, a, bound);
            if (!found) return false;
            slot = *found;
        } else {
            if (named) {
                error(a.start, "a positional argument after a named one in call to " + fn.name);
                return false;
            }
            if (position >= params.size()) {
                error(a.start, "'" + fn.name + "' takes " + std::to_string(params.size()) +
                                   " argument" + (params.size() == 1 ? "" : "s") + ", got " +
                                   std::to_string(call.args().size()));
                return false;
            }
            slot = position++;
        }
        auto v = evaluate(a.kind == Expr::Kind::NamedArg ? a.args()[0] : a, field);
        if (!v) return false;
        bound[slot] = std::move(*v);
    }
    for (size_t i = 0; i < params.size(); ++i) {
        if (!bound[i] && !params[i].expr) {
            error(call.loc, "missing argument '" + params[i].name + "' in call to " + fn.name,
                  "pass it as " + params[i].name.str() + " = …, or give the parameter a default");
            return false;
        }
    }
    return true;
}

std::optional<Value> Lowering::runCall(const Statement& fn, const Expr& call, ExprGraph* field,
                                       std::vector<std::optional<Value>>& bound) {
    const ArenaList<Property>& params = fn.properties;
    // A frame that sees the parameters and the top level.
    const size_t mark = mLocals.size();
    const size_t frameBase = std::exchange(mFrameBase, mark);
    mCalls.push_back({&fn.name, call.loc});
    const auto leave = [&]() {
        mCalls.pop_back();
        mLocals.resize(mark);
        mFrameBase = frameBase;
    };
    for (size_t i = 0; i < params.size(); ++i) {
        if (!bound[i]) {  // a default sees the parameters before it
            bound[i] = evaluate(*params[i].expr, field);
            if (!bound[i]) {
                leave();
                return std::nullopt;
            }
        }
        pushLocal(params[i].name, *bound[i]);
    }
    std::string key;
    // Only calls that make solids are memoised (their sharing is the point); a function seen
    // to return anything else is not looked up again. x, y, z belong to one implicit's graph.
    bool memo = field == nullptr && !mReturnsOther.count(&fn);
    if (memo) {
        const Statement* id = &fn;
        key.append(reinterpret_cast<const char*>(&id), sizeof id);
        for (const auto& v : bound) memo = memo && appendKey(*v, key);
    }
    if (memo) {
        if (const auto hit = mCallMemo.find(key); hit != mCallMemo.end()) {
            leave();
            return hit->second;
        }
    }
    if (!countIteration(call.loc)) {  // calls share the loops' budget: no runaway recursion
        leave();
        return std::nullopt;
    }
    auto result = evaluate(*fn.expr, field);
    leave();
    if (result && result->type != Value::Type::Solid)
        mReturnsOther.insert(&fn);
    else if (result && memo)
        mCallMemo.emplace(std::move(key), *result);
    return result;
}

bool Lowering::solidOf(const Value& v, SourcePos at, NodePtr& out, bool& empty) {
    if (v.type != Value::Type::Solid) {
        error(at, "expected a solid, got " + typeName(v.type));
        return false;
    }
    empty = v.solid == emptySolid();
    out = v.solid;
    return true;
}

}  // namespace kerf
