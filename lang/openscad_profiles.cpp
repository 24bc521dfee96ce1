// The one adapter between the .csg reader and 2-D profiles (csg/profiles/profile.h): circle, square
// and polygon are profiles, 2-D Booleans, multmatrix and color combine them, and linear_extrude and
// rotate_extrude make solids of them. A 2-D node is read only under an extrusion: kerf traces
// solids, so a 2-D shape anywhere else is an error at its line.
//
// Frames: makeExtrude and makeRevolve draw the profile in kerf's (x, z) and sweep / turn about
// y. OpenSCAD draws it in (x, y) and sweeps / turns about z. The map (x, y, z) ↦ (x, z, y)
// takes one to the other (the reader turns the whole model to y-up at the end): the profile
// keeps its coordinates, makeExtrude's twist (counter-clockwise seen from +y) becomes clockwise
// seen from +z, which is OpenSCAD's sense for a positive twist, and makeRevolve's turn from +x
// toward +z becomes OpenSCAD's turn from +x toward +y.
#include "csg/profiles/profile.h"
#include "csg/tree/solids.h"
#include "lang/openscad_lower.h"

#include <cmath>
#include <map>
#include <optional>

namespace kerf {

namespace {

bool isFlatShape(const std::string& n) {
    return n == "circle" || n == "square" || n == "polygon" || n == "text" || n == "offset";
}
bool isSolidNode(const std::string& n) {
    return n == "cube" || n == "sphere" || n == "cylinder" || n == "polyhedron" ||
           n == "linear_extrude" || n == "rotate_extrude";
}

/// A finite number, or null.
const double* finiteNumber(const ScadValue& v) {
    return v.kind == ScadValue::Kind::Number && std::isfinite(v.number) ? &v.number : nullptr;
}

/// A vector [a, b] (or longer, the rest ignored when `exact` is false) of finite numbers.
bool numberPair(const ScadValue& v, Vec2& out, bool exact) {
    if (v.kind != ScadValue::Kind::Vector || v.items.size() < 2 || (exact && v.items.size() != 2))
        return false;
    const double* a = finiteNumber(v.items[0]);
    const double* b = finiteNumber(v.items[1]);
    if (!a || !b) return false;
    out = Vec2(*a, *b);
    return true;
}

/// One 2-D subtree under an extrusion, read into a profile. nullopt is an empty shape (as
/// OpenSCAD drops it from Booleans) or an error (then `failed` is set, the error reported).
class FlatReader {
public:
    explicit FlatReader(ScadLowering& l) : mL(l) {}

    bool failed = false;
    /// The first color met in the subtree: the solid's material.
    const ScadCall* color = nullptr;

    std::optional<Profile> boolean(const std::string& op, const std::vector<ScadCall>& calls) {
        std::vector<std::optional<Profile>> children;
        for (const ScadCall& c : calls) {
            if (c.modifier == '%' || c.modifier == '*') continue;  // not part of the model
            children.push_back(read(c));
        }
        std::vector<Profile> present;
        for (auto& p : children)
            if (p) present.push_back(*p);
        if (op == "difference") {
            if (children.empty() || !children.front()) return std::nullopt;
            return present.size() == 1 ? present.front() : profileDifference(std::move(present));
        }
        if (op == "intersection") {
            if (present.empty() || present.size() < children.size()) return std::nullopt;
            return present.size() == 1 ? present.front() : profileIntersection(std::move(present));
        }
        if (present.empty()) return std::nullopt;
        return present.size() == 1 ? present.front() : profileUnion(std::move(present));
    }

private:
    std::optional<Profile> read(const ScadCall& c) {
        if (c.name == "circle") return circle(c);
        if (c.name == "square") return square(c);
        if (c.name == "polygon") return polygon(c);
        if (c.name == "multmatrix") return multmatrix(c);
        if (c.name == "text") return text(c);
        if (c.name == "offset") return offset(c);
        if (c.name == "color") {
            if (!color)
                color = &c;
            else if (!sameColor(*color, c))
                mL.warning(c.pos,
                           "2-D parts of one extrusion have different colours: the solid "
                           "takes the first one's");
            return boolean("union", c.children);
        }
        if (c.name == "group" || c.name == "union" || c.name == "render" ||
            c.name == "difference" || c.name == "intersection")
            return boolean(c.name, c.children);
        failed = true;
        if (isSolidNode(c.name)) {
            mL.error(c.pos, c.name + " is a solid under an extrusion, which takes 2-D shapes only",
                     "OpenSCAD ignores it there too");
            return std::nullopt;
        }
        mL.reportUnsupportedWithin({c});  // offset, text, projection, unknown names
        return std::nullopt;
    }

