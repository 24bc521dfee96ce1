// The .csg reader's lowering: OpenSCAD's Booleans, multmatrix, color and 3-D primitives onto
// csg/ nodes in OpenSCAD's own z-up coordinates; the whole model is turned to kerf's y-up at
// the end, framed by a default camera and lit by default lights. Empty solids (a group of
// nothing, a cube of size 0) are null, as OpenSCAD drops them from its Booleans.
#include "lang/openscad_lower.h"

#include "csg/affine_check.h"
#include "csg/tree/solids.h"
#include "lang/no_assets.h"
#include "lang/source.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace kerf {

namespace {

const char* kindName(ScadValue::Kind k) {
    switch (k) {
        case ScadValue::Kind::Undef: return "undef";
        case ScadValue::Kind::Bool: return "a boolean";
        case ScadValue::Kind::Number: return "a number";
        case ScadValue::Kind::String: return "a string";
        case ScadValue::Kind::Vector: return "a vector";
    }
    return "?";
}

/// Nodes that cannot be read, with why; each is reported at its own line.
const std::map<std::string, std::string>& unsupportedReasons() {
    static const std::map<std::string, std::string> reasons = {
        {"hull", "kerf traces exact primitives and has no convex hull"},
        {"minkowski", "kerf traces exact primitives and has no Minkowski sum"},
        {"projection", "kerf has no projection of a solid onto a plane (kerf slice cuts one)"},
        {"resize", "resize depends on OpenSCAD's polygonal bounding box"},
        {"import", "imported files are not read inside a .csg"},
        {"surface", "height maps are not read"},
        {"roof", "roof is not read"},
        {"fill", "fill is not read"},
    };
    return reasons;
}

/// The most fragments reported: `$fn = 1e12` or `$fs = 1e-300` would not fit an int.
constexpr int kMaxFragments = 1 << 30;

/// OpenSCAD's number of fragments for a circle of radius r (its get_fragments_from_r), at most
/// kMaxFragments (only reported: kerf traces the circle exactly).
int openScadFragments(double r, double fn, double fs, double fa) {
    if (r < 0.00000095367431640625) return 3;
    const double n = fn > 0.0 ? (fn >= 3 ? fn : 3)
                              : std::ceil(std::max(std::min(360.0 / fa, r * 2 * M_PI / fs), 5.0));
    return n < kMaxFragments ? static_cast<int>(n) : kMaxFragments;  // NaN too
}

}  // namespace

void ScadLowering::warning(SourcePos pos, std::string message) {
    Diagnostic d;
    d.loc = mSink.locate(pos);
    d.severity = Severity::Warning;
    d.message = std::move(message);
    mSink.report(std::move(d));
}

bool ScadLowering::number(const ScadCall& c, const std::string& name, int position, double& out) {
    const ScadArg* a = c.arg(name, position);
    if (!a || a->value.kind == ScadValue::Kind::Undef) return true;
    if (a->value.kind != ScadValue::Kind::Number) {
        error(a->value.pos,
              c.name + " " + name + " must be a number, got " + kindName(a->value.kind));
        return false;
    }
    if (!std::isfinite(a->value.number)) {
        error(a->value.pos, c.name + " " + name + " must be finite");
        return false;
    }
    out = a->value.number;
    return true;
}

bool ScadLowering::flag(const ScadCall& c, const std::string& name, int position, bool& out) {
    const ScadArg* a = c.arg(name, position);
    if (!a || a->value.kind == ScadValue::Kind::Undef) return true;
    if (a->value.kind != ScadValue::Kind::Bool) {
        error(a->value.pos,
              c.name + " " + name + " must be true or false, got " + kindName(a->value.kind));
        return false;
    }
    out = a->value.boolean;
    return true;
}

bool ScadLowering::triple(const ScadCall& c, const std::string& name, int position, Vec3& out) {
    const ScadArg* a = c.arg(name, position);
    if (!a || a->value.kind == ScadValue::Kind::Undef) return true;
    const ScadValue& v = a->value;
    if (v.kind == ScadValue::Kind::Number && std::isfinite(v.number)) {
        out = Vec3(v.number);
        return true;
    }
    bool ok = v.kind == ScadValue::Kind::Vector && v.items.size() == 3;
    for (size_t i = 0; ok && i < 3; ++i)
        ok = v.items[i].kind == ScadValue::Kind::Number && std::isfinite(v.items[i].number);
    if (!ok) {
        error(v.pos, c.name + " " + name + " must be a number or a vector of three finite numbers");
        return false;
    }
    out = Vec3(v.items[0].number, v.items[1].number, v.items[2].number);
    return true;
}

