// The rows of the node-kind registry (csg/tree/kind_registry.h), in the order of NodeKind: the
// hand-written kinds here, then the primitives of csg/tree/primitive_rows.def.
#include "csg/tree/kind_registry.h"

#include <iterator>

namespace kerf {
namespace {

// Columns: kind, name, leaf, rootFound, octreeLeaf, ownWalk, surface, csgOperand.
constexpr KindTraits kRows[] = {
    {NodeKind::Sphere, "sphere", true, false, false, false, false, true},
    {NodeKind::Box, "box", true, false, false, false, false, true},
    {NodeKind::Cylinder, "cylinder", true, false, false, false, false, true},
    {NodeKind::Cone, "cone", true, false, false, false, false, true},
    {NodeKind::Torus, "torus", true, true, false, false, false, true},
    {NodeKind::HalfSpace, "halfspace", true, false, false, false, false, true},
    {NodeKind::Implicit, "implicit", true, true, true, false, false, true},
    {NodeKind::Volume, "volume", true, false, false, true, false, true},
    {NodeKind::Mesh, "mesh", true, false, false, true, false, true},
    {NodeKind::Transform, "transform", false, false, false, false, false, true},
    {NodeKind::Material, "material", false, false, false, false, false, true},
    {NodeKind::Motion, "motion", false, false, false, false, false, true},
    {NodeKind::Union, "union", false, false, false, false, false, true},
    {NodeKind::Intersection, "intersection", false, false, false, false, false, true},
    {NodeKind::Difference, "difference", false, false, false, false, false, true},
    {NodeKind::Xor, "xor", false, false, false, false, false, true},
    {NodeKind::Disc, "disc", true, false, false, false, true, false},
    {NodeKind::Triangle, "triangle", true, false, false, false, true, false},
    {NodeKind::OpenCone, "open cone", true, false, false, false, true, false},
    {NodeKind::SurfaceOf, "surface", false, false, false, false, true, false},
    {NodeKind::Clip, "clip", false, false, false, false, true, false},
    {NodeKind::Interior, "interior", false, false, false, false, false, true},
#define KERF_PRIMITIVE(Kind, keyword, rootFound, fields, factoryParameters) \
    {NodeKind::Kind, keyword, true, rootFound, false, false, false, true},
#include "csg/tree/primitive_rows.def"
#undef KERF_PRIMITIVE
};

/// The rows are indexed by kind: each row's position must be its kind's value.
constexpr bool rowsInKindOrder() {
    for (size_t i = 0; i < std::size(kRows); ++i)
        if (size_t(kRows[i].kind) != i) return false;
    return true;
}
static_assert(rowsInKindOrder(), "kRows must list every NodeKind in enum order");

}  // namespace

const KindTraits& kindTraits(NodeKind kind) { return kRows[size_t(kind)]; }
const KindTraits* allKindTraits() { return kRows; }
size_t kindCount() { return std::size(kRows); }

const char* nodeKindName(NodeKind kind) { return kindTraits(kind).name; }
bool isLeaf(NodeKind kind) { return kindTraits(kind).leaf; }
bool isSurfaceKind(NodeKind kind) { return kindTraits(kind).surface; }

}  // namespace kerf