    static bool sameColor(const ScadCall& a, const ScadCall& b) {
        const ScadArg* x = a.arg("c", 0);
        const ScadArg* y = b.arg("c", 0);
        if (!x || !y) return !x && !y;
        const ScadValue &u = x->value, &v = y->value;
        if (u.kind != ScadValue::Kind::Vector || v.kind != ScadValue::Kind::Vector ||
            u.items.size() < 3 || v.items.size() < 3)
            return false;
        for (size_t i = 0; i < 3; ++i)
            if (u.items[i].number != v.items[i].number) return false;
        return true;
    }

    std::optional<Profile> circle(const ScadCall& c) {
        double r = 1.0;
        if (!mL.radius(c, "r", 0, "d", r)) return fail();
        if (r < 0) {
            mL.error(c.pos, "circle radius must not be negative");
            return fail();
        }
        if (r == 0) {
            mL.warning(c.pos, "circle of radius 0 is empty (OpenSCAD drops it too)");
            return std::nullopt;
        }
        mL.countFacets(c, r);
        return profileCircle(Vec2(0.0), r);
    }

    std::optional<Profile> square(const ScadCall& c) {
        Vec2 size(1.0);
        bool center = false;
        if (const ScadArg* a = c.arg("size", 0); a && a->value.kind != ScadValue::Kind::Undef) {
            if (const double* n = finiteNumber(a->value)) {
                size = Vec2(*n);
            } else if (!numberPair(a->value, size, true)) {
                mL.error(a->value.pos,
                         "square size must be a number or a vector [x, y] of finite numbers");
                return fail();
            }
            if (size.x < 0 || size.y < 0) {
                mL.error(a->value.pos, "square size must not be negative");
                return fail();
            }
        }
        if (!mL.flag(c, "center", 1, center)) return fail();
        if (size.x == 0 || size.y == 0) {
            mL.warning(c.pos, "square of zero size is empty (OpenSCAD drops it too)");
            return std::nullopt;
        }
        const Vec2 lo = center ? -0.5 * size : Vec2(0.0);
        return profileRect(lo, lo + size);
    }

