// The prism: closed-form spans of an outline of lines and Béziers extruded along y
// (csg/profiles/prism.h).
#include "csg/profiles/prism.h"

#include "csg/profiles/implicit_backed.h"

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

namespace kerf {

namespace {

/// A segment as a cubic Bézier's control points (a line: its ends, flagged).
struct BezierPiece {
    std::array<Vec2, 4> p;
    bool line = true;
};

/// Where the ray's shadow crosses the outline.
struct Crossing {
    double t;
    Vec2 normal;  ///< the outline's normal there, either side (unit)
};

/// The 1-D cubic Bézier with coefficients g at s (de Casteljau).
double bezier1(const std::array<double, 4>& g, double s) {
    const double a = g[0] + s * (g[1] - g[0]), b = g[1] + s * (g[2] - g[1]),
                 c = g[2] + s * (g[3] - g[2]);
    const double d = a + s * (b - a), e = b + s * (c - b);
    return d + s * (e - d);
}

Vec2 bezier2(const std::array<Vec2, 4>& p, double s) {
    const double u = 1.0 - s;
    return u * u * u * p[0] + 3.0 * u * u * s * p[1] + 3.0 * u * s * s * p[2] + s * s * s * p[3];
}

Vec2 tangent(const std::array<Vec2, 4>& p, double s) {
    const double u = 1.0 - s;
    const Vec2 d = u * u * (p[1] - p[0]) + 2.0 * u * s * (p[2] - p[1]) + s * s * (p[3] - p[2]);
    return d != Vec2(0.0) ? d : p[3] - p[0];
}

/// Whether the segment from a to b meets the closed box grown by `slack` (clipped against its
/// slabs).
bool segmentMeetsBox(Vec2 a, Vec2 b, Bounds2 box, double slack) {
    box = {box.lo - slack, box.hi + slack};
    double lo = 0.0, hi = 1.0;
    for (int axis = 0; axis < 2; ++axis) {
        const double e = b[axis] - a[axis];
        if (e == 0.0) {
            if (a[axis] < box.lo[axis] || a[axis] > box.hi[axis]) return false;
            continue;
        }
        double t0 = (box.lo[axis] - a[axis]) / e, t1 = (box.hi[axis] - a[axis]) / e;
        if (t0 > t1) std::swap(t0, t1);
        lo = std::max(lo, t0);
        hi = std::min(hi, t1);
        if (lo > hi) return false;
    }
    return true;
}

/// The root in [lo, hi] of the cubic Bézier g, monotone there with g(lo) = glo and g(hi) = ghi
/// of two classes (≤ 0, > 0); g' = 3·(qa·s² + qb·s + qc). Newton's steps from the chord's
/// root, kept in the bracket (bisecting when a step leaves it), end in a few steps at a root
/// to rounding, where bisection alone takes fifty.
double monotoneRoot(const std::array<double, 4>& g, double qa, double qb, double qc, double lo,
                    double hi, double glo, double ghi) {
    const bool clo = glo <= 0.0;
    double s = lo + glo / (glo - ghi) * (hi - lo);
    for (int it = 0; it < 100; ++it) {
        if (!(s > lo && s < hi)) s = 0.5 * (lo + hi);
        const double gs = bezier1(g, s);
        ((gs <= 0.0) == clo ? lo : hi) = s;
        const double slope = 3.0 * (s * (qa * s + qb) + qc);
        const double next = slope != 0.0 ? s - gs / slope : 0.5 * (lo + hi);
        if (gs == 0.0 || std::abs(next - s) <= 0x1p-52 * std::max(1.0, std::abs(s)) ||
            hi - lo <= 0x1p-52)
            return std::clamp(next, lo, hi);
        s = next;
    }
    return hi;
}

class Prism final : public ImplicitBackedPrimitive<Prism> {
public:
    Prism(const PathShape& shape, double y0, double y1, NodePtr implicitForm)
        : ImplicitBackedPrimitive(std::move(implicitForm)), mY0(y0), mY1(y1) {
        for (const PathLoop& loop : shape.loops) {
            std::vector<BezierPiece> pieces;
            for (const PathSegment& s : loop.segments) {
                BezierPiece piece;
                switch (s.kind) {
                    case PathSegment::Kind::Line: piece.p = {s.p[0], s.p[0], s.p[1], s.p[1]}; break;
                    case PathSegment::Kind::Quadratic:  // raised to a cubic, as
                                                        // csg/profiles/profile_field.cpp does
                        piece.p = {s.p[0], s.p[0] + (2.0 / 3.0) * (s.p[1] - s.p[0]),
                                   s.p[2] + (2.0 / 3.0) * (s.p[1] - s.p[2]), s.p[2]};
                        piece.line = false;
                        break;
                    case PathSegment::Kind::Cubic:
                        piece.p = {s.p[0], s.p[1], s.p[2], s.p[3]};
                        piece.line = false;
                        break;
                    case PathSegment::Kind::Arc: break;  // makeExtrude passes no arcs
                }
                pieces.push_back(piece);
            }
            if (pieces.empty()) continue;
            Bounds2 box{Vec2(kInf), Vec2(-kInf)};
            for (const BezierPiece& piece : pieces)
                for (const Vec2& c : piece.p) box = {glm::min(box.lo, c), glm::max(box.hi, c)};
            // Grown by a hair, so the cull below is conservative under rounding.
            const Vec2 pad = 0x1p-40 * (box.hi - box.lo) +
                             0x1p-50 * glm::max(glm::abs(box.lo), glm::abs(box.hi));
            mLoopBoxes.push_back({box.lo - pad, box.hi + pad});
            mLoops.push_back(std::move(pieces));
        }
    }

private:
    friend class ClosedFormPrimitive<Prism>;

