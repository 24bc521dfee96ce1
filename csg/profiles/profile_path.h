/// @file csg/profiles/profile_path.h
/// @brief Closed 2-D outlines as drawn: loops of line segments, circular arcs and quadratic
/// and cubic Bézier segments, kept exactly (never flattened). Polygons, `path { … }` and text
/// glyphs (FreeType's outlines) are all PathShapes; csg/profiles/profile_field.h makes one a signed
/// distance field in the plane, the leaf of every 2-D profile that is not a closed form.
#pragma once

#include "csg/types.h"

#include <array>
#include <cstdint>
#include <vector>

namespace kerf {

using Vec2 = glm::dvec2;

struct PathSegment {
    enum class Kind : uint8_t { Line, Quadratic, Cubic, Arc };
    Kind kind = Kind::Line;
    /// Line: p[0] → p[1]. Quadratic: p[0], control p[1], p[2]. Cubic: p[0], p[1], p[2], p[3].
    /// Arc: from p[0] to p[1] around the centre p[2] (both ends at the same distance from it),
    /// counter-clockwise when `ccw`, and never more than a full turn.
    std::array<Vec2, 4> p{};
    bool ccw = true;

    Vec2 start() const { return p[0]; }
    Vec2 end() const { return kind == Kind::Quadratic ? p[2] : kind == Kind::Cubic ? p[3] : p[1]; }
};

/// A closed loop: each segment starts where the one before ends, the last ends at the first's
/// start.
struct PathLoop {
    std::vector<PathSegment> segments;
};

/// Loops filled by the even-odd rule (a point is inside when a ray from it crosses the loops
/// an odd number of times), so holes need no orientation.
struct PathShape {
    std::vector<PathLoop> loops;
};

}  // namespace kerf
