// 2-D profiles as expressions, and the extrude / revolve solids built on them.
#include "csg/profiles/profile.h"

#include "csg/profiles/lathe.h"
#include "csg/profiles/prism.h"
#include "csg/tape/tape.h"
#include "csg/tree/solids.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace kerf {

namespace {

constexpr double kPi = 3.14159265358979323846;

Bounds2 hull(const Bounds2& a, const Bounds2& b) {
    return {glm::min(a.lo, b.lo), glm::max(a.hi, b.hi)};
}
Bounds2 overlap(const Bounds2& a, const Bounds2& b) {
    return {glm::max(a.lo, b.lo), glm::min(a.hi, b.hi)};
}

/// The box grown by a small fraction of its size, so that a face lying on it (an extrusion's
/// cap, a cylinder's side) is inside the implicit's bound rather than on its edge.
Bounds3 padded(Bounds3 b) {
    const Vec3 pad = 0x1p-20 * (b.hi - b.lo) + 0x1p-40 * glm::max(glm::abs(b.lo), glm::abs(b.hi));
    return {b.lo - pad, b.hi + pad};
}

Profile combine(std::vector<Profile> parts, Op op, Bounds2 bounds) {
    Profile r;
    r.bounds = bounds;
    r.distance = [parts = std::move(parts), op](ExprGraph& g, ExprId u, ExprId v) {
        ExprId d = parts[0].distance(g, u, v);
        for (size_t i = 1; i < parts.size(); ++i) {
            ExprId e = parts[i].distance(g, u, v);
            if (op == Op::Sub) {  // difference: max(d, −e)
                d = g.binary(Op::Max, d, g.unary(Op::Neg, e));
            } else {
                d = g.binary(op, d, e);
            }
        }
        return d;
    };
    return r;
}

/// The path as a plain outline when it has no arcs (lines and Béziers map to lines and
/// Béziers under any affine map, and the prism crosses them in closed form), else null.
std::shared_ptr<const PlainOutline> pathOutline(const PathShape& shape) {
    if (shape.loops.empty()) return nullptr;
    for (const PathLoop& loop : shape.loops)
        for (const PathSegment& s : loop.segments)
            if (s.kind == PathSegment::Kind::Arc) return nullptr;
    auto plain = std::make_shared<PlainOutline>();
    plain->kind = PlainOutline::Kind::Path;
    plain->path = shape;
    return plain;
}

PathSegment lineSegment(Vec2 a, Vec2 b) {
    PathSegment s;
    s.p[0] = a;
    s.p[1] = b;
    return s;
}

/// The plain outline mapped by p ↦ A·p + t, when its image is one: any polygon (or
/// rectangle, as a polygon unless A keeps it axis-aligned), a circle when A is a similarity.
std::shared_ptr<const PlainOutline> mappedOutline(const PlainOutline& in, const double m[6]) {
    const auto map = [m](Vec2 q) {
        return Vec2(m[0] * q.x + m[1] * q.y + m[2], m[3] * q.x + m[4] * q.y + m[5]);
    };
    auto out = std::make_shared<PlainOutline>();
    switch (in.kind) {
        case PlainOutline::Kind::None: return nullptr;
        case PlainOutline::Kind::Circle: {
            // A similarity: both columns of A of one length and orthogonal (exactly, as
            // rotations by multiples of 90°, mirrors and uniform scales give them).
            const double c0 = m[0] * m[0] + m[3] * m[3], c1 = m[1] * m[1] + m[4] * m[4];
            // Within rounding: cos² + sin² of a computed rotation need not be 1 to the bit.
            const double slack = 0x1p-50 * std::max(c0, c1);
            if (!(std::abs(c0 - c1) <= slack && std::abs(m[0] * m[1] + m[3] * m[4]) <= slack))
                return nullptr;
            out->kind = PlainOutline::Kind::Circle;
            out->a = map(in.a);
            out->radius = in.radius * std::sqrt(c0);
            return out;
        }
        case PlainOutline::Kind::Rect:
            if (m[1] == 0.0 && m[3] == 0.0) {
                const Vec2 p = map(in.a), q = map(in.b);
                out->kind = PlainOutline::Kind::Rect;
                out->a = glm::min(p, q);
                out->b = glm::max(p, q);
                return out;
            }
            {
                const Vec2 c[4] = {map(in.a), map(Vec2(in.b.x, in.a.y)), map(in.b),
                                   map(Vec2(in.a.x, in.b.y))};
                out->kind = PlainOutline::Kind::Path;
                out->path.loops.resize(1);
                for (int i = 0; i < 4; ++i)
                    out->path.loops[0].segments.push_back(lineSegment(c[i], c[(i + 1) % 4]));
                return out;
            }
        case PlainOutline::Kind::Path:
            out->kind = PlainOutline::Kind::Path;
            out->path = in.path;
            for (PathLoop& loop : out->path.loops)
                for (PathSegment& seg : loop.segments)
                    for (Vec2& q : seg.p) q = map(q);
            return out;
    }
    return nullptr;
}

}  // namespace

