// Lowering, part 7: statements that run rather than define. `for` and `if` at the top level
// (their bodies are statements, run in order, with block-local lets) and inside Boolean
// bodies (their bodies are solids), `assert` and `echo`.
#include "lang/lower.h"

#include "csg/tree/solids.h"

namespace kerf {

const NodePtr& emptySolid() {
    static const NodePtr marker = makeSphere(Vec3(0.0), 1.0);  // only its address is used
    return marker;
}

void Lowering::runBlock(const std::vector<Statement>& body, Scene& scene) {
    const size_t mark = mLocals.size();
    for (const Statement& s : body) {
        switch (s.kind) {
            case Statement::Kind::Let:
            case Statement::Kind::SolidDef: {
                // Block-local: visible to the statements after it. A failed one ends the block
                // (its uses would only report it again as undefined).
                const auto v = s.kind == Statement::Kind::Let ? evaluate(*s.expr, nullptr)
                                                              : [&]() -> std::optional<Value> {
                    NodePtr node = lowerSolid(*s.solid);
                    return node ? std::optional<Value>(Value::ofSolid(node)) : std::nullopt;
                }();
                if (!v) {
                    mLocals.resize(mark);
                    return;
                }
                pushLocal(s.name, *v);
                break;
            }
            case Statement::Kind::Object:
                if (NodePtr node = lowerSolid(*s.solid))
                    addObject(node, scene, s.name != "no_shadow");
                break;
            case Statement::Kind::Light:
                if (auto light = lowerLight(s)) scene.lights.push_back(*light);
                break;
            case Statement::Kind::Section: lowerSection(s, scene); break;
            case Statement::Kind::For: runFor(s, scene); break;
            case Statement::Kind::If: runIf(s, scene); break;
            case Statement::Kind::Assert: runAssert(s); break;
            case Statement::Kind::Echo: runEcho(s); break;
            default:
                error(s.loc,
                      "this statement is allowed only at the top level, not inside for or if",
                      "inside a block write let, solid, object, light, section, for, if, assert or "
                      "echo");
                break;
        }
    }
    mLocals.resize(mark);
}

void Lowering::runFor(const Statement& s, Scene& scene) {
    iterate(*s.expr, s.name, s.nameLoc, [&]() {
        const int errors = mSink.errorCount();
        runBlock(s.block->body, scene);
        return mSink.errorCount() == errors;  // one failing iteration is reported, not all
    });
}

void Lowering::runIf(const Statement& s, Scene& scene) {
    const auto c = evaluate(*s.expr, nullptr);
    if (!c) return;
    if (c->type != Value::Type::Bool) {
        error(s.expr->start, "the condition of 'if' must be a boolean, got " + typeName(c->type),
              "compare it, as in n > 0");
        return;
    }
    if (c->truth())
        runBlock(s.block->body, scene);
    else
        runBlock(s.block->elseBody, scene);
}

void Lowering::runAssert(const Statement& s) {
    const auto c = evaluate(*s.expr, nullptr);
    if (!c) return;
    if (c->type != Value::Type::Bool) {
        error(s.expr->start, "assert expects a boolean, got " + typeName(c->type));
        return;
    }
    if (c->truth()) return;
    std::string message = "assertion failed";
    if (!s.properties.empty()) {
        const auto m = evaluate(*s.properties[0].expr, nullptr);
        if (!m) return;
        message += ": " + (m->type == Value::Type::String ? m->string() : show(*m));
    }
    error(s.loc, message);
}

void Lowering::runEcho(const Statement& s) {
    std::string line;
    for (size_t i = 0; i < s.properties.size(); ++i) {
        const auto v = evaluate(*s.properties[i].expr, nullptr);
        if (!v) return;
        if (i) line += ", ";
        line += v->type == Value::Type::String ? v->string() : show(*v);
    }
    mSink.report(Diagnostic{mSink.locate(s.loc), Severity::Echo, std::move(line), {}, {}});
}

bool Lowering::expandChildren(const ArenaList<Solid>& children, std::vector<NodePtr>& out) {
    bool ok = true;
    for (const Solid& c : children) {
        if (c.kind == Solid::Kind::For) {
            const Property& head = c.properties[0];
            ok = iterate(*head.expr, head.name, head.loc,
                         [&]() { return expandChildren(c.children, out); }) &&
                 ok;
        } else if (c.kind == Solid::Kind::If) {
            const auto v = evaluate(*c.properties[0].expr, nullptr);
            if (!v) {
                ok = false;
                continue;
            }
            if (v->type != Value::Type::Bool) {
                error(c.properties[0].expr->start,
                      "the condition of 'if' must be a boolean, got " + typeName(v->type),
                      "compare it, as in n > 0");
                ok = false;
                continue;
            }
            const bool hasElse =
                !c.children.empty() && c.children[c.children.size() - 1].kind == Solid::Kind::Else;
            const size_t thenCount = c.children.size() - (hasElse ? 1 : 0);
            if (v->truth())
                ok = expandChildren(
                         ArenaList<Solid>(c.children.begin(), static_cast<uint32_t>(thenCount)),
                         out) &&
                     ok;
            else if (hasElse)
                ok = expandChildren(c.children[thenCount].children, out) && ok;
        } else {
            NodePtr node = lowerSolid(c);
            ok = ok && node;
            if (node) out.push_back(std::move(node));
        }
        if (!ok) return false;
    }
    return ok;
}

}  // namespace kerf
