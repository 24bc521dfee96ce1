// Reference first hits: candidates from interval isolation at a tight tolerance, each re-located
// by bisection of the object's implicit form in long double.
//
// Limitation (by construction): the reference cannot search a whole ray in long double, so a
// crossing the interval isolation did not report at all (a sliver thinner than 1e-13·t, or a
// touch) is not found here either. The reference inherits the soundness of the interval
// isolation, which the interval-containment and root-isolation tests cover; what it adds is
// the position of every reported crossing to long-double precision, and the verdict that a
// reported crossing is not a sign change in long double (Uncertain).
#include "csg/primitives/reference.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace kerf {
namespace {

using LD = long double;

/// Candidates are isolated to this relative tolerance (Interval method), the tightest at
/// which the double-precision polish still converges reliably.
constexpr double kCandidateTolerance = 1e-13;
/// Initial bracket half-width, in units of the candidate's own error bound.
constexpr double kBracketFactor = 4.0;
/// A bracket without a sign change is widened by this factor, up to kMaxBracket·|t| and never
/// past the midpoints to the neighbouring candidates (so it stays with its own crossing): the
/// candidate of a grazing ray can be off by more than 1e-13·t, since the double-precision
/// polynomial of a near-double root is ill-conditioned.
constexpr double kGrowth = 16.0;
constexpr double kMaxBracket = 1e-7;
/// A confirmed crossing whose long-double position is less certain than this (relative to t)
/// is reported Uncertain: grazing rays, where valueExtended's own rounding moves the zero.
constexpr double kMaxUncertainty = 1e-15;

struct Candidate {
    double t;
    Vec3 normal;  ///< the double-precision normal of the boundary
};

bool insideLD(LD v) { return v <= 0; }  // NaN counts as outside, as isInside does

/// The ray's point at t, computed in long double from the double origin and direction.
LVec3 pointAt(const Ray& ray, LD t) { return LVec3(ray.origin) + t * LVec3(ray.dir); }

/// Bounds of the bracket search around candidate i: halfway to its neighbours and past tmin.
void neighbourLimits(const std::vector<Candidate>& c, size_t i, double tmin, LD& lo, LD& hi) {
    lo = i == 0 ? (LD)tmin : std::max<LD>(tmin, 0.5L * ((LD)c[i - 1].t + c[i].t));
    hi = i + 1 == c.size() ? (LD)INFINITY : 0.5L * ((LD)c[i].t + c[i + 1].t);
}

/// The unit outward normal: a fourth-order central difference of valueExtended in long
/// double, with the step shrunk until two successive estimates agree to 1e-13 (the
/// difference is then limited by rounding, ~1e-15, not by curvature). Where they never
/// agree (an edge or a CSG seam under the stencil, or a zero gradient), the double normal.
Vec3 referenceNormal(const Node& node, const LVec3& p, const Vec3& doubleNormal) {
    const LD scale = std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z), 1e-300L});
    auto estimate = [&](LD h) {
        LVec3 g;
        for (int a = 0; a < 3; ++a) {
            LVec3 e(0);
            e[a] = h;
            const LD f1 = node.valueExtended(p + e) - node.valueExtended(p - e);
            const LD f2 = node.valueExtended(p + 2.0L * e) - node.valueExtended(p - 2.0L * e);
            g[a] = (8 * f1 - f2) / (12 * h);
        }
        const LD n = std::sqrt(glm::dot(g, g));
        return n > 0 && std::isfinite(n) ? g / n : LVec3(0);
    };
    LVec3 previous = estimate(scale * 0x1p-12L);
    for (int k = 1; k <= 6; ++k) {
        const LVec3 next = estimate(scale * std::ldexp(1.0L, -12 - 4 * k));
        const LVec3 diff = next - previous;
        if (glm::dot(next, next) > 0 && std::sqrt(glm::dot(diff, diff)) <= 1e-13L)
            return Vec3(next);
        previous = next;
    }
    const double len = glm::length(doubleNormal);
    return len > 0.0 ? doubleNormal / len : doubleNormal;
}

struct Refined {
    ReferenceHit::Kind kind = ReferenceHit::Kind::Uncertain;
    LD t = 0;
    Vec3 normal{0.0};
};

