/// @file slice/section_tape.h
/// @brief An object's implicit form restricted to the planes of one family: the tree's
/// expression (csg/tape/tree_tape.h) composed with x = origin + u·U + v·V + w·N, compiled over
/// (u, v, w) as the tape's (x, y, z). A stack of parallel planes shares the one tape (w moves).
/// Also the interval enclosure of ∂f/∂u and ∂f/∂v over a cell, which proves a cell's boundary
/// simple (slice/quadtree.cpp).
#pragma once

#include "csg/tape/tape.h"
#include "csg/tree/node.h"
#include "slice/plane.h"

#include <memory>
#include <vector>

namespace kerf {

/// The tape of `node` over plane coordinates (u, v, w) of `plane`'s family.
std::shared_ptr<const Tape> sectionTape(const Node& node, const SlicePlane& plane);

/// Enclosures over a box: f and its partial derivatives in u and v (forward mode on
/// intervals; min, max and abs where undecided take the hull of their operands' derivatives,
/// which still encloses every difference quotient since these are Lipschitz). `ok` is false
/// when some op has no derivative rule here or may be undefined: nothing can be concluded.
struct IntervalSlopes {
    Interval f, du, dv;
    bool ok = false;
};

/// f, ∂f/∂u, ∂f/∂v over u × v at the plane offset w; `scratch` is reused between calls.
IntervalSlopes evalIntervalSlopes(const Tape& tape, const Interval& u, const Interval& v, double w,
                                  std::vector<Interval>& scratch);

}  // namespace kerf
