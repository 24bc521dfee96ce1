/// @file bench/reference/ref_spans.cpp
#include "ref_spans.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kerf::bench {

namespace {

constexpr Real kInf = std::numeric_limits<Real>::infinity();
using K = RefNode::Kind;

void addSpan(RefSpans& out, Real enter, Real exit) {
    if (enter < exit) out.emplace_back(enter, exit);  // tangent (zero-length) spans vanish
}

/// |p + t q|^2 = r^2 with the cancellation-free discriminant a r^2 - |q x p|^2.
void quadricSpan(V3 p, V3 q, Real radius, RefSpans& out) {
    const Real a = dot(q, q);
    if (a == 0) {
        if (dot(p, p) <= radius * radius) addSpan(out, -kInf, kInf);
        return;
    }
    const V3 c = cross(q, p);
    const Real disc = a * radius * radius - dot(c, c);
    if (disc <= 0) return;
    const Real b = dot(p, q);
    const Real root = std::sqrt(disc);
    const Real s = -(b + std::copysign(root, b));  // never 0: |s| >= root > 0
    const Real t1 = s / a, t2 = (dot(p, p) - radius * radius) / s;
    addSpan(out, std::min(t1, t2), std::max(t1, t2));
}

/// lo <= o + t d <= hi along one axis, narrowing [t0, t1]; false if empty.
bool clipSlab(Real o, Real d, Real lo, Real hi, Real& t0, Real& t1) {
    if (d == 0) return lo <= o && o <= hi;
    Real a = (lo - o) / d, b = (hi - o) / d;
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
    return t0 < t1;
}

void boxSpans(const RefNode& n, V3 o, V3 d, RefSpans& out) {
    Real t0 = -kInf, t1 = kInf;
    if (clipSlab(o.x, d.x, n.a.x, n.b.x, t0, t1) && clipSlab(o.y, d.y, n.a.y, n.b.y, t0, t1) &&
        clipSlab(o.z, d.z, n.a.z, n.b.z, t0, t1))
        addSpan(out, t0, t1);
}

void cylinderSpans(const RefNode& n, V3 o, V3 d, RefSpans& out) {
    const V3 axis = n.b - n.a;
    const Real length = std::sqrt(dot(axis, axis));
    const V3 w = (1 / length) * axis;
    const V3 p = o - n.a;
    const Real pw = dot(p, w), dw = dot(d, w);
    Real t0 = -kInf, t1 = kInf;
    if (!clipSlab(pw, dw, 0, length, t0, t1)) return;
    RefSpans side;
    quadricSpan(p - pw * w, d - dw * w, n.r1, side);
    if (side.empty()) return;
    addSpan(out, std::max(t0, side[0].first), std::min(t1, side[0].second));
}

void halfSpaceSpans(const RefNode& n, V3 o, V3 d, RefSpans& out) {
    const Real nd = dot(n.a, d), no = dot(n.a, o);
    if (nd == 0) {
        if (no <= n.r1) addSpan(out, -kInf, kInf);
        return;
    }
    const Real t = (n.r1 - no) / nd;
    if (nd > 0)
        addSpan(out, -kInf, t);
    else
        addSpan(out, t, kInf);
}

Real evaluate(const Real* c, int degree, Real s) {
    Real v = c[degree];
    for (int i = degree - 1; i >= 0; --i) v = v * s + c[i];
    return v;
}

/// Bisects a sign change of the polynomial on [lo, hi] down to adjacent long doubles.
Real bisect(const Real* c, int degree, Real lo, Real hi, Real vlo) {
    for (;;) {
        const Real mid = lo + (hi - lo) / 2;
        if (mid <= lo || mid >= hi)
            return std::fabs(vlo) <= std::fabs(evaluate(c, degree, hi)) ? lo : hi;
        const Real v = evaluate(c, degree, mid);
        if (v == 0) return mid;
        if ((v < 0) == (vlo < 0))
            lo = mid, vlo = v;
        else
            hi = mid;
    }
}

/// (|p|^2 + R^2 - r^2)^2 - 4 R^2 (px^2 + pz^2) <= 0 along the ray, roots isolated on the
/// bounding sphere's chord after moving the origin to the chord's start (small coefficients).
void torusSpans(const RefNode& n, V3 o, V3 d, RefSpans& out) {
    const Real major = n.r1, minor = n.r2;
    RefSpans bound;
    quadricSpan(o, d, major + minor, bound);
    if (bound.empty()) return;
    const Real start = bound[0].first, chord = bound[0].second - start;
    const V3 p = o + start * d;
    const Real a = dot(d, d), b = 2 * dot(p, d), c = dot(p, p) + major * major - minor * minor;
    const Real ring = 4 * major * major;
    const Real coeff[5] = {c * c - ring * (p.x * p.x + p.z * p.z),
                           2 * b * c - 2 * ring * (p.x * d.x + p.z * d.z),
                           b * b + 2 * a * c - ring * (d.x * d.x + d.z * d.z), 2 * a * b, a * a};
    Real roots[4];
    // The quartic is positive outside the bounding sphere: a small margin keeps roots that
    // rounding puts on the chord's ends.
    const Real margin = chord * 1e-9L;
    const int count = polynomialRoots(coeff, 4, -margin, chord + margin, roots);
    bool inside = evaluate(coeff, 4, -margin) <= 0;
    Real enter = -kInf;
    for (int i = 0; i < count; ++i) {
        if (inside)
            addSpan(out, enter, start + roots[i]);
        else
            enter = start + roots[i];
        inside = !inside;
    }
}

/// Sweep over the boundaries of two span lists; keeps t where keep(inA, inB).
template <class Keep>
RefSpans combine(const RefSpans& a, const RefSpans& b, Keep keep) {
    RefSpans out;
    size_t i = 0, j = 0;
    bool inA = false, inB = false, was = keep(false, false);
    Real enter = -kInf;
    auto nextOf = [](const RefSpans& s, size_t k, bool in) {
        return k < s.size() ? (in ? s[k].second : s[k].first) : kInf;
    };
    for (;;) {
        const Real ta = nextOf(a, i, inA), tb = nextOf(b, j, inB);
        const Real t = std::min(ta, tb);
        if (t == kInf && i >= a.size() && j >= b.size()) break;
        // Every boundary at the same t changes state together: touching spans merge, a cutter
        // sharing a face leaves no sliver.
        if (ta == t && i < a.size()) {
            if (inA) ++i;
            inA = !inA;
        }
        if (tb == t && j < b.size()) {
            if (inB) ++j;
            inB = !inB;
        }
        const bool now = keep(inA, inB);
        if (now && !was) enter = t;
        if (!now && was) addSpan(out, enter, t);
        was = now;
        if (t == kInf) break;
    }
    if (was) addSpan(out, enter, kInf);
    return out;
}

}  // namespace

