/// @file csg/profiles/path_normals.h
/// @brief Where one curved segment (a Bézier or an arc) is the only outline near a box, the
/// signed distance's gradient over the box is the outline's outward normal at the feet of
/// its points, and those normals turn through a small angle: this file bounds that angle, so
/// slicing and root isolation can prove a curved boundary simple instead of splitting along
/// it down to the tolerance. Internal to csg/ (csg/profiles/profile_field.cpp uses it).
#pragma once

#include "csg/interval/interval.h"
#include "csg/profiles/path_geometry.h"

namespace kerf::path_geometry {

/// The unit normals of a part of a segment, as Nearest::normal gives them (a Bézier's
/// tangent turned by +90°; an arc's toward its centre), as the angles [lo, hi] (radians,
/// hi − lo < π), and a box holding that part.
struct NormalSector {
    double lo = 0.0;
    double hi = 0.0;
    Bounds2 partBox;
};

/// The sector of normals of the part of curved segment `s` that comes within `reach` of
/// `c`, and the radius `clear` of a disc around c that holds that part while no other part
/// of `s` enters it (so nothing of `s` crosses the part). False when that cannot be proven:
/// an end of `s` within reach, a part that turns by π or more, a line segment.
bool nearNormalSector(const Segment& s, Vec2 c, double reach, NormalSector& sector, double& clear);

/// Component enclosures of the unit vectors whose angles lie in [lo, hi] (hi − lo < 2π).
void sectorBox(double lo, double hi, Interval& x, Interval& y);

}  // namespace kerf::path_geometry
