/// @file bench/reference/ref_spans.h
/// @brief The oracle's ray casting: the exact spans (inside intervals of t over the whole line)
/// of each closed-form primitive in long double, combined by its own CSG sweep. It shares no
/// code with kerf's csg/.
#pragma once

#include "ref_scene.h"

#include <utility>
#include <vector>

namespace kerf::bench {

/// Sorted, disjoint [enter, exit] intervals of t where the ray is inside a solid.
using RefSpans = std::vector<std::pair<Real, Real>>;

/// Spans of `node` along o + t d, t over the whole real line.
RefSpans spansOf(const RefNode& node, V3 o, V3 d);

/// The span of the nearest entering boundary with t > 0 over all objects, as distances along
/// the unit direction `d` from `eye`: {+inf, +inf} if there is none.
std::pair<Real, Real> nearestHit(const std::vector<RefNode>& objects, V3 eye, V3 d);

/// Real roots of c[0] + c[1] s + ... + c[degree] s^degree in [lo, hi], ascending: every sign
/// change is isolated between the roots of the derivative and bisected to full precision.
/// Exposed for the self-test.
int polynomialRoots(const Real* c, int degree, Real lo, Real hi, Real* roots);

}  // namespace kerf::bench
