/// @file render/section_cut.h
/// @brief Section views: the scene's objects cut by its section planes (issue 11 §3).
///
/// Each cut object becomes intersection { object, the kept half-spaces }, every half-space
/// under a material of its plane's colour. The cap is then no special case: it is the
/// half-space's boundary where the ray enters the object's inside at the plane, so camera,
/// shadow and reflected rays, the BVH, the octree and the beams all see the cut model.
#pragma once

#include "scene/scene.h"

namespace kerf {

/// The scene with its objects cut by `scene.sections` (the side each normal points to
/// removed). One cap material per plane is appended to the materials. An object that interval
/// arithmetic over its bounds proves entirely on a removed side is dropped (with its flags);
/// one entirely on the kept side of a plane is not wrapped for that plane, and one on the kept
/// side of every plane is the very same tree, so its pixels keep their bits.
Scene cutBySections(const Scene& scene);

}  // namespace kerf
