// The lathe: closed-form spans of a polygon in the (r, y) plane turned about the y axis
// (csg/profiles/lathe.h).
#include "csg/profiles/lathe.h"

#include "csg/profiles/bernstein.h"
#include "csg/profiles/implicit_backed.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace kerf {

namespace {

/// One edge of the outline in (r, y), both ends at r ≥ 0.
struct LatheEdge {
    Vec2 a, b;
    Vec2 normal;  ///< in (r, y), unit, either side: fixed per edge, so made once
};

/// Where the ray crosses the surface of one segment.
struct LatheCrossing {
    double t;
    Vec3 normal;  ///< unit, either side
};

/// A Bézier of the outline: control points p[0 … degree] at r ≥ 0.
struct LatheCurve {
    std::array<Vec2, 4> p;
    int degree;
    Vec2 lo, hi;  ///< the control points' box (holds the curve)
};

/// The lines with the part at r < 0 put on the axis (split where a line crosses it): a point
/// at r > 0 is inside the clamped loops exactly when it is inside the given ones (the even-odd
/// count along +r never reaches r < 0). Lines on the axis turn into nothing.
std::vector<LatheEdge> clampedEdges(const std::vector<LatheSegment>& segments) {
    std::vector<LatheEdge> out;
    const auto add = [&](Vec2 a, Vec2 b) {
        a.x = std::max(a.x, 0.0);
        b.x = std::max(b.x, 0.0);
        if (a != b && !(a.x == 0.0 && b.x == 0.0))
            out.push_back({a, b, Vec2(b.y - a.y, a.x - b.x) / glm::length(b - a)});
    };
    for (const LatheSegment& segment : segments) {
        if (segment.degree != 1) continue;
        const Vec2 p = segment.p[0], q = segment.p[1];
        if ((p.x < 0.0 && q.x > 0.0) || (p.x > 0.0 && q.x < 0.0)) {
            const Vec2 m(0.0, p.y + p.x / (p.x - q.x) * (q.y - p.y));
            add(p, m);
            add(m, q);
        } else {
            add(p, q);
        }
    }
    return out;
}

/// A Bézier's point and tangent at s (de Casteljau; the chord where the tangent vanishes).
Vec2 curvePoint(const LatheCurve& c, double s, Vec2* tangent) {
    std::array<Vec2, 4> b = c.p;
    for (int r = 1; r <= c.degree; ++r) {
        if (r == c.degree && tangent) *tangent = b[1] - b[0];
        for (int i = 0; i + r <= c.degree; ++i) b[i] += s * (b[i + 1] - b[i]);
    }
    if (tangent && *tangent == Vec2(0.0)) *tangent = c.p[c.degree] - c.p[0];
    return b[0];
}

/// How far r lies outside [lo, hi] (0 inside).
double outside(double r, double lo, double hi) { return r < lo ? lo - r : r > hi ? r - hi : 0.0; }

/// Binomial coefficients up to 6.
double choose(int n, int k) {
    static constexpr double row[7][7] = {{1},
                                         {1, 1},
                                         {1, 2, 1},
                                         {1, 3, 3, 1},
                                         {1, 4, 6, 4, 1},
                                         {1, 5, 10, 10, 5, 1},
                                         {1, 6, 15, 20, 15, 6, 1}};
    return row[n][k];
}

/// The roots of a·x² + b·x + c (a ≠ 0 or b ≠ 0), without cancellation; false when none.
bool latheQuadraticRoots(double a, double b, double c, double& x1, double& x2) {
    if (a == 0.0) {
        if (b == 0.0) return false;
        x1 = x2 = -c / b;
        return true;
    }
    const double disc = b * b - 4.0 * a * c;
    if (disc < 0.0) return false;
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    x1 = q / a;
    x2 = q != 0.0 ? c / q : x1;
    return true;
}

class Lathe final : public ImplicitBackedPrimitive<Lathe> {
public:
    Lathe(const std::vector<LatheSegment>& segments, NodePtr implicitForm)
        : ImplicitBackedPrimitive(std::move(implicitForm)), mEdges(clampedEdges(segments)) {
        for (const LatheEdge& e : mEdges) mReach = std::max({mReach, e.a.x, e.b.x});
        for (const LatheSegment& segment : segments) {
            if (segment.degree == 1) continue;
            Vec2 lo = segment.p[0], hi = segment.p[0];
            for (int i = 1; i <= segment.degree; ++i) {
                lo = glm::min(lo, segment.p[i]);
                hi = glm::max(hi, segment.p[i]);
            }
            mCurves.push_back({segment.p, segment.degree, lo, hi});
            for (int i = 0; i <= segment.degree; ++i) mReach = std::max(mReach, segment.p[i].x);
        }
    }

private:
    friend class ClosedFormPrimitive<Lathe>;

