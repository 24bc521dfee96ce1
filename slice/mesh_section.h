/// @file slice/mesh_section.h
/// @brief The exact section of an object that is one closed mesh (under transforms and
/// materials): each triangle the plane crosses gives one segment between the points where it
/// cuts two of its edges, and segments join into loops through the edges they share. Every
/// vertex of a loop lies on a mesh edge, computed once per edge: no tolerance, no quadtree.
/// Objects with a mesh inside CSG go through the general contouring of its distance field.
#pragma once

#include "csg/tree/node.h"
#include "io/section_writers.h"
#include "slice/plane.h"

#include <array>
#include <memory>
#include <vector>

namespace kerf {

/// A mesh placed in the scene, prepared once for every plane of a family.
struct PlacedMesh {
    std::vector<Vec3> positions;  ///< in scene space
    std::vector<uint32_t> weld;   ///< vertex → first vertex at its position
    std::vector<std::array<uint32_t, 3>> triangles;
    bool solid = false;
};

/// The mesh an object consists of (through transforms and materials only), placed; null when
/// the object is anything else (CSG, primitives, motion).
std::shared_ptr<const PlacedMesh> placedMeshOf(const Node& object);

/// The section loops at `plane` (inside on the left: outer loops counter-clockwise), in plane
/// coordinates. A vertex exactly on the plane counts as above it, so a plane through vertices
/// or along edges still gives closed loops.
std::vector<SectionLoop> meshSectionLoops(const PlacedMesh& mesh, const SlicePlane& plane);

}  // namespace kerf
