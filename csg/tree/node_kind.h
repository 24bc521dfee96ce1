/// @file csg/tree/node_kind.h
/// @brief What a walker outside csg/ can learn about a node without knowing its class: its
/// kind, its children (csg/tree/node.h) and the parameters that define it, as the factories in
/// csg/tree/solids.h took them.
#pragma once

#include "csg/tree/span.h"
#include "csg/types.h"

#include <cstdint>
#include <memory>
#include <variant>

namespace kerf {

class Node;
class Tape;
class MeshShape;     // mesh/mesh_shape.h
class LevelSetGrid;  // volume/grids/level_set_grid.h
using NodePtr = std::shared_ptr<const Node>;

/// Every kind of node. Boolean nodes have one kind per operator.
// clang-format off: grouped by arity
enum class NodeKind : uint8_t {
    Sphere,
    Box,
    Cylinder,
    Cone,
    Torus,
    HalfSpace,
    Implicit,
    Volume,
    Mesh,  // leaves
    Transform,
    Material,
    Motion,  // one child
    Union,
    Intersection,
    Difference,
    Xor,  // one or more children
    // Surfaces (csg/primitives/surfaces.h): open sheets, never CSG operands. Leaves, then
    // `surface` (one child), `clip` (surface, solid) and the `interior` modifier (one child).
    Disc,
    Triangle,
    OpenCone,
    SurfaceOf,
    Clip,
    Interior,
// Primitives added as rows (csg/tree/primitive_rows.def): appended, so the kinds above
// keep their values.
#define KERF_PRIMITIVE(Kind, keyword, rootFound, fields, factoryParameters) Kind,
#include "csg/tree/primitive_rows.def"
#undef KERF_PRIMITIVE
};
// clang-format on

// The three below read the kind's row in csg/tree/kind_registry.cpp.
/// "sphere", "box", …, "xor": the language's keywords for the kinds.
const char* nodeKindName(NodeKind kind);
/// True for the primitives (nodes without children).
bool isLeaf(NodeKind kind);
/// True for the kinds that make a surface rather than a solid (csg/primitives/surfaces.h).
bool isSurfaceKind(NodeKind kind);
/// The Boolean kind of an operator, and back.
NodeKind booleanKind(BoolOp op);
BoolOp booleanOp(NodeKind kind);  ///< kind must be Union, Intersection, Difference or Xor

struct SphereParams {
    Vec3 center;
    double radius;
};
struct BoxParams {
    Vec3 lo, hi;
};
struct CylinderParams {
    Vec3 a, b;
    double radius;
};
struct ConeParams {
    Vec3 a, b;
    double r1, r2;
};
struct TorusParams {
    double majorRadius, minorRadius;
};
struct HalfSpaceParams {
    Vec3 normal;
    double offset;
};
struct ImplicitParams {
    std::shared_ptr<const Tape> tape;
    Bounds3 bound;
};
/// A triangle mesh, loaded once and shared by every instance; `smooth` shades with the
/// vertex normals where the file has them.
struct MeshParams {
    std::shared_ptr<const MeshShape> shape;
    bool smooth;
};
/// A level set read from a .vdb file (volume/grids/level_set_grid.h), in the grid's index space.
struct VolumeParams {
    std::shared_ptr<const LevelSetGrid> grid;
};
/// The map and the inverse the node keeps (computed once, with care for rounding).
struct TransformParams {
    Affine worldFromLocal;
    Affine localFromWorld;
};
struct MaterialParams {
    int32_t material;
};
struct BooleanParams {
    BoolOp op;
};
/// Over scene time s in [0, 1] the child turns by spin·s degrees (as rotate) and then moves by
/// velocity·s (csg/tree/motion.h).
struct MotionParams {
    Vec3 velocity;
    Vec3 spin;
};
/// A flat ring: the points of the plane through center, normal n, with inner ≤ |p − c| ≤ radius.
struct DiscParams {
    Vec3 center;
    Vec3 normal;
    double radius;
    double inner;
};
/// A triangle; its front faces (b − a) × (c − a).
struct TriangleParams {
    Vec3 a, b, c;
};
/// The side of a cone (or, r1 = r2, a cylinder) without its caps.
struct OpenConeParams {
    Vec3 a, b;
    double r1, r2;
};
/// `surface` and `clip`: nothing besides their children.
struct SurfaceParams {};
/// The material seen from a surface's back, or from inside a solid.
struct InteriorParams {
    int32_t material;
};

#define KERF_UNPARENTHESIZE(...) __VA_ARGS__
#define KERF_PRIMITIVE(Kind, keyword, rootFound, fields, factoryParameters) \
    struct Kind##Params {                                                   \
        KERF_UNPARENTHESIZE fields                                          \
    };
#include "csg/tree/primitive_rows.def"
#undef KERF_PRIMITIVE

/// A node's defining data: the alternative matches its kind (all four Boolean kinds give
/// BooleanParams). Passing it back to the factory of its kind rebuilds an equal node.
using NodeParams =
    std::variant<SphereParams, BoxParams, CylinderParams, ConeParams, TorusParams, HalfSpaceParams,
                 ImplicitParams, MeshParams, TransformParams, MaterialParams, BooleanParams,
                 MotionParams, DiscParams, TriangleParams, OpenConeParams, SurfaceParams,
                 InteriorParams, VolumeParams
#define KERF_PRIMITIVE(Kind, keyword, rootFound, fields, factoryParameters) , Kind##Params
#include "csg/tree/primitive_rows.def"
#undef KERF_PRIMITIVE
                 >;

/// A node's children: a view of the NodePtrs it holds, valid while the node lives.
class NodeSpan {
public:
    NodeSpan() = default;
    NodeSpan(const NodePtr* data, size_t size) : mData(data), mSize(size) {}
    size_t size() const { return mSize; }
    bool empty() const { return mSize == 0; }
    const NodePtr& operator[](size_t i) const { return mData[i]; }
    const NodePtr* begin() const { return mData; }
    const NodePtr* end() const { return mData + mSize; }

private:
    const NodePtr* mData = nullptr;
    size_t mSize = 0;
};

}  // namespace kerf