bool ScadLowering::radius(const ScadCall& c, const std::string& rName, int position,
                          const std::string& dName, double& out) {
    double d = 0.0;
    const ScadArg* diameter = c.arg(dName);
    if (!number(c, rName, position, out) || !number(c, dName, -1, d)) return false;
    if (diameter && diameter->value.kind == ScadValue::Kind::Number) out = 0.5 * d;  // d wins
    return true;
}

void ScadLowering::countFacets(const ScadCall& c, double r) {
    double fn = 0.0, fa = 12.0, fs = 2.0;  // OpenSCAD's defaults
    number(c, "$fn", -1, fn);
    number(c, "$fa", -1, fa);
    number(c, "$fs", -1, fs);
    if (!(fa > 0)) fa = 12.0;
    if (!(fs > 0)) fs = 2.0;
    const int f = openScadFragments(r, fn, fs, fa);
    if (mCurves++ == 0) {
        mFirstCurve = c.pos;
        mFewestFacets = mMostFacets = f;
    }
    mFewestFacets = std::min(mFewestFacets, f);
    mMostFacets = std::max(mMostFacets, f);
}

void ScadLowering::reportFacets() {
    if (mCurves == 0) return;
    Diagnostic d;
    d.loc = mSink.locate(mFirstCurve);
    d.severity = Severity::Note;
    const std::string facets =
        mFewestFacets == mMostFacets
            ? std::to_string(mFewestFacets)
            : std::to_string(mFewestFacets) + " to " + std::to_string(mMostFacets);
    d.message =
        "$fn, $fa and $fs are ignored: kerf traces circles, spheres and cylinders exactly (" +
        std::to_string(mCurves) + " here), where OpenSCAD would have used " + facets +
        " facets around each";
    mSink.report(std::move(d));
}

std::vector<NodePtr> ScadLowering::lowerChildren(const std::vector<ScadCall>& calls) {
    std::vector<NodePtr> out;
    for (const ScadCall& child : calls) {
        if (child.modifier == '%' || child.modifier == '*') continue;  // not part of the model
        out.push_back(lower(child));
    }
    return out;
}

NodePtr ScadLowering::lowerBoolean(const std::string& op, const std::vector<ScadCall>& calls) {
    std::vector<NodePtr> children = lowerChildren(calls);
    std::vector<NodePtr> present;
    for (const NodePtr& n : children)
        if (n) present.push_back(n);
    if (op == "difference") {
        // The first child is the body whatever it holds; an empty body leaves nothing.
        if (children.empty() || !children.front()) return nullptr;
        std::vector<NodePtr> operands{children.front()};
        for (size_t i = 1; i < children.size(); ++i)
            if (children[i]) operands.push_back(children[i]);
        return operands.size() == 1 ? operands.front()
                                    : makeBoolean(BoolOp::Difference, std::move(operands));
    }
    if (op == "intersection") {
        if (present.empty() || present.size() < children.size()) return nullptr;
        return present.size() == 1 ? present.front()
                                   : makeBoolean(BoolOp::Intersection, std::move(present));
    }
    // group, union, render: the union of what is there.
    if (present.empty()) return nullptr;
    return present.size() == 1 ? present.front() : makeBoolean(BoolOp::Union, std::move(present));
}

