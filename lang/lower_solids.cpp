// Lowering, part 3: solids. Primitives are validated and built with the csg factories,
// Booleans combine their children, and names resolve to one shared tree per `solid`
// (modifiers: lower_modifiers.cpp).
#include "lang/lower.h"

#include "csg/primitives/surfaces.h"
#include "csg/tape/tape.h"
#include "csg/tree/solids.h"
#include "lang/diagnostic_hints.h"
#include "lang/names.h"
#include "lang/solid_kinds.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace kerf {

namespace {

double maxAbs(const Vec3& v) { return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}); }

/// True when |b − a| is zero or below what doubles can resolve at this distance from the
/// origin. All three are scaled by one power of two first (exact), so the lengths neither
/// overflow (|a| ~ 1e308) nor underflow; b − a itself must be finite.
bool degenerateSegment(const Vec3& a, const Vec3& b) {
    const double big = std::max(maxAbs(a), maxAbs(b));
    if (big == 0.0) return true;
    const int e = std::ilogb(big);
    const auto scaled = [e](const Vec3& v) {
        return Vec3(std::ldexp(v.x, -e), std::ldexp(v.y, -e), std::ldexp(v.z, -e));
    };
    const double length = glm::length(scaled(b - a));
    return length == 0.0 ||
           length <= 1e-12 * std::max(glm::length(scaled(a)), glm::length(scaled(b)));
}

}  // namespace

std::string axisProblem(const char* what, const Vec3& from, const Vec3& to) {
    for (const auto& [name, v] : {std::pair<const char*, Vec3>{"from", from}, {"to", to}})
        if (!allFinite(v))
            return std::string(what) + " " + name + " is not finite, got " + formatVector(v);
    if (!allFinite(to - from))
        return std::string(what) + " axis to - from is not finite: from " + formatVector(from) +
               " and to " + formatVector(to) + " are more than about 1.8e308 apart";
    if (degenerateSegment(from, to))
        return std::string(what) + " has zero length: from and to are the same point " +
               formatVector(from);
    return "";
}

NodePtr Lowering::lowerSolid(const Solid& s) {
    if (!enter(s.loc)) return nullptr;
    NodePtr node;
    switch (s.kind) {
        case Solid::Kind::Reference: node = lowerReference(s); break;
        case Solid::Kind::Boolean: node = lowerBoolean(s); break;
        case Solid::Kind::Primitive: node = lowerPrimitive(s); break;
        case Solid::Kind::Call: {
            const auto v = evaluate(*s.properties[0].expr, nullptr);
            bool empty = false;
            if (v && !solidOf(*v, s.loc, node, empty)) node = nullptr;
            break;
        }
        case Solid::Kind::For:
        case Solid::Kind::If:
        case Solid::Kind::Else: {  // written where one solid goes (not in a Boolean body)
            std::vector<NodePtr> children;
            const ArenaList<Solid> one(&s, 1);
            if (expandChildren(s.kind == Solid::Kind::Else ? s.children : one, children) &&
                (children.size() < 2 ||
                 checkSolidOperands(children, "an operand of a union", s.loc))) {
                node = children.empty() ? emptySolid()
                       : children.size() == 1
                           ? children[0]
                           : limitDepth(makeBoolean(BoolOp::Union, std::move(children)), s.loc);
            }
            break;
        }
    }
    if (node != emptySolid()) node = applyModifiers(node, s);
    --mDepth;
    return node;
}

NodePtr Lowering::lowerReference(const Solid& s) {
    const SolidKind* row = findSolidKind(s.name);
    const bool isKind = row && row->has(kNeedsBlock);
    if (const Value* v = local(s.name)) {
        NodePtr node;
        bool empty = false;
        if (!solidOf(*v, s.loc, node, empty)) return nullptr;
        return node;
    }
    if (!mSolids.count(s.name) && mLets.count(s.name)) {
        const auto v = letValue(s.name, s.loc);
        NodePtr node;
        bool empty = false;
        if (!v || !solidOf(*v, s.loc, node, empty)) return nullptr;
        return node;
    }
    if (isKind && !mSolids.count(s.name)) {
        error(s.loc, "'" + s.name + "' needs a block", "write '" + s.name + " { … }'");
        return nullptr;
    }
    return solidByName(s.name, s.loc);
}

