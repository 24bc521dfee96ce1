/// @file csg/primitives/clear_bound.h
/// @brief A bound for a solid {f ≤ 0} that its surface provably does not reach: a box on
/// whose faces interval evaluation proves f > 0. An implicit primitive is clipped to its
/// box; when no face of the box meets the solid, the clip adds no face of its own and the
/// surface inside is exactly the zero set. Used for displaced solids (lang/lower_displace.cpp),
/// whose surface moves out of the undisplaced solid's bounds by an amount only f can tell.
#pragma once

#include "csg/tape/tape.h"
#include "csg/types.h"

#include <optional>

namespace kerf {

/// Whether f > 0 (and never NaN) at every point of the box's six faces, proved by interval
/// evaluation over subdivisions of each face, with at most `budget` evaluations in all.
bool facesClear(const Tape& f, const Bounds3& box, int budget);

/// `inner` grown on every side by margin·2ᵏ for the first k in 0 … maxDoublings whose box
/// facesClear proves; nullopt when none does (or inner is empty or not finite).
std::optional<Bounds3> grownClearBound(const Tape& f, const Bounds3& inner, double margin,
                                       int maxDoublings, int budgetPerTry);

}  // namespace kerf
