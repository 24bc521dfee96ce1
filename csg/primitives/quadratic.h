/// @file csg/primitives/quadratic.h
/// @brief The numerically stable quadratic root formula shared by the closed-form primitives.
///
/// Callers supply √disc themselves because the discriminant is where the precision is won or
/// lost: each primitive computes it in a cancellation-free geometric form (Haines et al.,
/// "Precision Improvements for Ray/Sphere Intersection", Ray Tracing Gems, ch. 7) rather than
/// as the difference h² − a·c of two nearly equal large numbers.
#pragma once

#include <cmath>

namespace kerf {

/// The two real roots of a·t² + 2·h·t + c = 0, sorted: t0 ≤ t1.
struct QuadraticRoots {
    double t0;
    double t1;
};

/// Roots of a·t² + 2·h·t + c = 0 (the "half-b" form) from sqrtDisc = √(h² − a·c) > 0 and
/// a ≠ 0. q = −(h + sign(h)·√disc) never cancels, and the roots are q/a and c/q (Vieta), so
/// the root of small magnitude does not come from subtracting nearly equal numbers either.
/// sqrtDisc > 0 guarantees q ≠ 0; h = ±0 is fine (copysign keeps q away from 0).
inline QuadraticRoots solveQuadraticHalf(double a, double h, double c, double sqrtDisc) {
    const double q = -(h + std::copysign(sqrtDisc, h));
    const double r0 = q / a;
    const double r1 = c / q;
    return r0 <= r1 ? QuadraticRoots{r0, r1} : QuadraticRoots{r1, r0};
}

}  // namespace kerf