    std::optional<Profile> polygon(const ScadCall& c) {
        const ScadArg* pts = c.arg("points", 0);
        std::vector<Vec2> points;
        if (pts && pts->value.kind != ScadValue::Kind::Undef) {
            bool ok = pts->value.kind == ScadValue::Kind::Vector;
            for (size_t i = 0; ok && i < pts->value.items.size(); ++i) {
                Vec2 p;
                ok = numberPair(pts->value.items[i], p, false);  // a z is ignored, as in OpenSCAD
                points.push_back(p);
            }
            if (!ok) {
                mL.error(pts->value.pos,
                         "polygon points must be a vector of [x, y] points of finite numbers");
                return fail();
            }
        }
        if (points.empty()) {
            mL.warning(c.pos, "polygon without points is empty");
            return std::nullopt;
        }
        std::vector<std::vector<Vec2>> loops;
        const ScadArg* paths = c.arg("paths", 1);
        if (!paths || paths->value.kind == ScadValue::Kind::Undef) {
            loops.push_back(points);  // no paths: the points in order
        } else {
            const ScadValue& v = paths->value;
            if (v.kind != ScadValue::Kind::Vector) {
                mL.error(v.pos, "polygon paths must be a vector of vectors of point indices");
                return fail();
            }
            for (const ScadValue& path : v.items) {
                std::vector<Vec2> loop;
                bool ok = path.kind == ScadValue::Kind::Vector;
                for (size_t i = 0; ok && i < path.items.size(); ++i) {
                    const double* n = finiteNumber(path.items[i]);
                    ok = n && *n >= 0 && *n == std::floor(*n) &&
                         *n < static_cast<double>(points.size());
                    if (ok) loop.push_back(points[static_cast<size_t>(*n)]);
                }
                if (!ok) {
                    mL.error(path.pos,
                             "polygon path must be a vector of indices into points (0 to " +
                                 std::to_string(points.size() - 1) + ")");
                    return fail();
                }
                loops.push_back(std::move(loop));
            }
        }
        for (const auto& loop : loops) {
            if (loop.size() < 3) {
                mL.error(paths ? paths->value.pos : pts->value.pos,
                         "polygon outline of fewer than three points");
                return fail();
            }
        }
        if (loops.empty()) return std::nullopt;
        // All outlines are filled together by the even-odd rule, as OpenSCAD does.
        return profilePolygon(loops.front(),
                              std::vector<std::vector<Vec2>>(loops.begin() + 1, loops.end()));
    }

    std::optional<Profile> multmatrix(const ScadCall& c) {
        // A 2-D shape takes the matrix's in-plane part (rows and columns x, y, and the
        // translation), as OpenSCAD applies it to 2-D geometry.
        double m[6] = {1, 0, 0, 0, 1, 0};
        if (const ScadArg* a = c.arg("m", 0)) {
            const ScadValue& v = a->value;
            bool ok = v.kind == ScadValue::Kind::Vector && v.items.size() >= 2;
            for (size_t i = 0; ok && i < 2; ++i) {
                const ScadValue& row = v.items[i];
                ok = row.kind == ScadValue::Kind::Vector && row.items.size() == 4;
                for (size_t j = 0; ok && j < 4; ++j) ok = finiteNumber(row.items[j]) != nullptr;
                if (ok) {
                    m[3 * i] = row.items[0].number;
                    m[3 * i + 1] = row.items[1].number;
                    m[3 * i + 2] = row.items[3].number;
                }
            }
            if (!ok) {
                mL.error(v.pos, "multmatrix m must be a 4×4 (or 3×4) matrix of finite numbers");
                return fail();
            }
            const double det = m[0] * m[4] - m[1] * m[3];
            if (!(std::fabs(det) > 0) || !std::isfinite(1.0 / det)) {
                mL.error(v.pos, "multmatrix flattens a 2-D shape (its x-y part is singular)",
                         "a scale of 0 in x or y leaves no area to extrude");
                return fail();
            }
        }
        std::optional<Profile> child = boolean("union", c.children);
        if (!child) return std::nullopt;
        return profileTransform(std::move(*child), m);
    }

    /// A string argument; false (with an error) when it is not one.
    bool string(const ScadCall& c, const std::string& name, int position, std::string& out) {
        const ScadArg* a = c.arg(name, position);
        if (!a || a->value.kind == ScadValue::Kind::Undef) return true;
        if (a->value.kind != ScadValue::Kind::String) {
            mL.error(a->value.pos, c.name + " " + name + " must be a string");
            return false;
        }
        out = a->value.text;
        return true;
    }