NodePtr Lowering::solidByName(const std::string& name, SourcePos use) {
    const auto it = mSolids.find(name);
    if (it == mSolids.end()) {
        if (mLets.count(name)) {
            error(use, "'" + name + "' is a let (a number or vector), not a solid");
            return nullptr;
        }
        std::vector<std::string> candidates;
        for (const auto& [n, entry] : mSolids) candidates.push_back(n);
        std::string hint = didYouMean(name, candidates);
        if (hint.empty()) hint = didYouMean(name, solidKeywords(kNeedsBlock));
        if (hint.empty()) hint = didYouMean(name, solidKeywords(kBoolean, true));
        if (hint.empty()) hint = foreignSolidHint(name);  // `object cube;`
        error(use, "undefined solid '" + name + "'", hint);
        return nullptr;
    }
    SolidEntry& entry = it->second;
    switch (entry.state) {
        case State::Done: return entry.node;
        case State::Failed: return nullptr;
        case State::Busy: error(use, cycleMessage("solid", mBusySolids, name)); return nullptr;
        case State::Pending: break;
    }
    if (entry.def->broken) {
        entry.state = State::Failed;
        return nullptr;
    }
    entry.state = State::Busy;
    mBusySolids.push_back(name);
    const size_t frameBase = std::exchange(mFrameBase, mLocals.size());  // the top level's scope
    NodePtr node = lowerSolid(*entry.def->solid);
    mFrameBase = frameBase;
    mBusySolids.pop_back();
    entry.state = node ? State::Done : State::Failed;
    entry.node = node;
    entry.def->releaseTree();  // never read again: the state answers every later use
    return node;
}

NodePtr Lowering::lowerBoolean(const Solid& s) {
    if (s.children.empty()) {
        error(s.loc, "'" + s.name + "' needs at least one solid");
        return nullptr;
    }
    std::vector<NodePtr> written;
    if (!expandChildren(s.children, written)) return nullptr;
    const SolidKind* row = findSolidKind(s.name);
    const BoolOp op = booleanOp(row ? row->node : NodeKind::Union);
    // Empty solids: an intersection with one is empty, a difference whose body is empty is
    // empty, elsewhere they are dropped; nothing left is the empty solid.
    std::vector<NodePtr> children;
    for (size_t i = 0; i < written.size(); ++i) {
        if (written[i] != emptySolid()) {
            children.push_back(written[i]);
        } else if (op == BoolOp::Intersection || (op == BoolOp::Difference && i == 0)) {
            return emptySolid();
        }
    }
    if (children.empty()) return emptySolid();
    if (children.size() == 1) return children[0];
    if (!checkSolidOperands(children, "an operand of " + s.name, s.loc)) return nullptr;
    return limitDepth(makeBoolean(op, std::move(children)), s.loc);
}

int Lowering::heightOf(const NodePtr& node) {
    // Leaves are not memoised: their height is known, and a memo entry (about 56 bytes) would
    // cost more than the primitive itself.
    if (node->children().size() == 0) return 1;
    const auto it = mHeights.find(node.get());
    if (it != mHeights.end()) return it->second.second;
    // Only nodes made since the last call are not memoised yet: a few levels at most.
    int height = 1;
    for (const NodePtr& child : node->children()) height = std::max(height, heightOf(child) + 1);
    mHeights.emplace(node.get(), std::make_pair(node, height));
    return height;
}

NodePtr Lowering::limitDepth(NodePtr node, SourcePos at) {
    if (!countNode(at)) return nullptr;  // every node lowering makes passes here
    if (heightOf(node) <= kMaxCsgDepth) return node;
    error(
        at,
        "solid nested too deeply: its tree would be more than " + std::to_string(kMaxCsgDepth) +
            " levels deep, counting named solids as written out",
        "each Boolean, transform or material over a solid is one level; a wide union { … } of many "
        "solids is one level");
    return nullptr;
}

bool Lowering::countPrimitive(SourcePos at) {
    if (++mPrimitives <= mLimits.primitives) return true;
    if (!mLimitReported) {
        mLimitReported = true;
        error(at,
              "this model makes more than " + std::to_string(mLimits.primitives) + " primitives",
              "the limit stops a model before it runs out of memory; see docs/language.md, Limits");
    }
    return false;
}