NodePtr ScadLowering::lowerMultmatrix(const ScadCall& c) {
    const ScadArg* a = c.arg("m", 0);
    double m[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    if (a) {
        const ScadValue& v = a->value;
        bool ok = v.kind == ScadValue::Kind::Vector && (v.items.size() == 3 || v.items.size() == 4);
        for (size_t i = 0; ok && i < v.items.size(); ++i) {
            const ScadValue& row = v.items[i];
            ok = row.kind == ScadValue::Kind::Vector && row.items.size() == 4;
            for (size_t j = 0; ok && j < 4; ++j) {
                ok = row.items[j].kind == ScadValue::Kind::Number &&
                     std::isfinite(row.items[j].number);
                if (ok) m[i][j] = row.items[j].number;
            }
        }
        if (!ok) {
            error(v.pos, "multmatrix m must be a 4×4 (or 3×4) matrix of finite numbers");
            return nullptr;
        }
        if (m[3][0] != 0 || m[3][1] != 0 || m[3][2] != 0 || m[3][3] != 1) {
            error(v.pos, "multmatrix m is projective: its last row must be [0, 0, 0, 1]",
                  "kerf reads affine maps only");
            return nullptr;
        }
    }
    const double rowMajor[12] = {m[0][0], m[0][1], m[0][2], m[0][3], m[1][0], m[1][1],
                                 m[1][2], m[1][3], m[2][0], m[2][1], m[2][2], m[2][3]};
    const Affine map = Affine::fromRowMajor(rowMajor);
    const AffineStatus status = checkAffine(map);
    if (status != AffineStatus::Ok) {
        error(a ? a->value.pos : c.pos,
              status == AffineStatus::Singular
                  ? "multmatrix flattens space (its matrix is singular)"
                  : "multmatrix cannot be inverted in double precision",
              "a scale of 0 along an axis makes a flat solid, which kerf cannot trace");
        return nullptr;
    }
    NodePtr child = lowerBoolean("union", c.children);
    if (!child) return nullptr;
    NodePtr placed = makeTransform(child, map);
    if (child->bounds().finite() && !placed->bounds().finite()) {
        error(a ? a->value.pos : c.pos,
              "multmatrix moves its children beyond the range of doubles (their extent overflows)");
        return nullptr;
    }
    return placed;
}

NodePtr ScadLowering::lowerColor(const ScadCall& c) {
    return applyColor(c, lowerBoolean("union", c.children));
}

NodePtr ScadLowering::applyColor(const ScadCall& c, NodePtr child) {
    const ScadArg* a = c.arg("c", 0);
    if (!a || a->value.kind == ScadValue::Kind::Undef) return child;
    const ScadValue& v = a->value;
    bool ok = v.kind == ScadValue::Kind::Vector && (v.items.size() == 3 || v.items.size() == 4);
    for (size_t i = 0; ok && i < v.items.size(); ++i)
        ok = v.items[i].kind == ScadValue::Kind::Number && std::isfinite(v.items[i].number);
    if (!ok) {
        error(v.pos,
              std::string("color c must be a vector [r, g, b] or [r, g, b, a] of numbers, got ") +
                  (v.kind == ScadValue::Kind::String ? "the name \"" + v.text + "\""
                                                     : kindName(v.kind)),
              "OpenSCAD exports named colours as vectors; export the .csg again");
        return nullptr;
    }
    if (!child) return nullptr;
    auto channel = [&](size_t i) { return std::clamp(v.items[i].number, 0.0, 1.0); };
    const auto key = std::make_tuple(channel(0), channel(1), channel(2));
    auto found = mColorMaterials.find(key);
    if (found == mColorMaterials.end()) {
        Material m;
        m.name = "openscad color " + std::to_string(mColorMaterials.size() + 1);
        m.color = Vec3(channel(0), channel(1), channel(2));
        m.specular = mScene.materials[0].specular;
        m.shininess = mScene.materials[0].shininess;
        found = mColorMaterials.emplace(key, static_cast<int>(mScene.materials.size())).first;
        mScene.materials.push_back(m);
    }
    return makeMaterial(child, found->second);
}

NodePtr ScadLowering::lowerCube(const ScadCall& c) {
    Vec3 size(1.0);
    bool center = false;
    if (!triple(c, "size", 0, size) || !flag(c, "center", 1, center)) return nullptr;
    if (size.x < 0 || size.y < 0 || size.z < 0) {
        error(c.arg("size", 0)->value.pos, "cube size must not be negative");
        return nullptr;
    }
    if (size.x == 0 || size.y == 0 || size.z == 0) {
        warning(c.pos, "cube of zero size is empty (OpenSCAD drops it too)");
        return nullptr;
    }
    const Vec3 lo = center ? -0.5 * size : Vec3(0.0);
    return makeBox(lo, lo + size);
}

NodePtr ScadLowering::lowerSphere(const ScadCall& c) {
    double r = 1.0;
    if (!radius(c, "r", 0, "d", r)) return nullptr;
    if (r < 0) {
        error(c.pos, "sphere radius must not be negative");
        return nullptr;
    }
    if (r == 0) {
        warning(c.pos, "sphere of radius 0 is empty (OpenSCAD drops it too)");
        return nullptr;
    }
    countFacets(c, r);
    return makeSphere(Vec3(0.0), r);
}

NodePtr ScadLowering::lowerCylinder(const ScadCall& c) {
    // OpenSCAD's signature: cylinder(h, r1, r2, center), r and the diameters named only; r
    // sets both radii, r1 and r2 each one.
    double h = 1.0, r = 1.0;
    bool center = false;
    if (!number(c, "h", 0, h) || !radius(c, "r", -1, "d", r) || !flag(c, "center", 3, center))
        return nullptr;
    double r1 = r, r2 = r;
    if (!radius(c, "r1", 1, "d1", r1) || !radius(c, "r2", 2, "d2", r2)) return nullptr;
    if (h < 0 || r1 < 0 || r2 < 0) {
        error(c.pos, "cylinder height and radii must not be negative");
        return nullptr;
    }
    if (h == 0 || (r1 == 0 && r2 == 0)) {
        warning(c.pos, "cylinder of zero height or radius is empty (OpenSCAD drops it too)");
        return nullptr;
    }
    countFacets(c, std::max(r1, r2));
    const double z0 = center ? -0.5 * h : 0.0;
    const Vec3 a(0, 0, z0), b(0, 0, z0 + h);
    return r1 == r2 ? makeCylinder(a, b, r1) : makeCone(a, b, r1, r2);
}

bool ScadLowering::reportIfUnsupported(const ScadCall& c) {
    static const std::set<std::string> known = {
        "group", "union", "render", "difference", "intersection", "multmatrix",
        "color", "cube",  "sphere", "cylinder",   "polyhedron"};
    if (known.count(c.name) || isScadProfileNode(c.name)) return false;
    const auto& reasons = unsupportedReasons();
    auto it = reasons.find(c.name);
    unsupported(c, it != reasons.end() ? c.name + " is not supported: " + it->second
                                       : "unknown OpenSCAD module '" + c.name + "'");
    return true;
}

void ScadLowering::unsupported(const ScadCall& c, const std::string& message) {
    if (++mUnsupported > kMaxUnsupportedReports) {
        if (mUnsupported == kMaxUnsupportedReports + 1) mFirstUnlisted = c.pos;
        return;  // counted, summed up by finish()
    }
    error(c.pos, message,
          "OpenSCAD can export this part as a mesh (openscad -o part.stl), which kerf reads with "
          "mesh \"part.stl\" in a .kerf model; docs/openscad.md lists the nodes read");
}

void ScadLowering::finish() {
    const int unlisted = mUnsupported - kMaxUnsupportedReports;
    if (unlisted > 0)
        error(mFirstUnlisted, std::to_string(unlisted) + " more node" + (unlisted == 1 ? "" : "s") +
                                  " from here on cannot be read either (not listed one by one)");
}

void ScadLowering::reportUnsupportedWithin(const std::vector<ScadCall>& calls) {
    for (const ScadCall& c : calls) {
        reportIfUnsupported(c);
        reportUnsupportedWithin(c.children);
    }
}

NodePtr ScadLowering::lower(const ScadCall& c) {
    if (reportIfUnsupported(c)) {
        reportUnsupportedWithin(c.children);  // every unsupported node in one run
        return nullptr;
    }
    if (isScadProfileNode(c.name)) return lowerScadProfileNode(c, *this);
    if (c.name == "multmatrix") return lowerMultmatrix(c);
    if (c.name == "color") return lowerColor(c);
    if (c.name == "cube") return lowerCube(c);
    if (c.name == "sphere") return lowerSphere(c);
    if (c.name == "cylinder") return lowerCylinder(c);
    if (c.name == "polyhedron") return lowerScadPolyhedron(c, *this);
    return lowerBoolean(c.name, c.children);
}

namespace {

/// The first call marked '!' (root) in the tree, depth first, or null.
const ScadCall* findRoot(const std::vector<ScadCall>& calls) {
    for (const ScadCall& c : calls) {
        if (c.modifier == '!') return &c;
        if (c.modifier == '%' || c.modifier == '*') continue;
        if (const ScadCall* inner = findRoot(c.children)) return inner;
    }
    return nullptr;
}

}  // namespace

NodePtr ScadLowering::lowerAll(const std::vector<ScadCall>& calls) {
    // '!' (root) keeps only that subtree, wherever it is, as OpenSCAD does.
    if (const ScadCall* root = findRoot(calls)) return lower(*root);
    return lowerBoolean("union", calls);
}

}  // namespace kerf
