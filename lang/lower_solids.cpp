// Lowering, part 3: solids. Primitives are validated and built with the csg factories,
// Booleans combine their children, names resolve to one shared tree per `solid`, and
// modifiers wrap the result (consecutive transforms folded into one Affine).
#include "lang/lower.h"

#include "csg/solids.h"
#include "csg/tape.h"
#include "lang/names.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace kerf {

namespace {

const std::vector<std::string> kPrimitiveKinds = {"sphere", "box", "cylinder", "cone", "torus", "halfspace",
                                                  "implicit"};
const std::vector<std::string> kBooleanKinds = {"union", "intersection", "difference", "xor"};

/// True when |b − a| is zero or below what doubles can resolve at this distance from the origin.
bool degenerateSegment(const Vec3& a, const Vec3& b) {
    const double length = glm::length(b - a);
    return length == 0.0 || length <= 1e-12 * std::max(glm::length(a), glm::length(b));
}

}  // namespace

NodePtr Lowering::lowerSolid(const Solid& s) {
    if (!enter(s.loc)) return nullptr;
    NodePtr node;
    switch (s.kind) {
        case Solid::Kind::Reference: node = lowerReference(s); break;
        case Solid::Kind::Boolean: node = lowerBoolean(s); break;
        case Solid::Kind::Primitive: node = lowerPrimitive(s); break;
    }
    node = applyModifiers(node, s);
    --mDepth;
    return node;
}

NodePtr Lowering::lowerReference(const Solid& s) {
    const bool isKind = std::find(kPrimitiveKinds.begin(), kPrimitiveKinds.end(), s.name) != kPrimitiveKinds.end() ||
                        std::find(kBooleanKinds.begin(), kBooleanKinds.end(), s.name) != kBooleanKinds.end();
    if (isKind && !mSolids.count(s.name)) {
        error(s.loc, "'" + s.name + "' needs a block", "write '" + s.name + " { … }'");
        return nullptr;
    }
    return solidByName(s.name, s.loc);
}

NodePtr Lowering::solidByName(const std::string& name, const SourceLoc& use) {
    const auto it = mSolids.find(name);
    if (it == mSolids.end()) {
        if (mLets.count(name)) {
            error(use, "'" + name + "' is a let (a number or vector), not a solid");
            return nullptr;
        }
        std::vector<std::string> candidates;
        for (const auto& [n, entry] : mSolids) candidates.push_back(n);
        std::string hint = didYouMean(name, candidates);
        if (hint.empty()) hint = didYouMean(name, kPrimitiveKinds);
        if (hint.empty()) hint = didYouMean(name, kBooleanKinds);
        error(use, "undefined solid '" + name + "'", hint);
        return nullptr;
    }
    SolidEntry& entry = it->second;
    switch (entry.state) {
        case State::Done: return entry.node;
        case State::Failed: return nullptr;
        case State::Busy:
            error(use, cycleMessage("solid", mBusySolids, name));
            return nullptr;
        case State::Pending: break;
    }
    if (entry.def->broken) {
        entry.state = State::Failed;
        return nullptr;
    }
    entry.state = State::Busy;
    mBusySolids.push_back(name);
    NodePtr node = lowerSolid(*entry.def->solid);
    mBusySolids.pop_back();
    entry.state = node ? State::Done : State::Failed;
    entry.node = node;
    return node;
}

NodePtr Lowering::lowerBoolean(const Solid& s) {
    if (s.children.empty()) {
        error(s.loc, "'" + s.name + "' needs at least one solid");
        return nullptr;
    }
    std::vector<NodePtr> children;
    bool ok = true;
    for (const SolidPtr& c : s.children) {
        NodePtr child = lowerSolid(*c);
        ok = ok && child;
        children.push_back(child);
    }
    if (!ok) return nullptr;
    if (children.size() == 1) return children[0];
    const BoolOp op = s.name == "union"          ? BoolOp::Union
                      : s.name == "intersection" ? BoolOp::Intersection
                      : s.name == "difference"   ? BoolOp::Difference
                                                 : BoolOp::Xor;
    return limitDepth(makeBoolean(op, std::move(children)), s.loc);
}

