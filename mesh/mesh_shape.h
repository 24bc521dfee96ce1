/// @file mesh/mesh_shape.h
/// @brief A loaded mesh ready for tracing: its triangles, their BVH, its validation report
/// (mesh/half_edges.h), and its implicit form as a field (csg/tape/scalar_field.h): the signed
/// distance to the triangles for a solid (negative inside, by the parity of a ray's crossings,
/// which the watertight test makes exact), the unsigned distance for an open surface.
/// One shape is shared by every instance of its file in a scene.
#pragma once

#include "csg/tape/scalar_field.h"
#include "csg/tree/node_kind.h"
#include "mesh/half_edges.h"
#include "mesh/triangle_bvh.h"

#include <memory>
#include <string>

namespace kerf {

class MeshShape final : public ScalarField {
public:
    /// Validates the mesh and builds its BVH.
    explicit MeshShape(TriangleMesh mesh);

    const TriangleMesh& mesh() const { return mMesh; }
    const TriangleBvh& bvh() const { return mBvh; }
    const MeshReport& report() const { return mReport; }
    /// Closed, 2-manifold and consistently oriented: it can be a CSG operand.
    bool isSolid() const { return mReport.solid; }
    const std::string& source() const { return mMesh.source; }
    /// The outward normal of the triangle: (p1 − p0) × (p2 − p0), not normalised.
    Vec3 faceNormal(uint32_t triangle) const;
    /// The normal to shade with at a point p of the triangle: the vertex normals interpolated
    /// when `smooth` and the mesh has them (turned to the face normal's side), else the face
    /// normal. Unit length.
    Vec3 shadingNormal(uint32_t triangle, const Vec3& p, bool smooth) const;

    /// Whether p is inside the solid: an odd number of crossings along a ray from p.
    /// (For an open mesh: false.)
    bool inside(const Vec3& p) const;
    /// Distance from p to the nearest triangle.
    double distance(const Vec3& p) const;

    // ScalarField: the signed distance (the unsigned one for an open mesh).
    double value(const Vec3& p) const override;
    long double valueExtended(const glm::tvec3<long double>& p) const override;
    double valueGradient(const Vec3& p, Vec3& gradient) const override;
    Interval range(const Interval& x, const Interval& y, const Interval& z) const override;

private:
    TriangleMesh mMesh;
    TriangleBvh mBvh;
    MeshReport mReport;
};

/// loadMesh (mesh/mesh_loader.h) and the shape built over it. Throws MeshError.
std::shared_ptr<const MeshShape> loadMeshShape(const std::string& path);

/// The mesh as a leaf of a solid tree (NodeKind::Mesh). A solid mesh has spans like any
/// primitive; an open one is a surface: zero-width spans at its crossings, which render and
/// cast shadows, but must not be a CSG operand (lang/ refuses it, naming the first bad edge).
NodePtr meshNode(std::shared_ptr<const MeshShape> shape, bool smooth);

}  // namespace kerf
