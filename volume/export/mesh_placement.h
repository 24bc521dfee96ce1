/// @file volume/export/mesh_placement.h
/// @brief Moving the vertices of OpenVDB's mesh onto the true surface. OpenVDB places a vertex
/// from its cell's interpolated samples, which rounds off sharp CSG edges. Here each vertex
/// alone in its cell gets its cell's exact crossings (root found along the cell's edges) and
/// their normals; where the normals span a crease (dual contouring's quadric has rank 2 or 3)
/// the vertex goes to the quadric's minimum, on the edge or corner, if that lies within half a
/// voxel of the cell and within a tenth of a voxel of the surface (first order). Otherwise the
/// vertex moves to the surface along the gradient, at most one voxel; where that finds no crossing
/// it stays. Moves are bounded, so no triangle folds over its neighbours.
#pragma once

#include "volume/export/mesh_field.h"

#include <vector>

namespace kerf {

/// Root-finding tolerance of vertex placement, as a fraction of the voxel.
constexpr double kPlacementRootTolerance = 1e-9;

struct PlacementStats {
    uint64_t features = 0;   ///< placed on an edge or corner by the quadric
    uint64_t projected = 0;  ///< moved onto the surface along the gradient
    uint64_t kept = 0;       ///< left where OpenVDB put them (no crossing found)
    uint64_t unpinched = 0;  ///< crease points given up for edges of four faces (mesh_unpinch.h)
};

/// `points` are in lattice index space on entry and in model space on return.
void placeVertices(const SampledField& field, std::vector<Vec3>& points, PlacementStats& stats);

/// Appends two triangles per quad (model space points, counter-clockwise), split along the
/// diagonal whose midpoint is nearer the surface (first-order |f|/|∇f|), so a quad that
/// straddles a crease folds along it rather than cutting it off.
void splitQuads(const SampledField& field, const std::vector<Vec3>& points,
                const std::vector<std::array<uint32_t, 4>>& quads,
                std::vector<std::array<uint32_t, 3>>& triangles);

/// Lattice index space to model space.
inline Vec3 modelFromIndex(const MeshLattice& l, const Vec3& i) { return l.origin + i * l.voxel; }

}  // namespace kerf