int Lowering::heightOf(const NodePtr& node) {
    const auto it = mHeights.find(node.get());
    if (it != mHeights.end()) return it->second.second;
    // Only nodes made since the last call are not memoised yet: a few levels at most.
    int height = 1;
    for (const NodePtr& child : node->children()) height = std::max(height, heightOf(child) + 1);
    mHeights.emplace(node.get(), std::make_pair(node, height));
    return height;
}

NodePtr Lowering::limitDepth(NodePtr node, const SourceLoc& at) {
    if (heightOf(node) <= kMaxCsgDepth) return node;
    error(at, "solid nested too deeply: its tree would be more than " + std::to_string(kMaxCsgDepth) +
                  " levels deep, counting named solids as written out",
          "each Boolean, transform or material over a solid is one level; a wide union { … } of many "
          "solids is one level");
    return nullptr;
}

NodePtr Lowering::lowerPrimitive(const Solid& s) {
    if (s.name == "sphere") return lowerSphere(s);
    if (s.name == "box") {
        const auto b = boxBounds(s, "box");
        return b ? makeBox(b->lo, b->hi) : nullptr;
    }
    if (s.name == "cylinder") return lowerCylinder(s);
    if (s.name == "cone") return lowerCone(s);
    if (s.name == "torus") return lowerTorus(s);
    if (s.name == "halfspace") return lowerHalfSpace(s);
    if (s.name == "implicit") return lowerImplicit(s);
    std::string hint = didYouMean(s.name, kPrimitiveKinds);
    if (hint.empty()) hint = didYouMean(s.name, kBooleanKinds);
    if (hint.empty()) hint = "the solids are " + joinNames(kPrimitiveKinds) + ", " + joinNames(kBooleanKinds);
    error(s.loc, "unknown solid '" + s.name + "'", hint);
    return nullptr;
}

NodePtr Lowering::lowerSphere(const Solid& s) {
    const PropertyBlock b(s.properties, {{"center", PropertyType::Vector}, {"radius", PropertyType::Number}},
                          "sphere", s.loc, mSink);
    Vec3 center{0.0};
    double radius = 1.0;
    bool ok = b.ok();
    ok &= readVector(b, "center", center);
    ok &= readNumber(b, "radius", radius);
    if (ok && !(radius > 0)) {
        error(b.find("radius")->valueLoc(), "sphere radius must be positive, got " + formatNumber(radius));
        ok = false;
    }
    return ok ? makeSphere(center, radius) : nullptr;
}

std::optional<Bounds3> Lowering::boxBounds(const Solid& s, const char* what) {
    const PropertyBlock b(s.properties,
                          {{"min", PropertyType::Vector, true}, {"max", PropertyType::Vector, true}}, "box",
                          s.loc, mSink);
    Bounds3 box{Vec3(0.0), Vec3(0.0)};
    bool ok = b.ok();
    ok &= readVector(b, "min", box.lo);
    ok &= readVector(b, "max", box.hi);
    if (!ok) return std::nullopt;
    if (!(box.lo.x < box.hi.x && box.lo.y < box.hi.y && box.lo.z < box.hi.z)) {
        error(s.loc, std::string("empty ") + what + ": min " + formatVector(box.lo) + " must be less than max " +
                         formatVector(box.hi) + " on every axis");
        return std::nullopt;
    }
    return box;
}

NodePtr Lowering::lowerCylinder(const Solid& s) {
    const PropertyBlock b(s.properties,
                          {{"from", PropertyType::Vector, true},
                           {"to", PropertyType::Vector, true},
                           {"radius", PropertyType::Number}},
                          "cylinder", s.loc, mSink);
    Vec3 from{0.0}, to{0.0};
    double radius = 1.0;
    bool ok = b.ok();
    ok &= readVector(b, "from", from);
    ok &= readVector(b, "to", to);
    ok &= readNumber(b, "radius", radius);
    if (!ok) return nullptr;
    if (!(radius > 0)) {
        error(b.find("radius")->valueLoc(), "cylinder radius must be positive, got " + formatNumber(radius));
        return nullptr;
    }
    if (degenerateSegment(from, to)) {
        error(s.loc, "cylinder has zero length: from and to are the same point " + formatVector(from));
        return nullptr;
    }
    return makeCylinder(from, to, radius);
}

