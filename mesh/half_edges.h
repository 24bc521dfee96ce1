/// @file mesh/half_edges.h
/// @brief Connectivity of a triangle mesh by half-edges (Shirley et al., Fundamentals of
/// Computer Graphics, §12.1.4) and the validation built on it: is the mesh a solid (closed,
/// 2-manifold along its edges, consistently oriented), and if not, what is wrong and where.
///
/// Topology is by position: vertices at exactly the same position are one vertex here even
/// when the mesh keeps them apart for different normals or UVs (a cube with hard edges).
#pragma once

#include "mesh/triangle_mesh.h"

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace kerf {

/// Half-edge h belongs to triangle h / 3 and runs from its corner h % 3 to the next corner,
/// so `next` is implicit: 3 * (h / 3) + (h + 1) % 3.
struct HalfEdges {
    static constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
    std::vector<uint32_t> weld;    ///< mesh vertex -> the first mesh vertex at its position
    std::vector<uint32_t> origin;  ///< half-edge -> welded vertex it starts from
    /// half-edge -> the opposite half-edge of the one other triangle on its edge, or kNone when
    /// the edge is a boundary, non-manifold, inconsistently oriented or in a degenerate triangle
    std::vector<uint32_t> twin;

    static uint32_t next(uint32_t h) { return 3 * (h / 3) + (h + 1) % 3; }
};

/// What is wrong with an edge, for the first bad edge of a report.
enum class EdgeFault { Boundary, NonManifold, Inconsistent };

struct BadEdge {
    EdgeFault fault;
    uint32_t a, b;  ///< mesh vertex indices, in the direction of the first triangle using it
    Vec3 pa, pb;    ///< their positions
};

struct MeshReport {
    size_t vertices = 0;  ///< distinct positions used by triangles
    size_t triangles = 0;
    size_t boundaryEdges = 0;        ///< edges of exactly one triangle
    size_t nonManifoldEdges = 0;     ///< edges of more than two triangles
    size_t inconsistentEdges = 0;    ///< edges of two triangles that run it the same way
    size_t degenerateTriangles = 0;  ///< a repeated vertex, or zero area
    /// closed, 2-manifold, consistently oriented, with at least one triangle
    bool solid = false;
    std::optional<BadEdge> firstBadEdge;  ///< in triangle order, for messages
};

/// Builds the half-edges, linking twins through a hash of the directed edge. Triangles with a
/// repeated (welded) vertex take no part in the links: their half-edges have no twin.
/// Both functions throw std::out_of_range for an index past the positions (loadMesh never
/// returns one).
HalfEdges buildHalfEdges(const TriangleMesh& mesh);

/// Counts what `MeshReport` lists.
MeshReport validateMesh(const TriangleMesh& mesh);

/// "boundary", "non-manifold" or "inconsistently oriented", for messages.
const char* edgeFaultName(EdgeFault fault);

/// One line naming the first bad edge: its fault, vertex indices and positions.
std::string describeBadEdge(const BadEdge& edge);

}  // namespace kerf