bool Lowering::countNode(SourcePos at) {
    if (++mNodes <= mLimits.nodes) return true;
    if (!mLimitReported) {
        mLimitReported = true;
        error(at, "this model makes more than " + std::to_string(mLimits.nodes) + " nodes",
              "each primitive, Boolean, transform and material made counts, every placement of a "
              "shared solid too; the limit stops a model before it runs out of memory (see "
              "docs/language.md, Limits)");
    }
    return false;
}

NodePtr Lowering::lowerPrimitive(const Solid& s) {
    if (!countPrimitive(s.loc) || !countNode(s.loc)) return nullptr;
    if (const SolidKind* row = findSolidKind(s.name); row && !row->has(kBoolean))
        return row->lower ? (this->*row->lower)(s) : lowerTabled(s, *row);
    if (isProfileKind(s.name)) {
        error(s.loc, "'" + s.name + "' is a 2-D profile, not a solid",
              "make a solid of it: extrude { profile " + s.name +
                  " { … } height 1 } or revolve { profile " + s.name + " { … } }");
        return nullptr;
    }
    error(s.loc, "unknown solid '" + s.name + "'",
          unknownSolidHint(s.name));  // the parser reports most
    return nullptr;
}

NodePtr Lowering::lowerTabled(const Solid& s, const SolidKind& kind) {
    std::vector<PropertySpec> specs;
    for (const SolidProperty& p : kind.properties) specs.push_back({p.name, p.type, p.required});
    const PropertyBlock b(s.properties, std::move(specs), kind.keyword, s.loc, mSink);
    PropertyValues values(kind.properties.size());
    bool ok = b.ok();
    for (size_t i = 0; i < values.size(); ++i) {
        const SolidProperty& p = kind.properties[i];
        PropertyValue& v = values[i];
        v = {p.number, p.vector, p.number != 0.0};
        if (p.type == PropertyType::Number) ok &= readNumber(b, p.name, v.number);
        if (p.type == PropertyType::Vector) ok &= readVector(b, p.name, v.vector);
        if (p.type == PropertyType::Bool) ok &= readBool(b, p.name, v.flag);
    }
    if (!ok) return nullptr;
    for (size_t i = 0; i < values.size(); ++i) {
        const SolidProperty& p = kind.properties[i];
        if (p.check == PropertyCheck::Positive && !(values[i].number > 0)) {
            error(b.find(p.name)->valueLoc(), std::string(kind.keyword) + " " + p.name +
                                                  " must be positive, got " +
                                                  formatNumber(values[i].number));
            ok = false;
        }
    }
    if (!ok) return nullptr;
    if (kind.problem) {
        if (const std::string problem = kind.problem(values); !problem.empty()) {
            error(s.loc, problem);
            return nullptr;
        }
    }
    return kind.make(values);
}

NodePtr Lowering::lowerBox(const Solid& s) {
    const auto b = boxBounds(s, "box");
    return b ? makeBox(b->lo, b->hi) : nullptr;
}

std::optional<Bounds3> Lowering::boxBounds(const Solid& s, const char* what) {
    const PropertyBlock b(
        s.properties, {{"min", PropertyType::Vector, true}, {"max", PropertyType::Vector, true}},
        "box", s.loc, mSink);
    Bounds3 box{Vec3(0.0), Vec3(0.0)};
    bool ok = b.ok();
    ok &= readVector(b, "min", box.lo);
    ok &= readVector(b, "max", box.hi);
    if (!ok) return std::nullopt;
    if (!(box.lo.x < box.hi.x && box.lo.y < box.hi.y && box.lo.z < box.hi.z)) {
        error(s.loc, std::string("empty ") + what + ": min " + formatVector(box.lo) +
                         " must be less than max " + formatVector(box.hi) + " on every axis");
        return std::nullopt;
    }
    return box;
}

NodePtr Lowering::lowerCylinder(const Solid& s) {
    const PropertyBlock b(s.properties,
                          {{"from", PropertyType::Vector, true},
                           {"to", PropertyType::Vector, true},
                           {"radius", PropertyType::Number},
                           {"open", PropertyType::Bool}},
                          "cylinder", s.loc, mSink);
    Vec3 from{0.0}, to{0.0};
    double radius = 1.0;
    bool open = false;  // the side alone, a surface (csg/primitives/surfaces.h)
    bool ok = b.ok();
    ok &= readBool(b, "open", open);
    ok &= readVector(b, "from", from);
    ok &= readVector(b, "to", to);
    ok &= readNumber(b, "radius", radius);
    if (!ok) return nullptr;
    if (!(radius > 0)) {
        error(b.find("radius")->valueLoc(),
              "cylinder radius must be positive, got " + formatNumber(radius));
        return nullptr;
    }
    if (const std::string problem = axisProblem("cylinder", from, to); !problem.empty()) {
        error(s.loc, problem);
        return nullptr;
    }
    return open ? noteSurface(makeOpenCone(from, to, radius, radius), s.loc)
                : makeCylinder(from, to, radius);
}

