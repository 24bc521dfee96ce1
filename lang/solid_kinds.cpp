// The rows of the language's kinds of solid (lang/solid_kinds.h). A new primitive is one row
// here: its keyword, its properties with their defaults and checks, and its factory.
#include "lang/solid_kinds.h"

#include "csg/tree/solids.h"
#include "lang/lower.h"

namespace kerf {
namespace {

using PT = PropertyType;

constexpr unsigned kPrimitive = kReserved | kSolidValue | kNeedsBlock | kListed;
constexpr unsigned kBooleanUses = kPrimitive | kBoolean;

}  // namespace

/// Builds the rows; a friend of Lowering, whose lowering functions the custom rows name.
struct SolidKindRows {
    static std::vector<SolidKind> build();
    static std::vector<SolidKind> primitives();  ///< sphere … implicit
    static std::vector<SolidKind> others();      ///< profiles, Booleans, meshes, surfaces, …
};

std::vector<SolidKind> SolidKindRows::build() {
    std::vector<SolidKind> rows = primitives();
    for (SolidKind& row : others()) rows.push_back(std::move(row));
    return rows;
}

std::vector<SolidKind> SolidKindRows::primitives() {
    return {
        {"sphere",
         NodeKind::Sphere,
         kPrimitive,
         {{"center", PT::Vector}, {"radius", PT::Number, false, 1.0, {}, PropertyCheck::Positive}},
         nullptr,
         [](const PropertyValues& v) { return makeSphere(v[0].vector, v[1].number); },
         nullptr,
         {"center", "radius"},
         {"<x, y, z>", "r"}},
        {"box",
         NodeKind::Box,
         kPrimitive,
         {},
         nullptr,
         nullptr,
         &Lowering::lowerBox,
         {"min", "max"},
         {"<x0, y0, z0>", "<x1, y1, z1>"}},
        {"cylinder",
         NodeKind::Cylinder,
         kPrimitive,
         {},
         nullptr,
         nullptr,
         &Lowering::lowerCylinder,
         {"from", "to", "radius"},
         {"<x0, y0, z0>", "<x1, y1, z1>", "r"}},
        {"cone",
         NodeKind::Cone,
         kPrimitive,
         {},
         nullptr,
         nullptr,
         &Lowering::lowerCone,
         {"from", "radius1", "to", "radius2"},
         {"<x0, y0, z0>", "r1", "<x1, y1, z1>", "r2"}},
        {"torus",
         NodeKind::Torus,
         kPrimitive,
         {},
         nullptr,
         nullptr,
         &Lowering::lowerTorus,
         {"major", "minor"},
         {"R", "r"}},
        {"halfspace",
         NodeKind::HalfSpace,
         kPrimitive,
         {},
         nullptr,
         nullptr,
         &Lowering::lowerHalfSpace,
         {"normal", "offset"},
         {"<nx, ny, nz>", "d"}},
        {"implicit",
         NodeKind::Implicit,
         kPrimitive,
         {},
         nullptr,
         nullptr,
         &Lowering::lowerImplicit},
    };
}

std::vector<SolidKind> SolidKindRows::others() {
    return {
        {"extrude",
         NodeKind::Implicit,
         kSolidValue | kListed,
         {},
         nullptr,
         nullptr,
         &Lowering::lowerExtrude},
        {"revolve",
         NodeKind::Implicit,
         kSolidValue | kListed,
         {},
         nullptr,
         nullptr,
         &Lowering::lowerRevolve},
        {"union", NodeKind::Union, kBooleanUses},
        {"intersection", NodeKind::Intersection, kBooleanUses},
        {"difference", NodeKind::Difference, kBooleanUses},
        {"xor", NodeKind::Xor, kBooleanUses},
        // Parsed by their own rules (lang/parse_volume.cpp, parse_surfaces.cpp).
        {"mesh", NodeKind::Mesh, kReserved, {}, nullptr, nullptr, &Lowering::lowerMesh},
        {"volume", NodeKind::Volume, 0, {}, nullptr, nullptr, &Lowering::lowerVolume},
        {"disc", NodeKind::Disc, kSolidValue, {}, nullptr, nullptr, &Lowering::lowerSurface},
        {"triangle",
         NodeKind::Triangle,
         kSolidValue,
         {},
         nullptr,
         nullptr,
         &Lowering::lowerSurface},
        {"surface", NodeKind::SurfaceOf, 0, {}, nullptr, nullptr, &Lowering::lowerSurface},
        {"clip", NodeKind::Clip, 0, {}, nullptr, nullptr, &Lowering::lowerSurface},
        // Not kListed: the list of solids in messages is fixed by tests/lang/ (see
        // docs/architecture.md, "Adding a kind of solid").
        {"capsule",
         NodeKind::Capsule,
         kReserved | kSolidValue | kNeedsBlock,
         {{"from", PT::Vector, true},
          {"to", PT::Vector, true},
          {"radius", PT::Number, false, 1.0, {}, PropertyCheck::Positive}},
         [](const PropertyValues& v) { return axisProblem("capsule", v[0].vector, v[1].vector); },
         [](const PropertyValues& v) {
             return makeCapsule(v[0].vector, v[1].vector, v[2].number);
         }},
    };
}

const std::vector<SolidKind>& solidKinds() {
    static const std::vector<SolidKind> rows = SolidKindRows::build();
    return rows;
}

const SolidKind* findSolidKind(const std::string& keyword) {
    for (const SolidKind& k : solidKinds())
        if (keyword == k.keyword) return &k;
    return nullptr;
}

std::vector<std::string> solidKeywords(SolidUse use, bool booleans) {
    std::vector<std::string> out;
    for (const SolidKind& k : solidKinds())
        if (k.has(use) && (booleans || !k.has(kBoolean))) out.push_back(k.keyword);
    return out;
}

}  // namespace kerf
