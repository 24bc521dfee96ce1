// Lowering, part 1: the definitions (lets, solids, materials) and the statement loop.
#include "lang/lower.h"

#include "csg/format.h"
#include "csg/tree/solids.h"
#include "lang/definition_order.h"

#include <algorithm>
#include <cstdio>

namespace kerf {

std::string formatNumber(double v) { return formatDouble("%g", v); }

std::string formatVector(const Vec3& v) {
    return "<" + formatNumber(v.x) + ", " + formatNumber(v.y) + ", " + formatNumber(v.z) + ">";
}

/// Counts one level of lowering recursion (the caller leaves with --mDepth); too deep is an error.
bool Lowering::enter(SourcePos at) {
    if (++mDepth <= kMaxLoweringDepth) return true;
    --mDepth;
    if (mTooDeepReported) return false;  // one report; the rest of the chain fails quietly
    mTooDeepReported = true;
    error(at, "nested too deeply through named solids, lets or function calls (more than " +
                  std::to_string(kMaxLoweringDepth) + " levels)");
    return false;
}

void Lowering::error(SourcePos loc, std::string message, std::string hint) {
    Diagnostic d{mSink.locate(loc), Severity::Error, std::move(message), std::move(hint), {}};
    // Innermost first; a deep recursion shows its two ends, not a hundred equal lines.
    constexpr size_t kInner = 5, kOuter = 3;
    for (size_t i = mCalls.size(); i-- > 0;) {
        const size_t fromInside = mCalls.size() - 1 - i;
        if (mCalls.size() > kInner + kOuter + 1 && fromInside >= kInner && i >= kOuter) {
            if (fromInside == kInner)
                d.notes.push_back("… " + std::to_string(mCalls.size() - kInner - kOuter) +
                                  " more calls …");
            continue;
        }
        const SourceLoc at = mSink.locate(mCalls[i].at);
        d.notes.push_back("in call to " + *mCalls[i].name + " at " +
                          (at.file ? *at.file : std::string("<input>")) + ":" +
                          std::to_string(at.line) + ":" + std::to_string(at.col));
    }
    mSink.report(std::move(d));
}

namespace {

std::string where(const SourceLoc& loc) {
    return (loc.file ? *loc.file : std::string("<input>")) + ":" + std::to_string(loc.line) + ":" +
           std::to_string(loc.col);
}

}  // namespace

std::optional<Scene> Lowering::lower(Program& program) {
    const int errorsBefore = mSink.errorCount();
    Scene scene;
    collectDefinitions(program, scene);
    lowerDefinitions();
    for (Statement& s : program.statements) lowerStatement(s, scene);
    checkSectionedSurfaces(scene);
    if (mDefaultMaterial) {
        // Materials nest innermost-first, so parts that name their own keep it.
        for (NodePtr& object : scene.objects)
            if (object->kind() != NodeKind::Material)
                object = makeMaterial(object, *mDefaultMaterial);
    }
    if (mSink.errorCount() > errorsBefore) return std::nullopt;
    return scene;
}

NodePtr Lowering::solidNamed(const std::string& name) const {
    const auto it = mSolids.find(name);
    return it == mSolids.end() ? nullptr : it->second.node;
}

void Lowering::collectDefinitions(Program& program, Scene& scene) {
    const auto define = [&](auto& table, Statement& s, const char* what) {
        auto [it, inserted] = table.try_emplace(s.name);
        if (!inserted) {
            error(s.nameLoc, std::string(what) + " '" + s.name + "' is already defined",
                  "first defined at " + where(mSink.locate(it->second.def->nameLoc)));
            return false;
        }
        it->second.def = &s;
        return true;
    };
    for (Statement& s : program.statements) {
        switch (s.kind) {
            case Statement::Kind::Let: define(mLets, s, "let"); break;
            case Statement::Kind::SolidDef: define(mSolids, s, "solid"); break;
            case Statement::Kind::Function: {
                if (isBuiltinFunction(s.name)) {
                    error(s.nameLoc,
                          "'" + s.name + "' is a built-in function and cannot be redefined");
                    break;
                }
                auto [it, inserted] = mFunctions.try_emplace(s.name, &s);
                if (!inserted)
                    error(s.nameLoc, "function '" + s.name + "' is already defined",
                          "first defined at " + where(mSink.locate(it->second->nameLoc)));
                break;
            }
            case Statement::Kind::DefaultMaterial:
                if (mDefaultMaterialDef) {
                    error(s.loc, "default material given twice",
                          "first given at " + where(mSink.locate(mDefaultMaterialDef->loc)));
                    break;
                }
                mDefaultMaterialDef = &s;
                break;
            case Statement::Kind::Material:
                if (define(mMaterials, s, "material")) {
                    mMaterials[s.name].index = static_cast<int>(scene.materials.size());
                    Material m;
                    m.name = s.name;
                    scene.materials.push_back(m);
                }
                break;
            default: break;
        }
    }
}

void Lowering::addObject(NodePtr node, Scene& scene, bool castsShadow) {
    if (node == emptySolid()) return;  // an empty object adds nothing
    scene.objects.push_back(std::move(node));
    if (!castsShadow || !scene.objectFlags.empty()) {
        scene.objectFlags.resize(scene.objects.size());
        scene.objectFlags.back().castsShadow = castsShadow;
    }
}

void Lowering::lowerDefinitions() {
    std::map<std::string, const Statement*> lets, solids;
    for (const auto& [name, entry] : mLets) lets[name] = entry.def;
    for (const auto& [name, entry] : mSolids) solids[name] = entry.def;
    const auto state = [&](const Statement* def) {
        return def->kind == Statement::Kind::Let ? mLets[def->name].state
                                                 : mSolids[def->name].state;
    };
    for (const OrderedDefinition& d : definitionOrder(lets, solids, mSink)) {
        const bool isLet = d.def->kind == Statement::Kind::Let;
        if (d.level <= kMaxNameDepth) {
            if (isLet)
                letValue(d.def->name, d.def->nameLoc);
            else
                solidByName(d.def->name, d.def->nameLoc);
            continue;
        }
        (isLet ? mLets[d.def->name].state : mSolids[d.def->name].state) = State::Failed;
        // One report, at the first definition too deep, unless what it uses failed already.
        const bool usesOk = std::all_of(d.uses.begin(), d.uses.end(), [&](const Statement* u) {
            return state(u) == State::Done;
        });
        if (d.firstTooDeep && usesOk)
            error(d.tooDeepAt,
                  std::string(isLet ? "let '" : "solid '") + d.def->name +
                      "' is nested too deeply through named solids or lets (more than " +
                      std::to_string(kMaxNameDepth) + " levels)",
                  "a definition may build on others at most " + std::to_string(kMaxNameDepth) +
                      " levels deep");
    }
}

bool Lowering::onlyOnce(const Statement& s, const Statement*& first, const char* what) {
    if (first) {
        error(s.loc, std::string(what) + " given twice",
              "first given at " + where(mSink.locate(first->loc)));
        return false;
    }
    first = &s;
    return true;
}

void Lowering::lowerStatement(Statement& s, Scene& scene) {
    switch (s.kind) {
        case Statement::Kind::Let:
            if (s.broken) break;
            if (mLets[s.name].def == &s) letValue(s.name, s.nameLoc);
            break;
        case Statement::Kind::SolidDef:
            if (s.broken) break;
            if (mSolids[s.name].def == &s) solidByName(s.name, s.nameLoc);
            break;
        case Statement::Kind::Object:
            if (NodePtr node = lowerSolid(*s.solid)) addObject(node, scene, s.name != "no_shadow");
            s.releaseTree();
            break;
        case Statement::Kind::For:
            runFor(s, scene);
            s.releaseTree();
            break;
        case Statement::Kind::If:
            runIf(s, scene);
            s.releaseTree();
            break;
        case Statement::Kind::Assert: runAssert(s); break;
        case Statement::Kind::Echo: runEcho(s); break;
        case Statement::Kind::Function: break;  // called where used
        case Statement::Kind::DefaultMaterial:
            if (&s == mDefaultMaterialDef) mDefaultMaterial = materialIndex(s.name, s.nameLoc);
            break;
        case Statement::Kind::Material: {
            const MaterialEntry& m = mMaterials[s.name];
            if (m.def == &s && !s.broken) lowerMaterial(s, scene.materials[m.index]);
            break;
        }
        case Statement::Kind::Camera:
            if (onlyOnce(s, mCamera, "camera")) lowerCamera(s, scene.camera);
            break;
        case Statement::Kind::Light:
            if (auto light = lowerLight(s)) scene.lights.push_back(*light);
            break;
        case Statement::Kind::Mist:
            if (onlyOnce(s, mMist, "mist")) lowerMist(s, scene);
            break;
        case Statement::Kind::Background:
            if (onlyOnce(s, mBackground, "background")) lowerBackground(s, scene);
            break;
        case Statement::Kind::Render:
            if (onlyOnce(s, mRender, "render")) lowerRender(s, scene.settings);
            break;
        case Statement::Kind::Section: lowerSection(s, scene); break;
        case Statement::Kind::Include: break;  // resolved by compile.cpp before lowering
    }
}

std::string Lowering::cycleMessage(const char* what, const std::vector<std::string>& busy,
                                   const std::string& name) const {
    size_t i = 0;
    while (i < busy.size() && busy[i] != name) ++i;
    std::string path;
    for (size_t k = i + 1; k < busy.size(); ++k) path += "'" + busy[k] + "' → ";
    std::string message = std::string(what) + " '" + name + "' refers to itself";
    if (!path.empty()) message += " through " + path + "'" + name + "'";
    return message;
}

}  // namespace kerf
