/// @file csg/polynomial_isolation.h
/// @brief TraceMethod::Interval for the quadric and planar primitives: their implicit forms
/// along a ray are polynomials of degree ≤ 2 in a normalised parameter s, isolated by
/// csg/root_isolation.h with centred-form enclosures (no closed-form root formula is used).
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

namespace kerf {

/// q(s) = c2·s² + c1·s + c0 (c2 = 0: a linear function). Inside where q ≤ 0.
struct QuadraticAlongRay {
    double c2 = 0.0, c1 = 0.0, c0 = 0.0;

    /// Centred form at the midpoint m: q(m + x) = q(m) + q'(m)·x + c2·x² exactly, |x| ≤ h.
    /// The slack covers the rounding of these few operations (a handful of ulps of the
    /// magnitudes involved); the coefficients themselves are taken as exact.
    void range(double a, double b, Interval& f, Interval& dfds) const {
        constexpr double kRound = 8.0 * std::numeric_limits<double>::epsilon();
        const double m = 0.5 * (a + b);
        const double h = std::max(b - m, m - a) * (1.0 + kRound);
        const double p0 = (c2 * m + c1) * m + c0;
        const double p1 = 2.0 * c2 * m + c1;
        const double spread = std::fabs(p1) * h, curve = c2 * h * h;
        const double slack =
            kRound * (std::fabs(c2 * m * m) + std::fabs(c1 * m) + std::fabs(c0) + spread +
                      std::fabs(curve));
        f = {p0 - spread + std::min(0.0, curve) - slack, p0 + spread + std::max(0.0, curve) + slack};
        const double dSpread = 2.0 * std::fabs(c2) * h;
        const double dSlack = kRound * (std::fabs(p1) + dSpread);
        dfds = {p1 - dSpread - dSlack, p1 + dSpread + dSlack};
    }
    double value(double s) const { return (c2 * s + c1) * s + c0; }
    double valueAndSlope(double s, double& dqds) const {
        dqds = 2.0 * c2 * s + c1;
        return (c2 * s + c1) * s + c0;
    }
};

/// The sign changes of a polynomial on a range, in increasing s.
struct Crossings {
    /// A quadratic has two; rounding near a double root can add a few more. Past this
    /// many, the last pair is dropped (a sliver below the tolerance) so states alternate.
    static constexpr int kMax = 8;
    double s[kMax];
    bool entering[kMax];
    int count = 0;
    bool insideAtStart = false;
};

/// Every crossing of q on the finite range [lo, hi] (lo ≤ hi), by isolateRoots.
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

/// Face numbers of a frustum's boundaries.
enum FrustumFace { kFrustumWindow = 0, kFrustumLateral = 1, kFrustumBase = 2, kFrustumTop = 3 };

/// Spans of the frustum on the window [sLo, sHi] ∩ [−1, 1]·(1 + 2⁻²⁰): the slab between the
/// caps (two linear functions), then the lateral quadric |p⊥|² − (r1 + k·z)² inside it (the
/// slab keeps only the real nappe, where r1 + k·z ≥ 0). emit as for quadraticSpans.
template <class Emit>
void frustumSpans(const FrustumAlongRay& f, double sLo, double sHi, double sOffset,
                  TraceContext& ctx, Emit&& emit) {
    constexpr double kBall = 1.0 + 0x1p-20;  // ends strictly outside the solid
    FacedRange r{std::max(sLo, -kBall), std::min(sHi, kBall)};
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