Profile profileCircle(Vec2 center, double radius) {
    Profile p;
    p.bounds = {center - Vec2(radius), center + Vec2(radius)};
    auto plain = std::make_shared<PlainOutline>();
    plain->kind = PlainOutline::Kind::Circle;
    plain->a = center;
    plain->radius = radius;
    p.plain = std::move(plain);
    p.distance = [center, radius](ExprGraph& g, ExprId u, ExprId v) {
        const ExprId du = g.sub(u, g.constant(center.x)), dv = g.sub(v, g.constant(center.y));
        return g.sub(g.unary(Op::Sqrt, g.add(g.unary(Op::Square, du), g.unary(Op::Square, dv))),
                     g.constant(radius));
    };
    return p;
}

Profile profileRect(Vec2 lo, Vec2 hi) {
    Profile p;
    p.bounds = {lo, hi};
    auto plain = std::make_shared<PlainOutline>();
    plain->kind = PlainOutline::Kind::Rect;
    plain->a = lo;
    plain->b = hi;
    p.plain = std::move(plain);
    const Vec2 c = 0.5 * (lo + hi), h = 0.5 * (hi - lo);
    p.distance = [c, h](ExprGraph& g, ExprId u, ExprId v) {
        // q = |p − c| − h. The distance is max(qx, qy) except beyond a corner (qx, qy > 0), where
        // it is |q|; there |q| ≤ qx + qy, and elsewhere qx + qy ≤ max(qx, qy), so
        // max(max(qx, qy), min(|q|, qx + qy)) is exact everywhere. The textbook |max(q, 0)| is
        // avoided: its sqrt is 0 over the whole inside, where its slope is unbounded and root
        // isolation could never prove an interval free of roots.
        const ExprId qx = g.sub(g.unary(Op::Abs, g.sub(u, g.constant(c.x))), g.constant(h.x));
        const ExprId qy = g.sub(g.unary(Op::Abs, g.sub(v, g.constant(c.y))), g.constant(h.y));
        const ExprId corner =
            g.unary(Op::Sqrt, g.add(g.unary(Op::Square, qx), g.unary(Op::Square, qy)));
        return g.binary(Op::Max, g.binary(Op::Max, qx, qy),
                        g.binary(Op::Min, corner, g.add(qx, qy)));
    };
    return p;
}

Profile profilePath(PathShape shape) {
    Profile p;
    p.bounds = pathBounds(shape);
    p.plain = pathOutline(shape);
    auto field = pathField(std::move(shape));
    p.distance = [field](ExprGraph& g, ExprId u, ExprId v) {
        return g.field(u, v, g.constant(0.0), field);
    };
    return p;
}

