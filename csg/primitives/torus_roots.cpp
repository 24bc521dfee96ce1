// Crossings of a line with the torus, piece by piece of one convexity of the distance form
// (the reasoning is in csg/primitives/torus_roots.h).
#include "csg/primitives/torus_roots.h"

#include <algorithm>

namespace kerf {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
/// Newton or tangent steps per crossing before settling: far more than convergence needs
/// (quadratic, or bisection of a double interval).
constexpr int kMaxSteps = 120;

}  // namespace

TorusLine::TorusLine(const Vec3& origin, const Vec3& unitDir, double major, double minor)
    : p0(origin), u(unitDir), R(major), r(minor) {
    a2 = u.x * u.x + u.z * u.z;
    sm = a2 > 0.0 ? -(p0.x * u.x + p0.z * u.z) / a2 : 0.0;
    // ρm² from the point itself (no cancellation).
    const double x = p0.x + sm * u.x, z = p0.z + sm * u.z;
    rm2 = x * x + z * z;
}

int TorusLine::pieces(double a, double b, double cuts[4], bool concave[3]) const {
    int n = 0;
    cuts[0] = a;
    double i1 = 0.0, i2 = 0.0;  // the concave zone (i1, i2), empty unless i1 < i2
    if (a2 > 0.0) {
        // Concave somewhere iff ρi > ρm, i.e. (R·a2)² > ρm² (no cube root needed to know).
        const double ra = R * a2;
        if (rm2 > 0.0 && ra * ra > rm2) {
            const double ri = std::cbrt(ra * rm2);
            const double w = std::sqrt(std::fmax(ri * ri - rm2, 0.0) / a2);
            i1 = sm - w, i2 = sm + w;
            if (i1 > a && i1 < b) cuts[++n] = i1;
            if (i2 > cuts[n] && i2 < b) cuts[++n] = i2;
        } else if (rm2 == 0.0 && sm > a && sm < b) {
            cuts[++n] = sm;  // the line meets the axis: a kink of h, convex on both sides
        }
    }
    cuts[++n] = b;
    for (int k = 0; k < n; ++k) {
        const double mid = 0.5 * (cuts[k] + cuts[k + 1]);
        concave[k] = mid > i1 && mid < i2;
    }
    return n;
}

double TorusLine::oneCrossing(double lo, double hi, bool insideLo, double start, double f,
                              double slope, double absTol, long& steps) const {
    double s = start;
    const double rho = std::sqrt(a2 * (s - sm) * (s - sm) + rm2);
    // Off the axis, else no curvature term (Newton): the kink has no second derivative.
    double curvature = rho > 0.0 ? 2.0 - 2.0 * R * a2 * rm2 / (rho * rho * rho) : 0.0;
    for (int it = 0; it < kMaxSteps; ++it) {
        // The root of the local quadratic model f + slope·δ + curvature·δ²/2 nearest 0 (the
        // stable form; Newton's step where the model has none): cubic convergence.
        const double disc = slope * slope - 2.0 * curvature * f;
        const double next = disc >= 0.0
                                ? s - 2.0 * f / (slope + std::copysign(std::sqrt(disc), slope))
                                : s - f / slope;
        // Converged: a step at the rounding of s, or of h's own value in these units (its
        // terms are O(1): steps below 4ε only follow its rounding noise).
        if (std::fabs(next - s) <= std::fmax(kEps * std::fmax(2.0 * std::fabs(s), 4.0), absTol))
            return std::fmin(std::fmax(next, lo), hi);
        if (next > lo && next < hi) {
            s = next;
        } else {
            s = 0.5 * (lo + hi);
            if (!(s > lo && s < hi)) return s;  // two adjacent doubles
        }
        ++steps;
        f = valueSlopeCurvature(s, slope, curvature);
        if (f == 0.0) return s;
        if ((f <= 0.0) == insideLo)
            lo = s;
        else
            hi = s;
    }
    return s;
}

int TorusLine::pieceCrossings(double lo, double hi, double hLo, double hHi, bool concave,
                              double absTol, double out[2], long& steps, Pending* later) const {
    // g = ±h is convex on the piece; Newton on g is Newton on h.
    const double sg = concave ? -1.0 : 1.0;
    const bool inLo = hLo <= 0.0, inHi = hHi <= 0.0;
    double slope = 0.0;
    if (inLo != inHi) {
        // One crossing. Newton started where g > 0 approaches it from that side only.
        if (sg * hHi > 0.0) {
            valueAndSlope(hi, -1.0, slope);
            out[0] = oneCrossing(lo, hi, inLo, hi, hHi, slope, absTol, steps);
        } else if (sg * hLo > 0.0) {
            valueAndSlope(lo, 1.0, slope);
            out[0] = oneCrossing(lo, hi, inLo, lo, hLo, slope, absTol, steps);
        } else {
            out[0] = hLo == 0.0 ? lo : hi;  // h = 0 exactly at an end: the crossing is there
        }
        return 1;
    }
    // Same side at both ends: none where that side is g ≤ 0 (a convex g stays below the
    // larger end); else two or none, where g dips below 0.
    if (inLo != concave) return 0;
    double L = lo, Rt = hi, gL = sg * hLo, gR = sg * hHi, dL, dR;
    if (!(gL > 0.0 && gR > 0.0)) return 0;
    valueAndSlope(L, 1.0, dL);
    valueAndSlope(Rt, -1.0, dR);
    dL *= sg, dR *= sg;
    for (int it = 0; it < kMaxSteps; ++it) {
        // g rises from L or falls towards Rt: its minimum here is at an end, above 0.
        if (!(dL < 0.0) || !(dR > 0.0)) return 0;
        // The tangents at L and Rt lie below g; where they meet is their lowest common point.
        double x = (gR - gL + dL * L - dR * Rt) / (dL - dR);
        if (!(x > L && x < Rt)) x = 0.5 * (L + Rt);
        if (!(x > L && x < Rt)) return 0;
        if (gL + dL * (x - L) > 0.0 && gR + dR * (x - Rt) > 0.0) return 0;
        ++steps;
        double d = 0.0;
        const double f = valueAndSlope(x, 1.0, d);
        if ((f <= 0.0) != inLo) {
            // A point of the other side: one crossing on each side of it.
            out[0] = oneCrossing(L, x, inLo, L, sg * gL, sg * dL, absTol, steps);
            const Pending second{x, Rt, sg * gR, sg * dR, !inLo};
            if (later)
                *later = second;
            else
                out[1] = secondCrossing(second, absTol, steps);
            return 2;
        }
        const double g = sg * f, dg = sg * d;
        if (dg < 0.0)
            L = x, gL = g, dL = dg;
        else if (dg > 0.0)
            Rt = x, gR = g, dR = dg;
        else
            return 0;  // the minimum, above 0
        // Narrower than rounding: a touch, no crossing.
        if (Rt - L <= std::fmax(2.0 * kEps * std::max(std::fabs(L), std::fabs(Rt)), absTol))
            return 0;
    }
    return 0;
}

}  // namespace kerf
