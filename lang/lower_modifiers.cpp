// Lowering, part 3b: the modifiers after a solid. Consecutive transforms are folded into one
// Affine, checked after each; a material or a motion (move, spin) wraps what came before it.
#include "lang/lower.h"

#include "csg/affine_check.h"
#include "csg/tree/solids.h"
#include "lang/names.h"

#include <cmath>

namespace kerf {

namespace {

const char* modifierWord(const Modifier& m) {
    switch (m.kind) {
        case Modifier::Kind::Translate: return "translate";
        case Modifier::Kind::Rotate: return "rotate";
        case Modifier::Kind::Scale: return "scale";
        case Modifier::Kind::Matrix: return "matrix";
        case Modifier::Kind::Move: return "move";
        case Modifier::Kind::Spin: return "spin";
        case Modifier::Kind::Displace: return "displace";
        default: return "modifier";
    }
}

}  // namespace

NodePtr Lowering::applyModifiers(NodePtr node, const Solid& s) {
    bool ok = node != nullptr;
    Affine pending;
    const Modifier* hasPending = nullptr;  // the last transform modifier folded into pending
    for (const Modifier& m : s.modifiers) {
        const bool motion = m.kind == Modifier::Kind::Move || m.kind == Modifier::Kind::Spin;
        if (m.kind == Modifier::Kind::Displace) {
            // Like a material or a motion, it takes what came before it.
            if (!ok) continue;
            if (hasPending) node = transformed(node, pending, *hasPending);
            pending = Affine{};
            hasPending = nullptr;
            node = node && checkSolidOperands({node}, "displaced", m.loc) ? displaced(node, m)
                                                                          : nullptr;
            ok = node != nullptr;
        } else if (m.kind == Modifier::Kind::Interior) {  // as a material (lower_surfaces.cpp)
            const std::optional<int> index = materialIndex(m.material, m.materialLoc);
            if (!index || !ok) {
                ok = false;
                continue;
            }
            if (hasPending)
                node = countNode(m.loc) ? transformed(node, pending, *hasPending) : nullptr;
            if (!node) return nullptr;
            pending = Affine{};
            hasPending = nullptr;
            node = limitDepth(interiorOf(node, *index), m.loc);
            ok = node != nullptr;
        } else if (motion || m.kind == Modifier::Kind::Material) {
            // A material or a motion wraps what came before it: pending transforms first.
            std::optional<Vec3> v;
            std::optional<int> index;
            if (motion)
                v = motionVector(m);
            else
                index = materialIndex(m.material, m.materialLoc);
            if (!(motion ? v.has_value() : index.has_value()) || !ok) {
                ok = false;
                continue;
            }
            if (hasPending) node = transformed(node, pending, *hasPending);
            if (!node) return nullptr;
            pending = Affine{};
            hasPending = nullptr;
            NodePtr wrapped = !motion                          ? makeMaterial(node, *index)
                              : m.kind == Modifier::Kind::Move ? makeMotion(node, *v, Vec3(0.0))
                                                               : makeMotion(node, Vec3(0.0), *v);
            node = limitDepth(std::move(wrapped), m.loc);
            ok = node != nullptr;
        } else if (const auto t = modifierTransform(m)) {
            pending = t->after(pending);  // later modifiers apply after earlier ones
            hasPending = &m;
            if (ok && !checkFolded(pending, m)) ok = false;
        } else {
            ok = false;
        }
    }
    if (!ok) return nullptr;
    if (!hasPending) return node;
    NodePtr out = transformed(node, pending, *hasPending);
    return out ? limitDepth(out, s.loc) : nullptr;
}

NodePtr Lowering::transformed(const NodePtr& node, const Affine& map, const Modifier& last) {
    // A solid of finite extent moved or scaled past the double range would have hit points
    // that overflow (a radius 1e300 scaled by 1e10); nested transforms can do this even when
    // each fold is finite.
    NodePtr out = makeTransform(node, map);
    if (node->bounds().finite() && !out->bounds().finite()) {
        error(last.loc,
              std::string("the solid's extent is not finite after this ") + modifierWord(last) +
                  ": it reaches past ±1.8e308",
              "coordinates must stay within the double range");
        return nullptr;
    }
    return out;
}

bool Lowering::checkFolded(const Affine& folded, const Modifier& m) {
    const std::string word = modifierWord(m);
    switch (checkAffine(folded)) {
        case AffineStatus::Ok: return true;
        case AffineStatus::NotFinite:
            error(m.loc,
                  "transform is not finite after this " + word +
                      ": the solid's transforms together overflow",
                  "coordinates and scales must stay within about ±1.8e308");
            break;
        case AffineStatus::Singular:
            error(m.loc, "transform is singular after this " + word + ": it flattens the solid",
                  "the transforms together scale some direction to 0");
            break;
        case AffineStatus::InverseNotFinite:
            error(m.loc,
                  "transform is singular after this " + word +
                      ": it shrinks the solid by more than doubles can undo (its inverse is not "
                      "finite)",
                  "scales together must stay above about 1e-308");
            break;
    }
    return false;
}

std::optional<Affine> Lowering::modifierTransform(const Modifier& m) {
    if (m.kind == Modifier::Kind::Matrix) {
        if (m.args.size() != 12) {
            error(m.loc, "matrix needs 12 numbers (3 rows of 4, row-major), got " +
                             std::to_string(m.args.size()));
            return std::nullopt;
        }
        double entries[12];
        bool ok = true;
        for (int i = 0; i < 12; ++i) {
            const auto v = evaluate(m.args[i], nullptr);
            if (v && v->type != Value::Type::Number)
                error(m.args[i].start, "a matrix entry must be a number, got " + typeName(v->type));
            ok = ok && v && v->type == Value::Type::Number;
            if (ok) entries[i] = v->number;
        }
        if (!ok) return std::nullopt;
        const Affine a = Affine::fromRowMajor(entries);
        // Judged relative to the matrix's own scale and without overflow (csg/affine_check.h),
        // so a matrix scaled by 1e300 or 1e-300 is not singular; the fold checks the rest.
        const double rel = relativeDeterminant(a.linear);
        if (std::isnan(rel)) {
            error(m.loc, "matrix is not finite: it has an entry that is inf or NaN");
            return std::nullopt;
        }
        if (!(rel > kSingularRelativeDeterminant)) {
            error(m.loc,
                  "matrix is singular (relative determinant " + formatNumber(rel) +
                      "): it flattens the solid",
                  "its rows (or columns) are nearly linearly dependent");
            return std::nullopt;
        }
        return a;
    }
    const char* word = m.kind == Modifier::Kind::Translate ? "translate"
                       : m.kind == Modifier::Kind::Rotate  ? "rotate"
                                                           : "scale";
    const auto v = evaluate(m.args[0], nullptr);
    if (!v) return std::nullopt;
    if (m.kind == Modifier::Kind::Scale) {
        const Vec3 s = v->type == Value::Type::Number ? Vec3(v->number) : v->vector;
        if (s.x == 0 || s.y == 0 || s.z == 0) {
            error(m.args[0].start, "scale by zero flattens the solid",
                  "scale factors must not be 0");
            return std::nullopt;
        }
        return Affine::scale(s);
    }
    if (v->type != Value::Type::Vector) {
        error(m.args[0].start, std::string(word) + " expects a vector, got " + typeName(v->type),
              std::string("write ") + word + " <x, y, z>");
        return std::nullopt;
    }
    return m.kind == Modifier::Kind::Translate ? Affine::translate(v->vector)
                                               : Affine::rotateDegrees(v->vector);
}

std::optional<int> Lowering::materialIndex(const std::string& name, SourcePos use) {
    const auto it = mMaterials.find(name);
    if (it != mMaterials.end()) return it->second.index;
    if (name == "default") return 0;
    std::vector<std::string> candidates{"default"};
    for (const auto& [n, entry] : mMaterials) candidates.push_back(n);
    error(use, "undefined material '" + name + "'", didYouMean(name, candidates));
    return std::nullopt;
}

std::optional<Vec3> Lowering::motionVector(const Modifier& m) {
    const char* word = m.kind == Modifier::Kind::Move ? "move" : "spin";
    const auto v = evaluate(m.args[0], nullptr);
    if (!v) return std::nullopt;
    if (v->type != Value::Type::Vector) {
        error(m.args[0].start, std::string(word) + " expects a vector, got " + typeName(v->type),
              m.kind == Modifier::Kind::Move
                  ? "move <x, y, z>: how far the solid goes over the scene time 0 to 1"
                  : "spin <x, y, z>: the degrees it turns over the scene time 0 to 1");
        return std::nullopt;
    }
    if (!(std::isfinite(v->vector.x) && std::isfinite(v->vector.y) && std::isfinite(v->vector.z))) {
        error(m.args[0].start,
              std::string(word) + " is not finite, got " + formatVector(v->vector));
        return std::nullopt;
    }
    return v->vector;
}

}  // namespace kerf