Profile profilePolygon(const std::vector<Vec2>& outline,
                       const std::vector<std::vector<Vec2>>& holes) {
    PathShape shape;
    const auto addLoop = [&](const std::vector<Vec2>& points) {
        PathLoop loop;
        for (size_t i = 0; i < points.size(); ++i) {
            PathSegment s;
            s.p[0] = points[i];
            s.p[1] = points[(i + 1) % points.size()];
            loop.segments.push_back(s);
        }
        shape.loops.push_back(std::move(loop));
    };
    addLoop(outline);
    for (const auto& h : holes) addLoop(h);
    return profilePath(std::move(shape));
}

Profile profileUnion(std::vector<Profile> parts) {
    Bounds2 b = parts[0].bounds;
    for (const Profile& p : parts) b = hull(b, p.bounds);
    return combine(std::move(parts), Op::Min, b);
}

Profile profileIntersection(std::vector<Profile> parts) {
    Bounds2 b = parts[0].bounds;
    for (const Profile& p : parts) b = overlap(b, p.bounds);
    b.hi = glm::max(b.hi, b.lo);  // disjoint: an empty box, kept well-formed
    return combine(std::move(parts), Op::Max, b);
}

Profile profileDifference(std::vector<Profile> parts) {
    const Bounds2 b = parts[0].bounds;
    return combine(std::move(parts), Op::Sub, b);
}

Profile profileOffset(Profile p, double r) {
    Profile out;
    out.bounds = {p.bounds.lo - Vec2(r), p.bounds.hi + Vec2(r)};
    if (r < 0.0) out.bounds = p.bounds;  // shrinking: the old box still holds it
    out.distance = [inner = std::move(p.distance), r](ExprGraph& g, ExprId u, ExprId v) {
        return g.sub(inner(g, u, v), g.constant(r));
    };
    return out;
}

Profile profileTransform(Profile p, const double m[6]) {
    const double a = m[0], b = m[1], tx = m[2], c = m[3], d = m[4], ty = m[5];
    const double det = a * d - b * c;
    // A⁻¹ = [[d, −b], [−c, a]] / det.
    const double ia = d / det, ib = -b / det, ic = -c / det, id = a / det;
    // σ_min of a 2×2 matrix: the smaller root of σ² from its trace of AᵀA and |det|.
    const double f = a * a + b * b + c * c + d * d;
    const double disc = std::sqrt(std::max(0.0, f * f - 4.0 * det * det));
    const double smax = std::sqrt(0.5 * (f + disc));
    const double smin = std::fabs(det) / smax;  // σ_min·σ_max = |det|
    Profile out;
    Vec2 lo(kInf), hi(-kInf);
    for (int i = 0; i < 4; ++i) {
        const Vec2 q((i & 1) ? p.bounds.hi.x : p.bounds.lo.x,
                     (i & 2) ? p.bounds.hi.y : p.bounds.lo.y);
        const Vec2 r(a * q.x + b * q.y + tx, c * q.x + d * q.y + ty);
        lo = glm::min(lo, r);
        hi = glm::max(hi, r);
    }
    // The corners' images are rounded: grow the box a little so it still holds the region.
    const Vec2 pad = 0x1p-40 * (hi - lo) + 0x1p-50 * glm::max(glm::abs(lo), glm::abs(hi));
    out.bounds = {lo - pad, hi + pad};
    out.distance = [inner = std::move(p.distance), ia, ib, ic, id, tx, ty, smin](
                       ExprGraph& g, ExprId u, ExprId v) {
        const ExprId du = g.sub(u, g.constant(tx)), dv = g.sub(v, g.constant(ty));
        const ExprId pu = g.add(g.mul(g.constant(ia), du), g.mul(g.constant(ib), dv));
        const ExprId pv = g.add(g.mul(g.constant(ic), du), g.mul(g.constant(id), dv));
        const ExprId e = inner(g, pu, pv);
        return smin == 1.0 ? e : g.mul(g.constant(smin), e);
    };
    if (p.plain) out.plain = mappedOutline(*p.plain, m);
    return out;
}