int polynomialRoots(const Real* c, int degree, Real lo, Real hi, Real* roots) {
    while (degree > 0 && c[degree] == 0) --degree;
    if (degree == 0) return 0;
    if (degree == 1) {
        const Real s = -c[0] / c[1];
        if (lo <= s && s <= hi) {
            roots[0] = s;
            return 1;
        }
        return 0;
    }
    Real derivative[4], critical[4];
    for (int i = 1; i <= degree; ++i) derivative[i - 1] = i * c[i];
    const int nc = polynomialRoots(derivative, degree - 1, lo, hi, critical);
    Real ends[6];
    int ne = 0;
    ends[ne++] = lo;
    for (int i = 0; i < nc; ++i) ends[ne++] = critical[i];
    ends[ne++] = hi;
    int count = 0;
    for (int k = 0; k + 1 < ne; ++k) {
        const Real v0 = evaluate(c, degree, ends[k]), v1 = evaluate(c, degree, ends[k + 1]);
        if (v0 == 0) {
            if (count == 0 || roots[count - 1] != ends[k]) roots[count++] = ends[k];
        } else if (v1 != 0 && (v0 < 0) != (v1 < 0)) {
            roots[count++] = bisect(c, degree, ends[k], ends[k + 1], v0);
        }
    }
    if (evaluate(c, degree, hi) == 0 && (count == 0 || roots[count - 1] != hi)) roots[count++] = hi;
    return count;
}

RefSpans spansOf(const RefNode& n, V3 o, V3 d) {
    RefSpans out;
    switch (n.kind) {
        case K::Sphere: quadricSpan(o - n.a, d, n.r1, out); break;
        case K::Box: boxSpans(n, o, d, out); break;
        case K::Cylinder: cylinderSpans(n, o, d, out); break;
        case K::HalfSpace: halfSpaceSpans(n, o, d, out); break;
        case K::Torus: torusSpans(n, o, d, out); break;
        case K::Transform:
            out = spansOf(n.children[0], n.localFromWorld * (o - n.offset), n.localFromWorld * d);
            break;
        case K::Union:
        case K::Intersection:
        case K::Difference: {
            out = spansOf(n.children[0], o, d);
            for (size_t k = 1; k < n.children.size(); ++k) {
                if (out.empty() && n.kind != K::Union) break;
                const RefNode& child = n.children[k];
                RefSpans other;
                if (child.kind == K::Sphere) {
                    quadricSpan(o - child.a, d, child.r1, other);  // the common cutter, no copy
                } else {
                    other = spansOf(child, o, d);
                }
                if (other.empty()) {
                    if (n.kind == K::Intersection) out.clear();
                    continue;
                }
                if (n.kind == K::Union)
                    out = combine(out, other, [](bool a, bool b) { return a || b; });
                else if (n.kind == K::Intersection)
                    out = combine(out, other, [](bool a, bool b) { return a && b; });
                else
                    out = combine(out, other, [](bool a, bool b) { return a && !b; });
            }
            break;
        }
    }
    return out;
}

std::pair<Real, Real> nearestHit(const std::vector<RefNode>& objects, V3 eye, V3 d) {
    std::pair<Real, Real> best{kInf, kInf};
    for (const RefNode& object : objects) {
        for (const auto& span : spansOf(object, eye, d)) {
            if (span.first > 0) {
                if (span.first < best.first) best = span;
                break;
            }
        }
    }
    return best;
}

}  // namespace kerf::bench