    /// The crossings of the line o + t·d with one segment. g(s) = d × (B(s) − o), the side of
    /// the segment's point, is a cubic with coefficients d × (pᵢ − o); its ends are the sides
    /// of the segment's end points, computed as the neighbours compute them. The line crosses
    /// where the class g ≤ 0 changes: on each piece of [0, 1] where g is monotone (split at
    /// the roots of g'), at most once, found by bisection; a touch changes nothing.
    static void crossSegment(const BezierPiece& piece, Vec2 o, Vec2 d, double dd,
                             std::vector<Crossing>& out) {
        std::array<double, 4> g;
        for (int i = 0; i < 4; ++i) g[i] = d.x * (piece.p[i].y - o.y) - d.y * (piece.p[i].x - o.x);
        const auto add = [&](Vec2 q, Vec2 along) {
            out.push_back({glm::dot(q - o, d) / dd, Vec2(-along.y, along.x) / glm::length(along)});
        };
        if (piece.line) {
            if ((g[0] <= 0.0) == (g[3] <= 0.0)) return;
            // At an end on the line, the end itself: both segments there give one t.
            const Vec2 a = piece.p[0], b = piece.p[3];
            add(g[3] == 0.0 ? b : g[0] == 0.0 ? a : a + g[0] / (g[0] - g[3]) * (b - a), b - a);
            return;
        }
        // All control sides in one class: the curve (in their hull) stays in it.
        const bool c0 = g[0] <= 0.0;
        if ((g[1] <= 0.0) == c0 && (g[2] <= 0.0) == c0 && (g[3] <= 0.0) == c0) return;
        // Split where g' = 3·(quadratic Bézier of the differences) vanishes.
        const double a = g[1] - g[0], b = g[2] - g[1], c = g[3] - g[2];
        const double qa = a - 2.0 * b + c, qb = 2.0 * (b - a), qc = a;
        double cuts[4] = {0.0, 0.0, 0.0, 1.0};
        int n = 1;
        const auto keep = [&](double s) {
            if (s > 0.0 && s < 1.0) cuts[n++] = s;
        };
        if (qa == 0.0) {
            if (qb != 0.0) keep(-qc / qb);
        } else {
            const double disc = qb * qb - 4.0 * qa * qc;
            if (disc >= 0.0) {
                const double r = std::sqrt(disc);
                const double q = -0.5 * (qb + (qb >= 0.0 ? r : -r));
                double s1 = q / qa, s2 = q != 0.0 ? qc / q : s1;
                if (s1 > s2) std::swap(s1, s2);
                keep(s1);
                if (s2 != s1) keep(s2);
            }
        }
        cuts[n++] = 1.0;
        for (int k = 0; k + 1 < n; ++k) {
            const double lo0 = cuts[k], hi0 = cuts[k + 1];
            const double glo = lo0 == 0.0 ? g[0] : bezier1(g, lo0),
                         ghi = hi0 == 1.0 ? g[3] : bezier1(g, hi0);
            const bool clo = glo <= 0.0;
            if (clo == (ghi <= 0.0)) continue;
            if (hi0 == 1.0 && g[3] == 0.0) {  // at the end point: as the next segment finds it
                add(piece.p[3], tangent(piece.p, 1.0));
                continue;
            }
            if (lo0 == 0.0 && g[0] == 0.0) {
                add(piece.p[0], tangent(piece.p, 0.0));
                continue;
            }
            const double s = monotoneRoot(g, qa, qb, qc, lo0, hi0, glo, ghi);
            add(bezier2(piece.p, s), tangent(piece.p, s));
        }
    }