namespace {

/// A straight extrusion of a plain outline as a closed-form solid, or null.
NodePtr plainExtrusion(const PlainOutline& plain, double y0, double y1,
                       const NodePtr& implicitForm) {
    switch (plain.kind) {
        case PlainOutline::Kind::Circle:
            return makeCylinder(Vec3(plain.a.x, y0, plain.a.y), Vec3(plain.a.x, y1, plain.a.y),
                                plain.radius);
        case PlainOutline::Kind::Rect:
            return makeBox(Vec3(plain.a.x, y0, plain.a.y), Vec3(plain.b.x, y1, plain.b.y));
        case PlainOutline::Kind::Path: return makePrism(plain.path, y0, y1, implicitForm);
        case PlainOutline::Kind::None: break;
    }
    return nullptr;
}

/// A full turn of a plain outline as a closed-form solid, or null: a circle clear of the axis
/// is a torus, a rectangle or a path of lines and Béziers a lathe. Arcs, and Béziers reaching
/// across the axis, stay implicit.
NodePtr plainRevolution(const PlainOutline& plain, const NodePtr& implicitForm) {
    switch (plain.kind) {
        case PlainOutline::Kind::Circle:
            if (!(plain.a.x > plain.radius)) return nullptr;
            return makeTransform(makeTorus(plain.a.x, plain.radius),
                                 Affine::translate(Vec3(0.0, plain.a.y, 0.0)));
        case PlainOutline::Kind::Rect: {
            const Vec2 c[4] = {plain.a, Vec2(plain.b.x, plain.a.y), plain.b,
                               Vec2(plain.a.x, plain.b.y)};
            std::vector<LatheSegment> sides;
            for (int k = 0; k < 4; ++k) sides.push_back({{c[k], c[(k + 1) % 4]}, 1});
            return makeLathe(sides, implicitForm);
        }
        case PlainOutline::Kind::Path: {
            std::vector<LatheSegment> segments;
            for (const PathLoop& loop : plain.path.loops)
                for (const PathSegment& s : loop.segments) {
                    const int degree = s.kind == PathSegment::Kind::Line        ? 1
                                       : s.kind == PathSegment::Kind::Quadratic ? 2
                                       : s.kind == PathSegment::Kind::Cubic     ? 3
                                                                                : 0;
                    if (degree == 0) return nullptr;  // an arc
                    // A Bézier reaching r < 0 is not clipped at the axis: implicit.
                    for (int i = 0; degree > 1 && i <= degree; ++i)
                        if (s.p[i].x < 0.0) return nullptr;
                    segments.push_back({s.p, degree});
                }
            return makeLathe(segments, implicitForm);
        }
        case PlainOutline::Kind::None: break;
    }
    return nullptr;
}

}  // namespace