/// Re-locates candidate i by long-double bisection of valueExtended.
Refined refine(const Node& node, const Ray& ray, const std::vector<Candidate>& c, size_t i,
               double tmin) {
    const double t = c[i].t;
    const double dirLen = glm::length(ray.dir);
    // The candidate's error: its tolerance, or the rounding of o + t·d in double (in t units).
    const double rounding = 0x1p-52 * (glm::length(ray.origin) + std::fabs(t) * dirLen) / dirLen;
    const double e = std::max(kCandidateTolerance * std::fabs(t), rounding);
    LD limitLo, limitHi;
    neighbourLimits(c, i, tmin, limitLo, limitHi);
    Refined r;
    LD lo = 0, hi = 0, vlo = 0, vhi = 0;
    bool bracketed = false;
    for (LD w = kBracketFactor * e;
         w <= std::max<LD>(kMaxBracket * std::fabs(t), kBracketFactor * e); w *= kGrowth) {
        lo = std::max<LD>(limitLo, t - w);
        hi = std::min<LD>(limitHi, t + w);
        vlo = node.valueExtended(pointAt(ray, lo));
        vhi = node.valueExtended(pointAt(ray, hi));
        if (insideLD(vlo) != insideLD(vhi)) {
            bracketed = true;
            break;
        }
        if (lo == limitLo && hi == limitHi) break;
    }
    if (!bracketed) return r;  // no sign change in long double: a tangency, or unconfirmable
    // Bisect until the bracket is a few long-double ulps of t wide.
    const bool insideLo = insideLD(vlo);
    for (int it = 0; it < 256; ++it) {
        const LD m = 0.5L * (lo + hi);
        if (!(m > lo && m < hi)) break;
        if (hi - lo <= 4 * std::max(std::fabs(lo), std::fabs(hi)) * 0x1p-63L) break;
        if (insideLD(node.valueExtended(pointAt(ray, m))) == insideLo)
            lo = m;
        else
            hi = m;
    }
    r.t = 0.5L * (lo + hi);
    const LVec3 p = pointAt(ray, r.t);
    r.normal = referenceNormal(node, p, c[i].normal);
    // Where the ray meets the surface at a glancing angle, a rounding of the point (at least
    // an ulp of |p| per coordinate, and valueExtended's own) moves the zero along the ray by
    // about ulp·|p| / |n·d|: an estimate of the reference's own uncertainty at this crossing.
    const LD along = std::fabs(glm::dot(LVec3(r.normal), LVec3(ray.dir)));
    const LD size = std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
    const LD uncertainty = 8 * 0x1p-63L * size / along;
    r.kind = uncertainty <= kMaxUncertainty * std::fabs(r.t) ? ReferenceHit::Kind::Hit
                                                             : ReferenceHit::Kind::Uncertain;
    return r;
}

}  // namespace

ReferenceHit referenceNearestHit(const SceneGeometry& geometry, const Ray& ray, double tmin) {
    TraceContext ctx;
    ctx.method = TraceMethod::Interval;
    ctx.relTolerance = kCandidateTolerance;
    ReferenceHit best, uncertain;
    std::vector<Candidate> candidates;
    geometry.forEachObjectSpans(ray, tmin, kInf, ctx, [&](int index, const SpanList& spans) {
        candidates.clear();
        for (const Span& s : spans)
            for (const Boundary* b : {&s.in, &s.out})
                if (b->isSurface() && b->t > tmin) candidates.push_back({b->t, b->normal});
        const Node& node = *geometry.objects()[index];
        for (size_t i = 0; i < candidates.size(); ++i) {
            // Past a hit already confirmed (beyond any bracket): nothing here can come first.
            if (best.kind == ReferenceHit::Kind::Hit &&
                candidates[i].t - (double)best.t > 2.0 * kMaxBracket * std::fabs(candidates[i].t))
                break;
            const Refined r = refine(node, ray, candidates, i, tmin);
            if (r.kind == ReferenceHit::Kind::Uncertain) {
                const LD t = candidates[i].t;
                if (uncertain.kind != ReferenceHit::Kind::Uncertain || t < uncertain.t) {
                    uncertain.kind = ReferenceHit::Kind::Uncertain;
                    uncertain.t = t;
                    uncertain.object = index;
                    const double len = glm::length(candidates[i].normal);
                    uncertain.normal = len > 0.0 ? candidates[i].normal / len : Vec3(0.0);
                }
                continue;
            }
            if (best.kind != ReferenceHit::Kind::Hit || r.t < best.t) {
                best.kind = ReferenceHit::Kind::Hit;
                best.t = r.t;
                best.object = index;
                best.normal = r.normal;
            }
            break;  // this object's first confirmed crossing
        }
    });
    if (uncertain.kind == ReferenceHit::Kind::Uncertain &&
        (best.kind != ReferenceHit::Kind::Hit || uncertain.t < best.t))
        return uncertain;
    return best;
}

}  // namespace kerf