    /// Even-odd inside test of a point of the plane: the crossings of the line through it
    /// along +x, on its positive side.
    bool inside(Vec2 p) const {
        std::vector<Crossing>& hits = mScratch;
        hits.clear();
        for (const auto& loop : mLoops)
            for (const BezierPiece& piece : loop) crossSegment(piece, p, Vec2(1.0, 0.0), 1.0, hits);
        bool odd = false;
        for (const Crossing& c : hits) odd ^= c.t > 0.0;
        return odd;
    }

    void closedSpans(const Ray& ray, SpanList& out) const {
        // The slab y0 ≤ y ≤ y1 (closed, as a box's).
        double ta = -kInf, tb = kInf;
        if (ray.dir.y == 0.0) {
            if (ray.origin.y < mY0 || ray.origin.y > mY1) return;
        } else {
            const double t0 = (mY0 - ray.origin.y) / ray.dir.y,
                         t1 = (mY1 - ray.origin.y) / ray.dir.y;
            ta = std::min(t0, t1);
            tb = std::max(t0, t1);
        }
        const Vec3 capIn(0.0, ray.dir.y > 0.0 ? -1.0 : 1.0, 0.0);
        const Vec3 capOut = -capIn;
        const Vec2 o(ray.origin.x, ray.origin.z), d(ray.dir.x, ray.dir.z);
        if (d.x == 0.0 && d.y == 0.0) {  // along y: in or out of the outline throughout
            if (inside(o)) out.push_back({boundary(ta, capIn), boundary(tb, capOut)});
            return;
        }
        std::vector<Crossing>& hits = mScratch;
        hits.clear();
        const double dd = glm::dot(d, d);
        // A loop whose box the ray's shadow within the slab misses neither holds a point of it
        // nor crosses it there: its crossings (an even number) change nothing in the slab.
        const Vec2 from = o + ta * d, to = o + tb * d;
        const bool finite = std::isfinite(ta) && std::isfinite(tb);
        // The ends' rounding: a few ulps of the largest coordinate that went into them.
        const double slack = 0x1p-44 * (std::max(std::abs(o.x), std::abs(o.y)) +
                                        std::max(std::abs(d.x), std::abs(d.y)) *
                                            std::max(std::abs(ta), std::abs(tb)));
        for (size_t i = 0; i < mLoops.size(); ++i)
            if (!finite || segmentMeetsBox(from, to, mLoopBoxes[i], slack))
                for (const BezierPiece& piece : mLoops[i]) crossSegment(piece, o, d, dd, hits);
        std::sort(hits.begin(), hits.end(),
                  [](const Crossing& x, const Crossing& y) { return x.t < y.t; });
        // The line starts and ends outside: crossings pair up into inside intervals.
        const auto side = [&](const Crossing& c, bool entering) {
            const Vec2 n = (glm::dot(c.normal, d) < 0.0) == entering ? c.normal : -c.normal;
            return Vec3(n.x, 0.0, n.y);
        };
        for (size_t k = 0; k + 1 < hits.size(); k += 2) {
            const double tin = std::max(hits[k].t, ta), tout = std::min(hits[k + 1].t, tb);
            if (!(tin <= tout)) continue;
            const Boundary leave = hits[k + 1].t <= tb ? boundary(tout, side(hits[k + 1], false))
                                                       : boundary(tout, capOut);
            // A line through a vertex where the outline touches it from outside (a reflex
            // vertex met from inside) leaves and enters at one t: one span, no gap.
            if (!out.empty() && out.back().out.t == tin) {
                out.back().out = leave;
                continue;
            }
            out.push_back(
                {hits[k].t >= ta ? boundary(tin, side(hits[k], true)) : boundary(tin, capIn),
                 leave});
        }
    }

    std::vector<std::vector<BezierPiece>> mLoops;
    std::vector<Bounds2> mLoopBoxes;  ///< each loop's control points' box
    double mY0, mY1;
    static thread_local std::vector<Crossing> mScratch;
};

thread_local std::vector<Crossing> Prism::mScratch;

}  // namespace

NodePtr makePrism(const PathShape& shape, double y0, double y1, NodePtr implicitForm) {
    return std::make_shared<Prism>(shape, y0, y1, std::move(implicitForm));
}

}  // namespace kerf