NodePtr Lowering::lowerCone(const Solid& s) {
    const PropertyBlock b(s.properties,
                          {{"from", PropertyType::Vector, true},
                           {"to", PropertyType::Vector, true},
                           {"radius1", PropertyType::Number},
                           {"radius2", PropertyType::Number}},
                          "cone", s.loc, mSink);
    Vec3 from{0.0}, to{0.0};
    double r1 = 1.0, r2 = 0.0;
    bool ok = b.ok();
    ok &= readVector(b, "from", from);
    ok &= readVector(b, "to", to);
    ok &= readNumber(b, "radius1", r1);
    ok &= readNumber(b, "radius2", r2);
    if (!ok) return nullptr;
    for (const auto& [name, r] : {std::pair<const char*, double>{"radius1", r1}, {"radius2", r2}}) {
        if (r < 0) {
            error(b.find(name)->valueLoc(), std::string("cone ") + name + " must not be negative, got " +
                                                formatNumber(r));
            ok = false;
        }
    }
    if (!ok) return nullptr;
    if (r1 == 0 && r2 == 0) {
        error(s.loc, "cone with both radii 0 has no volume");
        return nullptr;
    }
    if (degenerateSegment(from, to)) {
        error(s.loc, "cone has zero length: from and to are the same point " + formatVector(from));
        return nullptr;
    }
    return makeCone(from, to, r1, r2);
}

NodePtr Lowering::lowerTorus(const Solid& s) {
    const PropertyBlock b(s.properties,
                          {{"major", PropertyType::Number, true}, {"minor", PropertyType::Number, true}}, "torus",
                          s.loc, mSink);
    double major = 1.0, minor = 0.25;
    bool ok = b.ok();
    ok &= readNumber(b, "major", major);
    ok &= readNumber(b, "minor", minor);
    if (!ok) return nullptr;
    for (const auto& [name, r] : {std::pair<const char*, double>{"major", major}, {"minor", minor}}) {
        if (!(r > 0)) {
            error(b.find(name)->valueLoc(), std::string("torus ") + name + " radius must be positive, got " +
                                                formatNumber(r));
            ok = false;
        }
    }
    return ok ? makeTorus(major, minor) : nullptr;
}

NodePtr Lowering::lowerHalfSpace(const Solid& s) {
    const PropertyBlock b(s.properties,
                          {{"normal", PropertyType::Vector, true}, {"offset", PropertyType::Number}}, "halfspace",
                          s.loc, mSink);
    Vec3 normal{0.0};
    double offset = 0.0;
    bool ok = b.ok();
    ok &= readVector(b, "normal", normal);
    ok &= readNumber(b, "offset", offset);
    if (!ok) return nullptr;
    if (normal == Vec3(0.0)) {
        error(b.find("normal")->valueLoc(), "halfspace normal must not be zero");
        return nullptr;
    }
    return makeHalfSpace(normal, offset);
}

NodePtr Lowering::lowerImplicit(const Solid& s) {
    const PropertyBlock b(s.properties,
                          {{"f", PropertyType::Function, true}, {"bound", PropertyType::Solid, true}}, "implicit",
                          s.loc, mSink);
    bool ok = b.ok();
    ExprGraph graph;
    ExprId root = -1;
    if (const Property* f = b.find("f")) {
        if (f->solid) {
            error(f->solid->loc, "property 'f' of implicit expects a function of x, y, z, got a solid");
            ok = false;
        } else if (const auto v = evaluate(*f->expr, &graph)) {
            if (v->type == Value::Type::Vector) {
                error(f->expr->start, "property 'f' of implicit expects a function of x, y, z, got a vector");
                ok = false;
            } else {
                root = v->type == Value::Type::Field ? v->field : graph.constant(v->number);
            }
        } else {
            ok = false;
        }
    }
    std::optional<Bounds3> bound;
    if (const Property* p = b.find("bound")) {
        if (p->expr) {
            error(p->expr->start, "property 'bound' of implicit expects box { min … max … }");
        } else if (p->solid->kind != Solid::Kind::Primitive || p->solid->name != "box") {
            error(p->solid->loc, "property 'bound' of implicit expects box { min … max … }, got '" +
                                     p->solid->name + "'");
        } else {
            bound = boxBounds(*p->solid, "bound");
        }
    }
    if (!ok || !bound) return nullptr;
    return makeImplicit(Tape::compile(graph, root), *bound);
}