NodePtr Lowering::lowerCone(const Solid& s) {
    const PropertyBlock b(s.properties,
                          {{"from", PropertyType::Vector, true},
                           {"to", PropertyType::Vector, true},
                           {"radius1", PropertyType::Number},
                           {"radius2", PropertyType::Number},
                           {"open", PropertyType::Bool}},
                          "cone", s.loc, mSink);
    Vec3 from{0.0}, to{0.0};
    double r1 = 1.0, r2 = 0.0;
    bool open = false;  // the side alone, a surface (csg/primitives/surfaces.h)
    bool ok = b.ok();
    ok &= readBool(b, "open", open);
    ok &= readVector(b, "from", from);
    ok &= readVector(b, "to", to);
    ok &= readNumber(b, "radius1", r1);
    ok &= readNumber(b, "radius2", r2);
    if (!ok) return nullptr;
    for (const auto& [name, r] : {std::pair<const char*, double>{"radius1", r1}, {"radius2", r2}}) {
        if (r < 0) {
            error(b.find(name)->valueLoc(),
                  std::string("cone ") + name + " must not be negative, got " + formatNumber(r));
            ok = false;
        }
    }
    if (!ok) return nullptr;
    if (r1 == 0 && r2 == 0) {
        error(s.loc, "cone with both radii 0 has no volume");
        return nullptr;
    }
    if (const std::string problem = axisProblem("cone", from, to); !problem.empty()) {
        error(s.loc, problem);
        return nullptr;
    }
    return open ? noteSurface(makeOpenCone(from, to, r1, r2), s.loc) : makeCone(from, to, r1, r2);
}

NodePtr Lowering::lowerTorus(const Solid& s) {
    const PropertyBlock b(
        s.properties,
        {{"major", PropertyType::Number, true}, {"minor", PropertyType::Number, true}}, "torus",
        s.loc, mSink);
    double major = 1.0, minor = 0.25;
    bool ok = b.ok();
    ok &= readNumber(b, "major", major);
    ok &= readNumber(b, "minor", minor);
    if (!ok) return nullptr;
    for (const auto& [name, r] :
         {std::pair<const char*, double>{"major", major}, {"minor", minor}}) {
        if (!(r > 0)) {
            error(b.find(name)->valueLoc(), std::string("torus ") + name +
                                                " radius must be positive, got " + formatNumber(r));
            ok = false;
        }
    }
    return ok ? makeTorus(major, minor) : nullptr;
}

NodePtr Lowering::lowerHalfSpace(const Solid& s) {
    const PropertyBlock b(
        s.properties, {{"normal", PropertyType::Vector, true}, {"offset", PropertyType::Number}},
        "halfspace", s.loc, mSink);
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
    const PropertyBlock b(
        s.properties, {{"f", PropertyType::Function, true}, {"bound", PropertyType::Solid, true}},
        "implicit", s.loc, mSink);
    bool ok = b.ok();
    ExprGraph graph;
    ExprId root = -1;
    if (const Property* f = b.find("f")) {
        if (f->solid) {
            error(f->solid->loc,
                  "property 'f' of implicit expects a function of x, y, z, got a solid");
            ok = false;
        } else if (const auto v = evaluate(*f->expr, &graph)) {
            if (v->type == Value::Type::Vector) {
                error(f->expr->start,
                      "property 'f' of implicit expects a function of x, y, z, got a vector");
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
        if (p->expr && p->expr->kind == Expr::Kind::Name && mSolids.count(p->expr->name())) {
            error(p->expr->start,
                  "a named solid is not allowed as the bound of an implicit: write box { min … max "
                  "… } "
                  "in place of '" +
                      p->expr->name() + "'",
                  implicitBoundHint());
        } else if (p->expr) {
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

}  // namespace kerf
