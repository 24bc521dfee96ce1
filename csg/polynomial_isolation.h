/// @file csg/polynomial_isolation.h
/// @brief TraceMethod::Interval for the quadric and planar primitives: their implicit forms
/// along a ray are polynomials of degree ≤ 2 in a normalised parameter s, whose crossings are
/// isolated by interval enclosures and polished by a guarded Newton iteration (no closed-form
/// root formula is used). The generic bisection of csg/root_isolation.h is not needed: the
/// derivative of a quadratic is linear, so one cut at its zero (the vertex) leaves pieces on
/// which the derivative's enclosure has one sign, and each piece is decided at once.
///
/// Parameters are normalised by the primitive (lengths divided by its size, s measured from
/// the ray's point nearest its centre) so the coefficients are O(1) at every scene scale and
/// position, as csg/torus.cpp does for its quartic. `sOffset` is the s-value of the ray's
/// origin with the sign flipped: s + sOffset is proportional to the ray's t, to which the
/// tolerance refers.
#pragma once

#include "csg/root_isolation.h"
#include "csg/types.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kerf {

/// q(s) = c2·s² + c1·s + c0 (c2 = 0: a linear function). Inside where q ≤ 0.
struct QuadraticAlongRay {
    double c2 = 0.0, c1 = 0.0, c0 = 0.0;

    double value(double s) const { return (c2 * s + c1) * s + c0; }
    double slope(double s) const { return 2.0 * c2 * s + c1; }
    /// A bound on the rounding error of value(s) (Horner: a few ulps of the terms' sizes);
    /// the coefficients themselves are taken as exact.
    double rounding(double s) const {
        constexpr double kRound = 8.0 * std::numeric_limits<double>::epsilon();
        return kRound * (std::fabs(c2 * s * s) + std::fabs(c1 * s) + std::fabs(c0));
    }
};

/// The sign changes of a polynomial on a range, in increasing s.
struct Crossings {
    /// A quadratic has at most two: one on each side of its vertex.
    static constexpr int kMax = 2;
    double s[kMax];
    bool entering[kMax];
    int count = 0;
    bool insideAtStart = false;
};

/// Every crossing of q on the finite range [lo, hi] (lo ≤ hi). The range is cut at q's vertex
/// when it lies inside; each piece is then monotone (the derivative's enclosure, the hull of
/// its end values, has one sign), so q's enclosure on it is the hull of its end values: it
/// excludes 0 (no crossing), or the end states differ (exactly one crossing, polished by
/// Newton inside the bracket to ctx.relTolerance of s + sOffset), or an end touches 0 without
/// a change of state (a touch: no crossing, as in csg/root_isolation.h).
void findCrossings(const QuadraticAlongRay& q, double lo, double hi, double sOffset,
                   TraceContext& ctx, Crossings& out);

/// A parameter range whose ends each lie on a numbered face of the solid; face 0 is an end
/// of the search window (a clip of the caller's range, or a point outside the solid).
struct FacedRange {
    double lo, hi;
    int loFace = 0, hiFace = 0;
};

/// Narrows r to where the linear function (c2 = 0) is ≤ 0; a moved end gets `face`.
/// Returns false when nothing of r is left.
bool clipToLinear(const QuadraticAlongRay& linear, int face, double sOffset, TraceContext& ctx,
                  FacedRange& r);

/// Calls emit(sIn, faceIn, sOut, faceOut) for each span of r where q ≤ 0, in order; ends on
/// q's zero set get `face`, ends at an end of r keep that end's face.
template <class Emit>
void quadraticSpans(const QuadraticAlongRay& q, const FacedRange& r, int face, double sOffset,
                    TraceContext& ctx, Emit&& emit) {
    Crossings c;
    findCrossings(q, r.lo, r.hi, sOffset, ctx, c);
    bool inside = c.insideAtStart;
    double pendingS = r.lo;
    int pendingFace = r.loFace;
    for (int i = 0; i < c.count; ++i) {
        if (c.entering[i]) {
            pendingS = c.s[i];
            pendingFace = face;
        } else {
            emit(pendingS, pendingFace, c.s[i], face);
        }
        inside = c.entering[i];
    }
    if (inside) emit(pendingS, pendingFace, r.hi, r.hiFace);
}

/// A capped cone or cylinder along a normalised ray: local coordinates (x, y across the
/// axis, z along it from the base) of the ray's point p(s) = g + s·u, lengths divided by the
/// radius of a ball around the axis' middle that holds the solid (so |s| ≤ 1 covers it).
struct FrustumAlongRay {
    Vec3 g;         ///< ray point at s = 0 (nearest the axis' middle), local, normalised
    Vec3 u;         ///< unit direction, local
    double r1;      ///< normalised base radius
    double slope;   ///< radius growth per unit of z (0 for a cylinder)
    double length;  ///< normalised axis length
};

/// Half-width of the search window in normalised units (the solid lies in [−1, 1]): a hair
/// wider, so the window's ends lie strictly outside the solid.
constexpr double kNormalisedWindow = 1.0 + 0x1p-20;

/// Face numbers of a frustum's boundaries.
enum FrustumFace { kFrustumWindow = 0, kFrustumLateral = 1, kFrustumBase = 2, kFrustumTop = 3 };

/// Spans of the frustum on the window [sLo, sHi] ∩ [−1, 1]·(1 + 2⁻²⁰): the slab between the
/// caps (two linear functions), then the lateral quadric |p⊥|² − (r1 + k·z)² inside it (the
/// slab keeps only the real nappe, where r1 + k·z ≥ 0). emit as for quadraticSpans.
template <class Emit>
void frustumSpans(const FrustumAlongRay& f, double sLo, double sHi, double sOffset,
                  TraceContext& ctx, Emit&& emit) {
    FacedRange r{std::max(sLo, -kNormalisedWindow), std::min(sHi, kNormalisedWindow)};
    if (!(r.lo <= r.hi)) return;
    const Vec3& g = f.g;
    const Vec3& u = f.u;
    if (!clipToLinear({0.0, -u.z, -g.z}, kFrustumBase, sOffset, ctx, r)) return;
    if (!clipToLinear({0.0, u.z, g.z - f.length}, kFrustumTop, sOffset, ctx, r)) return;
    const double w0 = f.r1 + f.slope * g.z, w1 = f.slope * u.z;
    const QuadraticAlongRay lateral{u.x * u.x + u.y * u.y - w1 * w1,
                                    2.0 * (g.x * u.x + g.y * u.y - w0 * w1),
                                    g.x * g.x + g.y * g.y - w0 * w0};
    quadraticSpans(lateral, r, kFrustumLateral, sOffset, ctx, emit);
}

}  // namespace kerf