NodePtr makeExtrude(const Profile& profile, const ExtrudeOptions& o) {
    ExprGraph g;
    const double y0 = o.center ? -0.5 * o.height : 0.0;
    const ExprId x = g.x(), y = g.y(), z = g.z();
    // t = (y − y0)/h, 0 at the bottom, 1 at the top.
    const ExprId t = g.mul(g.sub(y, g.constant(y0)), g.constant(1.0 / o.height));
    ExprId u = x, v = z;
    if (o.twist != 0.0) {
        // The profile at t is turned about +y by θ = twist·t; undo it: (u, v) = R(−θ)(x, z).
        const ExprId theta = g.mul(t, g.constant(o.twist * kPi / 180.0));
        const ExprId c = g.unary(Op::Cos, theta), s = g.unary(Op::Sin, theta);
        u = g.sub(g.mul(x, c), g.mul(z, s));
        v = g.add(g.mul(x, s), g.mul(z, c));
    }
    ExprId d;
    if (o.scale != Vec2(1.0)) {
        // The profile at t is scaled about the axis by kx = 1 + (sx − 1)t along u and ky along
        // v: d2(u/kx, v/ky) has the scaled profile's sign, and min(kx, ky)·d2(u/kx, v/ky) is
        // never more than its in-plane distance in magnitude (and is it when kx = ky).
        const ExprId kx = g.add(g.constant(1.0), g.mul(t, g.constant(o.scale.x - 1.0)));
        const ExprId ky = o.scale.y == o.scale.x
                              ? kx
                              : g.add(g.constant(1.0), g.mul(t, g.constant(o.scale.y - 1.0)));
        const ExprId one = g.constant(1.0);
        const ExprId su = g.mul(u, g.binary(Op::Div, one, kx)),
                     sv = g.mul(v, g.binary(Op::Div, one, ky));
        const ExprId k = kx == ky ? kx : g.binary(Op::Min, kx, ky);
        d = g.mul(k, profile.distance(g, su, sv));
    } else {
        d = profile.distance(g, u, v);
    }
    const double yc = y0 + 0.5 * o.height;
    const ExprId slab =
        g.sub(g.unary(Op::Abs, g.sub(y, g.constant(yc))), g.constant(0.5 * o.height));
    const ExprId f = g.binary(Op::Max, d, slab);

    Bounds2 b = profile.bounds;
    if (o.scale != Vec2(1.0)) b = hull(b, {b.lo * o.scale, b.hi * o.scale});
    if (o.twist != 0.0) {
        const double r = glm::length(glm::max(glm::abs(b.lo), glm::abs(b.hi)));
        b = {Vec2(-r), Vec2(r)};
    }
    const Bounds3 bound{Vec3(b.lo.x, y0, b.lo.y), Vec3(b.hi.x, y0 + o.height, b.hi.y)};
    NodePtr implicitForm = makeImplicit(Tape::compile(g, f), padded(bound));
    // A straight extrusion of a circle, a rectangle or a polygon has closed-form spans.
    if (o.twist == 0.0 && o.scale == Vec2(1.0) && profile.plain)
        if (NodePtr exact = plainExtrusion(*profile.plain, y0, y0 + o.height, implicitForm))
            return exact;
    return implicitForm;
}

NodePtr makeRevolve(const Profile& profile, double degrees) {
    ExprGraph g;
    const ExprId x = g.x(), y = g.y(), z = g.z();
    const ExprId r = g.unary(Op::Sqrt, g.add(g.unary(Op::Square, x), g.unary(Op::Square, z)));
    ExprId f = profile.distance(g, r, y);
    if (degrees < 360.0) {
        // The wedge from +x toward +z: z ≥ 0, and the side of the ray at `degrees` facing back.
        const double a = degrees * kPi / 180.0;
        const double ca = degrees == 180.0                      ? -1.0
                          : degrees == 90.0 || degrees == 270.0 ? 0.0
                                                                : std::cos(a);
        const double sa = degrees == 180.0   ? 0.0
                          : degrees == 90.0  ? 1.0
                          : degrees == 270.0 ? -1.0
                                             : std::sin(a);
        const ExprId first = g.unary(Op::Neg, z);
        const ExprId second = g.sub(g.mul(g.constant(ca), z), g.mul(g.constant(sa), x));
        const ExprId wedge = g.binary(degrees <= 180.0 ? Op::Max : Op::Min, first, second);
        f = g.binary(Op::Max, f, wedge);
    }
    const double reach = std::max(profile.bounds.hi.x, 0.0);  // only u ≥ 0 is turned
    const Bounds3 bound{Vec3(-reach, profile.bounds.lo.y, -reach),
                        Vec3(reach, profile.bounds.hi.y, reach)};
    NodePtr implicitForm = makeImplicit(Tape::compile(g, f), padded(bound));
    if (degrees == 360.0 && profile.plain)
        if (NodePtr exact = plainRevolution(*profile.plain, implicitForm)) return exact;
    return implicitForm;
}

}  // namespace kerf
