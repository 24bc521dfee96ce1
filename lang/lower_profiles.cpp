// 2-D profiles (circle, rect, polygon, path, offset, and Booleans of them) and the solids
// made from them (extrude, revolve). The geometry is csg/profiles/profile.h; this file reads
// blocks.
#include "csg/profiles/profile.h"
#include "lang/lower.h"

#include <cmath>

namespace kerf {

namespace {

bool isProfileBoolean(const std::string& name) {
    return name == "union" || name == "intersection" || name == "difference";
}

/// How many points a path step takes (line 1; quad, arc, arc_cw 2; cubic 3), 0 for no step.
int pathStepPoints(const std::string& name) {
    return name == "line"                                        ? 1
           : name == "quad" || name == "arc" || name == "arc_cw" ? 2
           : name == "cubic"                                     ? 3
                                                                 : 0;
}

}  // namespace

bool Lowering::point2(const Expr& e, const std::string& what, Vec2& out) {
    const auto v = evaluate(e, nullptr);
    if (!v) return false;
    if (v->type == Value::Type::List && v->list().size() == 2 &&
        v->list()[0].type == Value::Type::Number && v->list()[1].type == Value::Type::Number) {
        out = Vec2(v->list()[0].number, v->list()[1].number);
        if (std::isfinite(out.x) && std::isfinite(out.y)) return true;
        error(e.start, what + " is not finite");
        return false;
    }
    error(e.start,
          what + " expects a 2-D point [x, y], got " +
              (v->type == Value::Type::List
                   ? "a list of " + std::to_string(v->list().size()) + " values"
                   : typeName(v->type)),
          "2-D points are lists of two numbers: [1, 2]");
    return false;
}

bool Lowering::extrudeScale(const Expr& e, Vec2& out) {
    const auto v = evaluate(e, nullptr);
    if (!v) return false;
    if (v->type == Value::Type::Number) {
        out = Vec2(v->number);
    } else if (!point2(e, "extrude scale", out)) {
        return false;
    }
    if (out.x > 0 && out.y > 0 && std::isfinite(out.x) && std::isfinite(out.y)) return true;
    error(e.start,
          "extrude scale must be positive, got " +
              (out.x == out.y ? formatNumber(out.x)
                              : "[" + formatNumber(out.x) + ", " + formatNumber(out.y) + "]"),
          "a scale of 0 would narrow the profile to a point or a line");
    return false;
}

bool Lowering::points2(const Value& v, SourcePos at, const std::string& what,
                       std::vector<Vec2>& out) {
    if (v.type != Value::Type::List) {
        error(at, what + " expects a list of 2-D points [[x, y], …], got " + typeName(v.type));
        return false;
    }
    for (const Value& p : v.list()) {
        if (p.type != Value::Type::List || p.list().size() != 2 ||
            p.list()[0].type != Value::Type::Number || p.list()[1].type != Value::Type::Number) {
            error(at, what + " expects a list of 2-D points [[x, y], …]; an element is " +
                          (p.type == Value::Type::List
                               ? "a list of " + std::to_string(p.list().size()) + " values"
                               : typeName(p.type)));
            return false;
        }
        out.emplace_back(p.list()[0].number, p.list()[1].number);
        if (!std::isfinite(out.back().x) || !std::isfinite(out.back().y)) {
            error(at, what + " holds a point that is not finite");
            return false;
        }
    }
    if (out.size() < 3) {
        error(at, what + " needs at least 3 points, got " + std::to_string(out.size()));
        return false;
    }
    return true;
}

std::optional<Profile> Lowering::lowerProfile(const Solid& s) {
    if (!enter(s.loc)) return std::nullopt;
    struct Leave {
        int& depth;
        ~Leave() { --depth; }
    } leave{mDepth};
    if (!s.modifiers.empty()) {
        error(s.modifiers[0].loc, "a 2-D profile takes no modifiers",
              "move, turn or scale the extruded or revolved solid instead");
        return std::nullopt;
    }
    if (s.kind == Solid::Kind::Boolean && isProfileBoolean(s.name)) return profileBoolean(s);
    if (s.kind != Solid::Kind::Primitive) {
        error(s.loc,
              "expected a 2-D profile (circle, rect, polygon, path, text, offset, or a union, "
              "intersection "
              "or difference of them), found '" +
                  s.name + "'",
              "profiles are written in place: they cannot be named or made by functions yet");
        return std::nullopt;
    }
    if (s.name == "circle") return circleProfile(s);
    if (s.name == "rect") return rectProfile(s);
    if (s.name == "polygon") return polygonProfile(s);
    if (s.name == "path") return lowerPath(s);
    if (s.name == "text") return textProfile(s);  // lower_text.cpp
    if (s.name == "offset") return offsetProfile(s);
    error(s.loc,
          "expected a 2-D profile (circle, rect, polygon, path, text, offset, or a union, "
          "intersection or "
          "difference of them), found '" +
              s.name + "'");
    return std::nullopt;
}

std::optional<Profile> Lowering::profileBoolean(const Solid& s) {
    std::vector<Profile> parts;
    for (const Solid& child : s.children) {
        if (child.kind != Solid::Kind::Primitive && child.kind != Solid::Kind::Boolean) {
            error(child.loc, "inside a 2-D " + s.name +
                                 " write profiles in place (circle, rect, polygon, "
                                 "path, offset or a Boolean of them)");
            return std::nullopt;
        }
        auto p = lowerProfile(child);
        if (!p) return std::nullopt;
        parts.push_back(std::move(*p));
    }
    if (parts.empty()) {
        error(s.loc, "a 2-D " + s.name + " needs at least one profile");
        return std::nullopt;
    }
    if (s.name == "union") return profileUnion(std::move(parts));
    if (s.name == "intersection") return profileIntersection(std::move(parts));
    return profileDifference(std::move(parts));
}

std::optional<Profile> Lowering::circleProfile(const Solid& s) {
    const PropertyBlock b(s.properties,
                          {{"center", PropertyType::Function}, {"radius", PropertyType::Number}},
                          "circle", s.loc, mSink);
    Vec2 center(0.0);
    double radius = 1.0;
    bool ok = b.ok() && readNumber(b, "radius", radius);
    if (ok && b.find("center")) ok = point2(*b.find("center")->expr, "center of circle", center);
    if (ok && !(radius > 0)) {
        error(b.find("radius")->valueLoc(),
              "circle radius must be positive, got " + formatNumber(radius));
        ok = false;
    }
    if (!ok) return std::nullopt;
    return profileCircle(center, radius);
}

std::optional<Profile> Lowering::rectProfile(const Solid& s) {
    const PropertyBlock b(
        s.properties,
        {{"min", PropertyType::Function, true}, {"max", PropertyType::Function, true}}, "rect",
        s.loc, mSink);
    Vec2 lo(0.0), hi(0.0);
    if (!b.ok() || !point2(*b.find("min")->expr, "min of rect", lo) ||
        !point2(*b.find("max")->expr, "max of rect", hi))
        return std::nullopt;
    if (!(lo.x < hi.x && lo.y < hi.y)) {
        error(s.loc, "empty rect: min [" + formatNumber(lo.x) + ", " + formatNumber(lo.y) +
                         "] must be less than max [" + formatNumber(hi.x) + ", " +
                         formatNumber(hi.y) + "] on both axes");
        return std::nullopt;
    }
    return profileRect(lo, hi);
}

std::optional<Profile> Lowering::polygonProfile(const Solid& s) {
    const PropertyBlock b(
        s.properties, {{"points", PropertyType::Function, true}, {"holes", PropertyType::Function}},
        "polygon", s.loc, mSink);
    if (!b.ok()) return std::nullopt;
    std::vector<Vec2> outline;
    const Property* pts = b.find("points");
    const auto v = evaluate(*pts->expr, nullptr);
    if (!v || !points2(*v, pts->valueLoc(), "points of polygon", outline)) return std::nullopt;
    std::vector<std::vector<Vec2>> holes;
    if (const Property* h = b.find("holes")) {
        const auto list = evaluate(*h->expr, nullptr);
        if (!list) return std::nullopt;
        if (list->type != Value::Type::List) {
            error(h->valueLoc(),
                  "holes of polygon expects a list of point lists [[[x, y], …], …], got " +
                      typeName(list->type));
            return std::nullopt;
        }
        for (const Value& hole : list->list()) {
            holes.emplace_back();
            if (!points2(hole, h->valueLoc(), "a hole of polygon", holes.back()))
                return std::nullopt;
        }
    }
    return profilePolygon(outline, holes);
}

std::optional<Profile> Lowering::offsetProfile(const Solid& s) {
    const PropertyBlock b(
        s.properties,
        {{"distance", PropertyType::Number, true}, {"profile", PropertyType::Solid, true}},
        "offset", s.loc, mSink);
    double r = 0.0;
    if (!b.ok() || !readNumber(b, "distance", r)) return std::nullopt;
    auto inner = profileProperty(b);
    if (!inner) return std::nullopt;
    return profileOffset(std::move(*inner), r);
}

std::optional<Profile> Lowering::profileProperty(const PropertyBlock& b) {
    const Property* p = b.find("profile");
    if (!p->solid) {
        error(p->valueLoc(),
              "property 'profile' of " + b.what() +
                  " expects a 2-D profile such as circle { radius 1 }",
              "profiles are written in place: circle, rect, polygon, path, offset, or a Boolean of "
              "them");
        return std::nullopt;
    }
    return lowerProfile(*p->solid);
}

std::optional<Profile> Lowering::lowerPath(const Solid& s) {
    // Read in order: `start P` begins a loop; `line P`, `arc [TO, CENTER]`, `arc_cw [TO,
    // CENTER]`, `quad [C, P]` and `cubic [C1, C2, P]` extend it; each loop is closed by a line
    // back to its start when it does not end there.
    PathShape shape;
    Vec2 start(0.0), at(0.0);
    bool open = false;
    const auto closeLoop = [&]() {
        if (!open) return;
        auto& segs = shape.loops.back().segments;
        if (at != start) {
            PathSegment line;
            line.p[0] = at;
            line.p[1] = start;
            segs.push_back(line);
        }
        open = false;
    };
    for (const Property& p : s.properties) {
        const std::string name = p.name;
        if (!p.expr) {
            error(p.loc, "'" + name + "' in path needs a value", "e.g. line [1, 0]");
            return std::nullopt;
        }
        if (name == "start") {
            closeLoop();
            if (!point2(*p.expr, "start of path", start)) return std::nullopt;
            at = start;
            shape.loops.emplace_back();
            open = true;
            continue;
        }
        const int count = pathStepPoints(name);
        if (count == 0) {
            error(p.loc, "unknown step '" + name + "' in path",
                  "path takes: start [x, y], line [x, y], arc [to, center], arc_cw [to, center], "
                  "quad [c, p], "
                  "cubic [c1, c2, p]");
            return std::nullopt;
        }
        if (!open) {
            error(p.loc, "path: '" + name + "' before 'start'",
                  "begin each loop with start [x, y]");
            return std::nullopt;
        }
        std::vector<Vec2> pts;
        if (!readPathPoints(p, name, count, pts)) return std::nullopt;
        const std::optional<PathSegment> seg = pathSegment(p, name, at, pts);
        if (!seg) return std::nullopt;
        shape.loops.back().segments.push_back(*seg);
        at = seg->end();
    }
    closeLoop();
    size_t segments = 0;
    for (const PathLoop& l : shape.loops) segments += l.segments.size();
    if (segments == 0) {
        error(s.loc, "empty path: write start [x, y] and then line, arc, quad or cubic steps");
        return std::nullopt;
    }
    return profilePath(std::move(shape));
}

bool Lowering::readPathPoints(const Property& p, const std::string& name, int count,
                              std::vector<Vec2>& pts) {
    if (count == 1) {
        pts.emplace_back();
        if (!point2(*p.expr, name + " of path", pts[0])) return false;
    } else {
        if (p.expr->kind != Expr::Kind::List ||
            p.expr->args().size() != static_cast<size_t>(count)) {
            error(p.expr->start,
                  name + " of path expects a list of " + std::to_string(count) + " points",
                  name == "quad"    ? "quad [control, end]"
                  : name == "cubic" ? "cubic [control1, control2, end]"
                                    : name + " [end, center]");
            return false;
        }
        for (const Expr& e : p.expr->args()) {
            pts.emplace_back();
            if (!point2(e, "a point of " + name, pts.back())) return false;
        }
    }
    return true;
}

std::optional<PathSegment> Lowering::pathSegment(const Property& p, const std::string& name,
                                                 Vec2 at, const std::vector<Vec2>& pts) {
    PathSegment seg;
    seg.p[0] = at;
    if (name == "line") {
        seg.p[1] = pts[0];
    } else if (name == "quad") {
        seg.kind = PathSegment::Kind::Quadratic;
        seg.p[1] = pts[0];
        seg.p[2] = pts[1];
    } else if (name == "cubic") {
        seg.kind = PathSegment::Kind::Cubic;
        seg.p[1] = pts[0];
        seg.p[2] = pts[1];
        seg.p[3] = pts[2];
    } else {
        seg.kind = PathSegment::Kind::Arc;
        seg.p[1] = pts[0];
        seg.p[2] = pts[1];
        seg.ccw = name == "arc";
        const double r0 = glm::length(at - pts[1]), r1 = glm::length(pts[0] - pts[1]);
        if (!(r0 > 0.0) || std::abs(r0 - r1) > 1e-9 * std::max(r0, r1)) {
            error(p.expr->start,
                  name +
                      " of path: its start and end must be at the same distance from the "
                      "center, got " +
                      formatNumber(r0) + " and " + formatNumber(r1));
            return std::nullopt;
        }
    }
    return seg;
}

NodePtr Lowering::lowerExtrude(const Solid& s) {
    const PropertyBlock b(s.properties,
                          {{"profile", PropertyType::Solid, true},
                           {"height", PropertyType::Number, true},
                           {"twist", PropertyType::Number},
                           {"scale", PropertyType::Function},
                           {"center", PropertyType::Bool}},
                          "extrude", s.loc, mSink);
    ExtrudeOptions o;
    bool ok = b.ok();
    ok &= readNumber(b, "height", o.height);
    ok &= readNumber(b, "twist", o.twist);
    ok &= readBool(b, "center", o.center);
    if (ok && !(o.height > 0)) {
        error(b.find("height")->valueLoc(),
              "extrude height must be positive, got " + formatNumber(o.height));
        ok = false;
    }
    if (const auto* scale = b.find("scale"); ok && scale) ok = extrudeScale(*scale->expr, o.scale);
    if (!ok) return nullptr;
    const auto profile = profileProperty(b);
    return profile ? makeExtrude(*profile, o) : nullptr;
}

NodePtr Lowering::lowerRevolve(const Solid& s) {
    const PropertyBlock b(s.properties,
                          {{"profile", PropertyType::Solid, true}, {"angle", PropertyType::Number}},
                          "revolve", s.loc, mSink);
    double angle = 360.0;
    if (!b.ok() || !readNumber(b, "angle", angle)) return nullptr;
    if (!(angle > 0.0 && angle <= 360.0)) {
        error(b.find("angle")->valueLoc(),
              "revolve angle must be in (0, 360] degrees, got " + formatNumber(angle));
        return nullptr;
    }
    const auto profile = profileProperty(b);
    if (!profile) return nullptr;
    if (!(profile->bounds.hi.x > 0.0)) {
        error(b.find("profile")->valueLoc(),
              "revolve: the profile lies at u ≤ 0; only its part at u > 0 is turned",
              "draw the profile in the (distance from the y axis, y) plane, at positive first "
              "coordinates");
        return nullptr;
    }
    return makeRevolve(*profile, angle);
}

}  // namespace kerf