NodePtr Lowering::applyModifiers(NodePtr node, const Solid& s) {
    bool ok = node != nullptr;
    Affine pending;
    bool hasPending = false;
    for (const Modifier& m : s.modifiers) {
        if (m.kind == Modifier::Kind::Material) {
            const auto index = materialIndex(m.material, m.materialLoc);
            if (!index || !ok) {
                ok = false;
                continue;
            }
            if (hasPending) node = makeTransform(node, pending);
            pending = Affine{};
            hasPending = false;
            node = limitDepth(makeMaterial(node, *index), m.loc);
            ok = node != nullptr;
        } else if (const auto t = modifierTransform(m)) {
            pending = t->after(pending);  // later modifiers apply after earlier ones
            hasPending = true;
        } else {
            ok = false;
        }
    }
    if (!ok) return nullptr;
    return hasPending ? limitDepth(makeTransform(node, pending), s.loc) : node;
}

std::optional<Affine> Lowering::modifierTransform(const Modifier& m) {
    if (m.kind == Modifier::Kind::Matrix) {
        if (m.args.size() != 12) {
            error(m.loc, "matrix needs 12 numbers (3 rows of 4, row-major), got " + std::to_string(m.args.size()));
            return std::nullopt;
        }
        double entries[12];
        bool ok = true;
        for (int i = 0; i < 12; ++i) {
            const auto v = evaluate(*m.args[i], nullptr);
            if (v && v->type != Value::Type::Number)
                error(m.args[i]->start, "a matrix entry must be a number, got " + typeName(v->type));
            ok = ok && v && v->type == Value::Type::Number;
            if (ok) entries[i] = v->number;
        }
        if (!ok) return std::nullopt;
        const Affine a = Affine::fromRowMajor(entries);
        // Singular relative to the rows' lengths (Hadamard's bound), so scale does not matter.
        const Vec3 r0(entries[0], entries[1], entries[2]), r1(entries[4], entries[5], entries[6]),
            r2(entries[8], entries[9], entries[10]);
        const double det = glm::dot(r0, glm::cross(r1, r2));
        if (!(std::fabs(det) > 1e-12 * glm::length(r0) * glm::length(r1) * glm::length(r2))) {
            error(m.loc, "matrix is singular (determinant " + formatNumber(det) + "): it flattens the solid");
            return std::nullopt;
        }
        return a;
    }
    const char* word = m.kind == Modifier::Kind::Translate ? "translate"
                       : m.kind == Modifier::Kind::Rotate  ? "rotate"
                                                           : "scale";
    const auto v = evaluate(*m.args[0], nullptr);
    if (!v) return std::nullopt;
    if (m.kind == Modifier::Kind::Scale) {
        const Vec3 s = v->type == Value::Type::Number ? Vec3(v->number) : v->vector;
        if (s.x == 0 || s.y == 0 || s.z == 0) {
            error(m.args[0]->start, "scale by zero flattens the solid", "scale factors must not be 0");
            return std::nullopt;
        }
        return Affine::scale(s);
    }
    if (v->type != Value::Type::Vector) {
        error(m.args[0]->start, std::string(word) + " expects a vector, got " + typeName(v->type),
              std::string("write ") + word + " <x, y, z>");
        return std::nullopt;
    }
    return m.kind == Modifier::Kind::Translate ? Affine::translate(v->vector) : Affine::rotateDegrees(v->vector);
}

std::optional<int> Lowering::materialIndex(const std::string& name, const SourceLoc& use) {
    const auto it = mMaterials.find(name);
    if (it != mMaterials.end()) return it->second.index;
    if (name == "default") return 0;
    std::vector<std::string> candidates{"default"};
    for (const auto& [n, entry] : mMaterials) candidates.push_back(n);
    error(use, "undefined material '" + name + "'", didYouMean(name, candidates));
    return std::nullopt;
}

}  // namespace kerf
