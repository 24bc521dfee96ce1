/// @file io/outline_overlap.h
/// @brief Whether two filled outlines may share a point: neighbouring glyphs overlap in
/// italics and tight kerning pairs, and one even-odd shape of both would show the overlap as
/// a hole. The answer is never a false "no"; it is "yes" for outlines that touch or come
/// within rounding of each other.
#pragma once

#include "csg/profiles/profile_path.h"

namespace kerf {

/// True when the filled regions (even-odd) of `a` and `b` may share a point: their outlines
/// cross or touch (found by subdividing Bézier control polygons while their boxes meet), or
/// a loop of one lies inside the other. Arcs are taken as their control boxes (conservative).
bool outlinesMayOverlap(const PathShape& a, const PathShape& b);

/// Even-odd inside test by crossings of the ray from `q` toward +x; arcs are not supported
/// (glyphs have none) and count as no crossing.
bool insideEvenOdd(const PathShape& shape, Vec2 q);

}  // namespace kerf
