/// @file csg/profiles/bernstein.h
/// @brief Polynomials on [0, 1] in Bernstein form (degree at most 6), and where they change
/// class (> 0 or not): the crossings of a ray with a turned Bézier (csg/profiles/lathe.cpp).
/// The coefficients' sign changes bound the roots (Descartes' rule in Bernstein form): none,
/// no root; one, exactly one; more, split in half and look again.
#pragma once

#include <array>
#include <cstdlib>
#include <vector>

namespace kerf {

constexpr int kMaxBernsteinDegree = 6;
using BernsteinCoefficients = std::array<double, kMaxBernsteinDegree + 1>;

/// The value at s (de Casteljau).
inline double bernsteinValue(const BernsteinCoefficients& c, int degree, double s) {
    BernsteinCoefficients b = c;
    for (int r = 1; r <= degree; ++r)
        for (int i = 0; i + r <= degree; ++i) b[i] += s * (b[i + 1] - b[i]);
    return b[0];
}

/// The parameters in [0, 1] where the polynomial changes class (> 0 or not), each once: the
/// end values are c[0] and c[degree] as given, so two polynomials that share an end value
/// agree on that end's class.
void bernsteinClassChanges(const BernsteinCoefficients& c, int degree, std::vector<double>& out);

}  // namespace kerf
