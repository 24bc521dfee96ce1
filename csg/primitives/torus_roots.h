/// @file csg/primitives/torus_roots.h
/// @brief Where a line crosses a torus, from the shape of the torus' distance form along it.
///
/// Along p(s) = p0 + s·u (|u| = 1) the form h = (ρ − R)² + y² − r² (ρ = √(x² + z²)) equals
/// |p|² + R² − r² − 2R·ρ(s): a convex quadratic minus 2R times ρ(s) = √(a2·(s − sm)² + ρm²),
/// whose second derivative is a2·ρm²/ρ³. So h'' = 2 − 2R·a2·ρm²/ρ³ changes sign only where
/// ρ = ∛(R·a2·ρm²): at most two inflection points, in closed form, symmetric about sm. Between
/// them h is concave, outside them convex. On a piece of one convexity the crossings are found
/// without any enclosure: at most two, decided by the tangents at the piece's ends and at the
/// points where they meet (a convex function lies above its tangents), each located in its
/// bracket by steps to the root of h's local quadratic model (h'' is known in closed form:
/// cubic convergence). h is the well-conditioned form (the quartic is h times a positive
/// factor), so every decision and every root is as accurate as h is.
#pragma once

#include <cmath>
#include <limits>

#include "csg/types.h"

namespace kerf {

/// A line against the torus around the y axis, in units where the coordinates are O(1).
struct TorusLine {
    Vec3 p0, u;     ///< p(s) = p0 + s·u, |u| = 1
    double R, r;    ///< major and minor radius
    double a2, sm;  ///< x² + z² = a2·(s − sm)² + ρm² along the line
    double rm2;     ///< ρm²

    TorusLine(const Vec3& origin, const Vec3& unitDir, double major, double minor);

    /// h at s.
    double value(double s) const {
        const Vec3 q = p0 + s * u;
        const double e = std::sqrt(q.x * q.x + q.z * q.z) - R;
        return e * e + (q.y - r) * (q.y + r);
    }

    /// h at s and its slope. On the axis (ρ = 0, a kink of h) the slope is the one-sided
    /// slope on the side `side` (−1: left of s, +1: right of s).
    double valueAndSlope(double s, double side, double& slope) const {
        const Vec3 q = p0 + s * u;
        const double rho = std::sqrt(q.x * q.x + q.z * q.z), e = rho - R;
        const double drho = rho > 0.0 ? (q.x * u.x + q.z * u.z) / rho : side * std::sqrt(a2);
        slope = 2.0 * (e * drho + q.y * u.y);
        return e * e + (q.y - r) * (q.y + r);
    }

    /// h at s, its slope and its second derivative 2 − 2R·a2·ρm²/ρ³ (off the axis).
    double valueSlopeCurvature(double s, double& slope, double& curvature) const {
        const Vec3 q = p0 + s * u;
        const double rho = std::sqrt(q.x * q.x + q.z * q.z), e = rho - R;
        const double drho = (q.x * u.x + q.z * u.z) / rho;
        slope = 2.0 * (e * drho + q.y * u.y);
        curvature = 2.0 - 2.0 * R * a2 * rm2 / (rho * rho * rho);
        return e * e + (q.y - r) * (q.y + r);
    }

    /// Cuts [a, b] into pieces of one convexity: writes a, the inflection points inside (a, b)
    /// and b to cuts[], and whether each piece is concave to concave[]; returns the number of
    /// pieces (1–3).
    int pieces(double a, double b, double cuts[4], bool concave[3]) const;

    /// What pieceCrossings needs to locate a piece's second crossing later.
    struct Pending {
        double x;  ///< a point strictly between the two crossings
        double hi, hHi, slopeHi;
        bool insideX;
    };

    /// The crossings of h inside the piece [lo, hi] (one convexity: `concave`), whose ends
    /// have h = hLo and hHi, in increasing order; returns how many (0–2). A point is inside
    /// where h ≤ 0; the count is odd exactly when the ends' sides differ. Each crossing is
    /// located to the rounding of s or absTol, whichever is larger. With `later`, the second
    /// of two crossings is left to secondCrossing(*later) (a first-surface search may be
    /// decided without it: it lies after later->x).
    int pieceCrossings(double lo, double hi, double hLo, double hHi, bool concave, double absTol,
                       double out[2], long& steps, Pending* later = nullptr) const;

    /// The second crossing that pieceCrossings left in `later`.
    double secondCrossing(const Pending& later, double absTol, long& steps) const {
        return oneCrossing(later.x, later.hi, later.insideX, later.hi, later.hHi, later.slopeHi,
                           absTol, steps);
    }

private:
    /// The one crossing in [lo, hi] (sides differ at the ends) from `start` (where h = f and
    /// h' = slope): steps to the root of the local quadratic model (Newton's step where the
    /// model has none), bisection where a step would leave the shrinking bracket.
    double oneCrossing(double lo, double hi, bool insideLo, double start, double f, double slope,
                       double absTol, long& steps) const;
};

}  // namespace kerf