    /// text(text, size, font, halign, valign, spacing, direction, …): the font's outlines,
    /// exact. OpenSCAD draws `size` points at 100 dpi against 72, so its em is size / 0.72
    /// ('H' of DejaVu Sans at size 10 is 10.125 high there: 0.729 em).
    std::optional<Profile> text(const ScadCall& c) {
        TextRequest spec;
        spec.font = "Liberation Sans";  // OpenSCAD's default
        spec.acceptSubstitute = true;   // fontconfig's substitute, as OpenSCAD takes it
        double size = 10.0;
        std::string halign = "left", valign = "baseline", direction = "ltr";
        if (!string(c, "text", 0, spec.text) || !mL.number(c, "size", 1, size) ||
            !string(c, "font", 2, spec.font) || !string(c, "halign", 3, halign) ||
            !string(c, "valign", 4, valign) || !mL.number(c, "spacing", 5, spec.spacing) ||
            !string(c, "direction", 6, direction))
            return fail();
        if (!(size > 0) || !(spec.spacing > 0)) {
            mL.error(c.pos, "text size and spacing must be positive");
            return fail();
        }
        if (direction != "ltr") {
            mL.error(c.pos, "text direction '" + direction + "' is not supported (only \"ltr\")");
            return fail();
        }
        spec.size = size / 0.72;
        if (spec.font.empty()) spec.font = "Liberation Sans";  // OpenSCAD's default, too
        const std::map<std::string, TextRequest::HAlign> h = {
            {"left", TextRequest::HAlign::Left},
            {"center", TextRequest::HAlign::AdvanceCenter},
            {"right", TextRequest::HAlign::Right}};
        const std::map<std::string, TextRequest::VAlign> v = {
            {"baseline", TextRequest::VAlign::Baseline},
            {"top", TextRequest::VAlign::Top},
            {"center", TextRequest::VAlign::Center},
            {"bottom", TextRequest::VAlign::Bottom}};
        if (!h.count(halign) || !v.count(valign)) {
            mL.error(c.pos,
                     "text halign must be left, center or right and valign baseline, top, center "
                     "or bottom");
            return fail();
        }
        spec.halign = h.at(halign);
        spec.valign = v.at(valign);
        const Loaded<TextShape> text = mL.assets().text(spec);
        if (!text) {
            mL.error(c.pos, text.error.reason, text.error.hint);
            return fail();
        }
        const TextShape& outline = *text.value;
        if (!outline.substitutedFamily.empty())
            mL.warning(c.pos, "font '" + spec.font + "' is not installed: using '" +
                                  outline.substitutedFamily +
                                  "', the font fontconfig (and so OpenSCAD) substitutes");
        if (outline.shape.loops.empty()) return std::nullopt;  // spaces only: empty, as in OpenSCAD
        if (!outline.glyphsOverlap) return profilePath(outline.shape);
        std::vector<Profile> parts;
        for (const PathShape& glyph : outline.glyphs) parts.push_back(profilePath(glyph));
        return profileUnion(std::move(parts));
    }

    /// offset(r): the exact rounded offset (the distance's level set). offset(delta), with
    /// its mitred or chamfered corners, is not a distance level set: an error.
    std::optional<Profile> offset(const ScadCall& c) {
        if (const ScadArg* d = c.arg("delta"); d && d->value.kind != ScadValue::Kind::Undef) {
            mL.unsupported(
                c,
                "offset(delta) is not supported: its mitred or chamfered corners are not a rounded "
                "offset; offset(r) is exact in kerf");
            return fail();
        }
        double r = 1.0;  // OpenSCAD's default
        if (!mL.number(c, "r", 0, r)) return fail();
        std::optional<Profile> child = boolean("union", c.children);
        if (!child) return std::nullopt;
        if (r == 0.0) return child;
        return profileOffset(std::move(*child), r);
    }

    std::optional<Profile> fail() {
        failed = true;
        return std::nullopt;
    }