    /// The surface normal at the ray's point p of a segment with profile normal n (in (r, y)).
    static Vec3 normalAt(const Vec3& p, Vec2 n) {
        const double radial = std::sqrt(p.x * p.x + p.z * p.z);
        if (radial > 0.0) return Vec3(n.x * p.x / radial, n.y, n.x * p.z / radial);
        return Vec3(0.0, n.y >= 0.0 ? 1.0 : -1.0, 0.0);  // on the axis: a cone's apex or a disc
    }

    /// F(v) of crossSloped: the class of a vertex, computed from its coordinates alone.
    static double levelAt(Vec2 v, Vec2 o, Vec2 d, double oy, double dy) {
        const Vec2 w = dy * o + (v.y - oy) * d;
        return dy * v.x * dy * v.x - glm::dot(w, w);
    }

    /// Whether a ray with dy ≠ 0 stays clear of a Bézier's hull, beyond it or within it at
    /// every height the hull spans, with both ends' classes saying the same: then F keeps one
    /// class along the curve and it has no crossing. The ray's scaled squared radius
    /// G(y) = |dy·o + (y − oy)·d|² is convex in y: its least value on the hull's heights is at
    /// the clamped vertex, its greatest at an end. The margins cover rounding.
    static bool curveClear(const LatheCurve& c, Vec2 o, Vec2 d, double oy, double dy) {
        const double fa = levelAt(c.p[0], o, d, oy, dy), fb = levelAt(c.p[c.degree], o, d, oy, dy);
        if ((fa > 0.0) != (fb > 0.0)) return false;
        const auto g = [&](double y) {
            const Vec2 w = dy * o + (y - oy) * d;
            return glm::dot(w, w);
        };
        const double dd = glm::dot(d, d);
        const double r2 = dy * dy;
        if (fa > 0.0)  // beyond the ray's radius at both ends: clear if the ray stays inside
            return std::max(g(c.lo.y), g(c.hi.y)) < r2 * c.lo.x * c.lo.x * (1.0 - 0x1p-40);
        const double vertex =
            dd > 0.0 ? std::clamp(oy - dy * glm::dot(o, d) / dd, c.lo.y, c.hi.y) : c.lo.y;
        return g(vertex) > r2 * c.hi.x * c.hi.x * (1.0 + 0x1p-40);
    }

    /// The crossings with the Béziers of a ray with dy ≠ 0: F along a Bézier of degree n is
    /// dy²·r(s)² − |w(s)|² with w = dy·o + (y − oy)·d, a polynomial of degree 2n whose
    /// Bernstein coefficients are the products' (its end values the vertices' own levels).
    void crossCurvesSloped(const Ray& ray, std::vector<LatheCrossing>& hits) const {
        const Vec2 o(ray.origin.x, ray.origin.z), d(ray.dir.x, ray.dir.z);
        const double oy = ray.origin.y, dy = ray.dir.y;
        std::vector<double>& roots = mRoots;
        for (const LatheCurve& c : mCurves) {
            if (curveClear(c, o, d, oy, dy)) continue;
            const int n = c.degree;
            std::array<Vec2, 4> w;
            for (int i = 0; i <= n; ++i) w[i] = dy * o + (c.p[i].y - oy) * d;
            BernsteinCoefficients f{};
            for (int i = 0; i <= n; ++i)
                for (int j = 0; j <= n; ++j)
                    f[i + j] += choose(n, i) * choose(n, j) / choose(2 * n, i + j) *
                                (dy * c.p[i].x * dy * c.p[j].x - glm::dot(w[i], w[j]));
            f[0] = levelAt(c.p[0], o, d, oy, dy);
            f[2 * n] = levelAt(c.p[n], o, d, oy, dy);
            roots.clear();
            bernsteinClassChanges(f, 2 * n, roots);
            for (const double s : roots) {
                Vec2 tangent;
                const Vec2 q = s == 0.0 ? c.p[0] : s == 1.0 ? c.p[n] : curvePoint(c, s, &tangent);
                if (s == 0.0 || s == 1.0) curvePoint(c, s, &tangent);
                const double t = (q.y - oy) / dy;
                hits.push_back({t, normalAt(ray.origin + t * ray.dir,
                                            Vec2(tangent.y, -tangent.x) / glm::length(tangent))});
            }
        }
    }

    /// The root in [lo, hi] of F(s) = qa·s² + qb·s + f0, where F is monotone and changes class
    /// (F > 0) from flo to fhi: the quadratic's root nearest that piece, kept in it.
    static double rootOnPiece(double qa, double qb, double f0, double lo, double hi, double flo,
                              double fhi) {
        double s1, s2;
        if (!latheQuadraticRoots(qa, qb, f0, s1, s2))  // lost to rounding: the chord's root
            return lo + flo / (flo - fhi) * (hi - lo);
        return std::clamp(outside(s1, lo, hi) <= outside(s2, lo, hi) ? s1 : s2, lo, hi);
    }

    /// The ray's t at the height of the edge's parameter s (at an end, the end's own height,
    /// so both edges there give one t).
    static double heightT(const LatheEdge& seg, double s, double oy, double dy) {
        const double y = s == 0.0   ? seg.a.y
                         : s == 1.0 ? seg.b.y
                                    : seg.a.y + s * (seg.b.y - seg.a.y);
        return (y - oy) / dy;
    }

    /// The ray's crossings with the cone of a sloped edge, r = m + k·dy·t:
    /// |o + t·d|² = (m + k·dy·t)², with the edge parameter s of each; false when none.
    static bool coneRoots(const LatheEdge& seg, Vec2 o, Vec2 d, double oy, double dy, double t[2],
                          double s[2]) {
        const Vec2 e = seg.b - seg.a;
        const double k = e.x / e.y, m = seg.a.x + k * (oy - seg.a.y);
        if (!latheQuadraticRoots(glm::dot(d, d) - k * k * dy * dy,
                                 2.0 * (glm::dot(o, d) - m * k * dy), glm::dot(o, o) - m * m, t[0],
                                 t[1]))
            return false;
        for (int i = 0; i < 2; ++i) s[i] = (oy + t[i] * dy - seg.a.y) / e.y;
        return true;
    }

    /// A ray with dy ≠ 0 meets height y once, at radius |o + (y − oy)/dy · d| (o, d: its
    /// (x, z) parts). F(r, y) = (dy·r)² − |dy·o + (y − oy)·d|² is positive where a point of the
    /// plane lies beyond the ray's radius at its height; each vertex's class F > 0 is computed
    /// from its own coordinates alone, so the two edges at a vertex agree and the crossings of
    /// a loop come in pairs. Along an edge F is a quadratic in the edge's parameter s: split at
    /// its extremum, each monotone piece crosses once where the classes of its ends differ
    /// (an edge the ray's curve cuts twice gives both crossings, one it touches none).
    void crossSloped(const Ray& ray, std::vector<LatheCrossing>& hits) const {
        const Vec2 o(ray.origin.x, ray.origin.z), d(ray.dir.x, ray.dir.z);
        const double oy = ray.origin.y, dy = ray.dir.y, dd = glm::dot(d, d);
        const auto level = [&](Vec2 v) { return levelAt(v, o, d, oy, dy); };
        Vec2 last(-1.0);  // the previous edge's end, whose level carries over (r ≥ 0 at ends)
        double lastLevel = 0.0;
        for (const LatheEdge& seg : mEdges) {
            const double fa = seg.a == last ? lastLevel : level(seg.a), fb = level(seg.b);
            last = seg.b;
            lastLevel = fb;
            const Vec2 e = seg.b - seg.a;
            const double qa = dy * dy * e.x * e.x - e.y * e.y * dd;
            // Ends of one class: the curve crosses only if F's extremum is of the other.
            const bool above = fa > 0.0;
            if (above == (fb > 0.0) && !(above ? qa > 0.0 : qa < 0.0)) continue;
            const Vec2 wa = dy * o + (seg.a.y - oy) * d;
            const double qb = 2.0 * (dy * dy * seg.a.x * e.x - e.y * glm::dot(wa, d));
            double cut[3] = {0.0, 1.0, 1.0}, value[3] = {fa, fb, fb};
            int pieces = 1;
            const double se = qa != 0.0 ? -qb / (2.0 * qa) : -1.0;
            if (se > 0.0 && se < 1.0) {
                cut[1] = se;
                value[1] = fa + se * (qb + qa * se);
                pieces = 2;
            }
            // The cone's roots, once for both pieces: each is the root of F at its own s.
            double coneT[2], coneS[2];
            bool cone = false, coneSolved = false;
            for (int k = 0; k < pieces; ++k) {
                const double flo = value[k], fhi = value[k + 1];
                if ((flo > 0.0) == (fhi > 0.0)) continue;
                double t;
                if (e.y == 0.0) {  // an annulus: one height
                    t = heightT(seg, 0.0, oy, dy);
                } else if ((k == 0 && fa == 0.0) || (k + 1 == pieces && fb == 0.0)) {
                    t = heightT(seg, k == 0 && fa == 0.0 ? 0.0 : 1.0, oy, dy);
                } else {
                    if (!coneSolved) {
                        cone = coneRoots(seg, o, d, oy, dy, coneT, coneS);
                        coneSolved = true;
                    }
                    const double lo = cut[k], hi = cut[k + 1];
                    t = cone ? coneT[outside(coneS[0], lo, hi) <= outside(coneS[1], lo, hi) ? 0 : 1]
                             : heightT(seg, rootOnPiece(qa, qb, fa, lo, hi, flo, fhi), oy, dy);
                }
                hits.push_back({t, normalAt(ray.origin + t * ray.dir, seg.normal)});
            }
        }
    }