    ScadLowering& mL;
};

/// The solid in makeExtrude / makeRevolve's frame put into OpenSCAD's: (x, y, z) ↦ (x, z, y),
/// or (x, −z, y) when `mirrorY` (a rotate_extrude by a negative angle).
NodePtr toOpenScadFrame(NodePtr solid, bool mirrorY) {
    const double s = mirrorY ? -1.0 : 1.0;
    const double m[12] = {1, 0, 0, 0, 0, 0, s, 0, 0, 1, 0, 0};
    return makeTransform(std::move(solid), Affine::fromRowMajor(m));
}

NodePtr linearExtrude(const ScadCall& c, ScadLowering& l, const Profile& p) {
    ExtrudeOptions o;
    o.height = 100.0;  // OpenSCAD's default
    if (!l.number(c, "height", 0, o.height) || !l.flag(c, "center", 1, o.center) ||
        !l.number(c, "twist", -1, o.twist))
        return nullptr;
    if (const ScadArg* a = c.arg("scale"); a && a->value.kind != ScadValue::Kind::Undef) {
        Vec2 s;
        if (const double* n = finiteNumber(a->value)) {
            s = Vec2(*n);
        } else if (!numberPair(a->value, s, true)) {
            l.error(a->value.pos, "linear_extrude scale must be a number or a vector [sx, sy]");
            return nullptr;
        }
        if (!(s.x > 0 && s.y > 0)) {
            l.error(a->value.pos, "linear_extrude scale must be > 0",
                    "kerf's extrusion does not narrow to a point or a line (scale 0)");
            return nullptr;
        }
        o.scale = s;
    }
    if (o.height < 0) {
        l.error(c.pos, "linear_extrude height must not be negative");
        return nullptr;
    }
    if (o.height == 0) {
        l.warning(c.pos, "linear_extrude of height 0 is empty");
        return nullptr;
    }
    return toOpenScadFrame(makeExtrude(p, o), false);
}

NodePtr rotateExtrude(const ScadCall& c, ScadLowering& l, Profile p) {
    double angle = 360.0;
    if (!l.number(c, "angle", -1, angle)) return nullptr;
    if (angle == 0) {
        l.warning(c.pos, "rotate_extrude by an angle of 0 is empty");
        return nullptr;
    }
    const bool negative = angle < 0;
    const double degrees = std::min(std::fabs(angle), 360.0);  // OpenSCAD caps it at a full turn
    if (p.bounds.hi.x <= 0) {
        // OpenSCAD turns a profile left of the axis as well: its mirror image.
        const double mirror[6] = {-1, 0, 0, 0, 1, 0};
        p = profileTransform(std::move(p), mirror);
    } else if (p.bounds.lo.x < 0) {
        l.warning(c.pos,
                  "rotate_extrude: the profile may reach x < 0; only its part at x ≥ 0 is "
                  "turned (OpenSCAD refuses a profile on both sides of the axis)");
    }
    return toOpenScadFrame(makeRevolve(p, degrees), negative);
}

}  // namespace

bool isScadProfileNode(const std::string& name) {
    return isFlatShape(name) || name == "linear_extrude" || name == "rotate_extrude";
}

NodePtr lowerScadProfileNode(const ScadCall& c, ScadLowering& lowering) {
    if (isFlatShape(c.name)) {
        lowering.error(c.pos,
                       c.name +
                           " is a 2-D shape outside linear_extrude or rotate_extrude: "
                           "kerf traces solids only",
                       "extrude it (linear_extrude) to make a solid of it");
        return nullptr;
    }
    if (const ScadArg* file = c.arg("file"); file && file->value.kind != ScadValue::Kind::Undef) {
        lowering.error(file->value.pos,
                       c.name + " file imports a DXF drawing, which kerf does not read");
        return nullptr;
    }
    FlatReader reader(lowering);
    std::optional<Profile> profile = reader.boolean("union", c.children);
    if (reader.failed) return nullptr;
    if (!profile) {
        lowering.warning(c.pos, c.name + " of an empty 2-D shape is empty");
        return nullptr;
    }
    NodePtr solid = c.name == "linear_extrude" ? linearExtrude(c, lowering, *profile)
                                               : rotateExtrude(c, lowering, std::move(*profile));
    if (solid && reader.color) return lowering.applyColor(*reader.color, solid);
    return solid;
}

}  // namespace kerf