    /// A ray with dy = 0 stays at height oy and meets radius ρ twice, at tc ± √(ρ² − ρc²)/|d|
    /// about its closest approach ρc to the axis: the lines and Béziers crossing the line
    /// y = oy (classes y > oy, as the prism's) give the radii.
    void crossLevel(const Ray& ray, std::vector<LatheCrossing>& hits) const {
        const Vec2 o(ray.origin.x, ray.origin.z), d(ray.dir.x, ray.dir.z);
        const double oy = ray.origin.y, dd = glm::dot(d, d);
        const double tc = -glm::dot(o, d) / dd;
        const Vec2 closest = o + tc * d;
        const double rc2 = glm::dot(closest, closest);
        const auto atRadius = [&](double r, Vec2 n) {
            const double h2 = r * r - rc2;
            if (!(h2 > 0.0)) return;  // missed or touched: both crossings or neither
            const double h = std::sqrt(h2 / dd);
            for (const double t : {tc - h, tc + h})
                hits.push_back({t, normalAt(ray.origin + t * ray.dir, n)});
        };
        for (const LatheEdge& seg : mEdges) {
            if ((seg.a.y > oy) == (seg.b.y > oy)) continue;
            atRadius(seg.a.y == oy ? seg.a.x
                     : seg.b.y == oy
                         ? seg.b.x
                         : seg.a.x + (oy - seg.a.y) / (seg.b.y - seg.a.y) * (seg.b.x - seg.a.x),
                     seg.normal);
        }
        std::vector<double>& roots = mRoots;
        for (const LatheCurve& c : mCurves) {
            BernsteinCoefficients g{};
            for (int i = 0; i <= c.degree; ++i) g[i] = c.p[i].y - oy;
            roots.clear();
            bernsteinClassChanges(g, c.degree, roots);
            for (const double s : roots) {
                Vec2 tangent;
                const Vec2 q = curvePoint(c, s, &tangent);
                atRadius(s == 0.0   ? c.p[0].x
                         : s == 1.0 ? c.p[c.degree].x
                                    : q.x,
                         Vec2(tangent.y, -tangent.x) / glm::length(tangent));
            }
        }
    }

    void closedSpans(const Ray& ray, SpanList& out) const {
        std::vector<LatheCrossing>& hits = mScratch;
        hits.clear();
        const Vec2 o(ray.origin.x, ray.origin.z), d(ray.dir.x, ray.dir.z);
        const double dd = glm::dot(d, d);
        // A line that stays farther from the axis than the outline reaches misses (the margin
        // covers the rounding of its closest approach).
        const Vec2 closest = dd > 0.0 ? o - (glm::dot(o, d) / dd) * d : o;
        if (glm::dot(closest, closest) > mReach * mReach * (1.0 + 0x1p-40)) return;
        const double dxz = std::sqrt(dd);
        // Below 1e-100 of the horizontal part, a slope moves the ray's height by less than
        // rounding anywhere the ray can reach the solid.
        if (std::abs(ray.dir.y) <= 1e-100 * dxz)
            crossLevel(ray, hits);
        else
            crossSloped(ray, hits), crossCurvesSloped(ray, hits);
        std::sort(hits.begin(), hits.end(),
                  [](const LatheCrossing& x, const LatheCrossing& y) { return x.t < y.t; });
        const auto side = [&](const LatheCrossing& c, bool entering) {
            return (glm::dot(c.normal, ray.dir) < 0.0) == entering ? c.normal : -c.normal;
        };
        // The line starts and ends outside: crossings pair up into inside intervals.
        for (size_t k = 0; k + 1 < hits.size(); k += 2) {
            const Boundary leave = boundary(hits[k + 1].t, side(hits[k + 1], false));
            // Leaving and entering at one t (a vertex touched from outside): one span.
            if (!out.empty() && out.back().out.t == hits[k].t) {
                out.back().out = leave;
                continue;
            }
            out.push_back({boundary(hits[k].t, side(hits[k], true)), leave});
        }
    }

    std::vector<LatheEdge> mEdges;
    std::vector<LatheCurve> mCurves;
    double mReach = 0.0;  ///< the largest r of the outline
    static thread_local std::vector<LatheCrossing> mScratch;
    static thread_local std::vector<double> mRoots;
};

thread_local std::vector<LatheCrossing> Lathe::mScratch;
thread_local std::vector<double> Lathe::mRoots;

}  // namespace

NodePtr makeLathe(const std::vector<LatheSegment>& segments, NodePtr implicitForm) {
    return std::make_shared<Lathe>(segments, std::move(implicitForm));
}

}  // namespace kerf
