// Lowering, part 3e: surfaces (csg/primitives/surfaces.h): `disc`, `triangle`, `cylinder`/`cone`
// with `open true` (lower_solids.cpp), `surface SOLID`, `clip SURFACE by SOLID` and the `interior`
// modifier. A surface has no inside, so it is refused wherever a solid is needed, through the
// same check as open meshes (checkSolidOperands, lower_mesh.cpp).
#include "lang/lower.h"

#include "csg/primitives/surfaces.h"

#include <cmath>

namespace kerf {

namespace {

/// The surface-kind node under transforms, materials, motions and interiors, or null.
const Node* surfaceBelow(const Node* node) {
    while (node) {
        const NodeKind k = node->kind();
        if (isSurfaceKind(k)) return node;
        if (k != NodeKind::Transform && k != NodeKind::Material && k != NodeKind::Motion &&
            k != NodeKind::Interior)
            return nullptr;
        node = node->children()[0].get();
    }
    return nullptr;
}

const char* describeSurface(const Node& n) {
    switch (n.kind()) {
        case NodeKind::Disc: return "disc";
        case NodeKind::Triangle: return "triangle";
        case NodeKind::OpenCone: return "open cylinder or cone";
        case NodeKind::SurfaceOf: return "'surface'";
        default: return "'clip'";
    }
}

}  // namespace

NodePtr Lowering::noteSurface(NodePtr surface, SourcePos at) {
    if (surface) mSurfaces.emplace(surface.get(), std::make_pair(surface, at));
    return surface;
}

NodePtr Lowering::lowerSurface(const Solid& s) {
    if (s.name == "disc") return lowerDisc(s);
    if (s.name == "triangle") return lowerTriangle(s);
    if (s.name == "surface") {
        NodePtr solid = lowerSolid(s.children[0]);
        if (!solid || solid == emptySolid()) return nullptr;
        if (!checkSolidOperands({solid}, "the operand of 'surface'", s.loc)) return nullptr;
        return noteSurface(limitDepth(makeSurfaceOf(std::move(solid)), s.loc), s.loc);
    }
    // clip SURFACE by SOLID
    NodePtr surface = lowerSolid(s.children[0]);
    NodePtr solid = lowerSolid(s.children[1]);
    if (!surface || !solid || surface == emptySolid() || solid == emptySolid()) return nullptr;
    if (!isSurfaceTree(*surface)) {
        error(s.children[0].loc, "clip cuts a surface, but this is a solid",
              "to clip a solid's boundary write 'clip surface SOLID by …'; to cut a solid use "
              "intersection");
        return nullptr;
    }
    if (!checkSolidOperands({solid}, "what 'clip' cuts by", s.loc)) return nullptr;
    return noteSurface(limitDepth(makeClip(std::move(surface), std::move(solid)), s.loc), s.loc);
}

NodePtr Lowering::lowerDisc(const Solid& s) {
    const PropertyBlock b(s.properties,
                          {{"center", PropertyType::Vector},
                           {"normal", PropertyType::Vector},
                           {"radius", PropertyType::Number},
                           {"inner", PropertyType::Number}},
                          "disc", s.loc, mSink);
    Vec3 center(0.0), normal(0.0, 1.0, 0.0);
    double radius = 1.0, inner = 0.0;
    bool ok = b.ok();
    ok &= readVector(b, "center", center);
    ok &= readVector(b, "normal", normal);
    ok &= readNumber(b, "radius", radius);
    ok &= readNumber(b, "inner", inner);
    if (!ok) return nullptr;
    if (!(radius > 0) || !std::isfinite(radius)) {
        error(b.find("radius")->valueLoc(),
              "disc radius must be positive and finite, got " + formatNumber(radius));
        return nullptr;
    }
    if (!(inner >= 0 && inner < radius)) {
        error(b.find("inner")->valueLoc(),
              "disc inner radius must be at least 0 and less than the radius " +
                  formatNumber(radius) + ", got " + formatNumber(inner));
        return nullptr;
    }
    if (!allFinite(center)) {
        error(b.find("center")->valueLoc(),
              "disc center is not finite, got " + formatVector(center));
        return nullptr;
    }
    if (!allFinite(normal) || !(glm::length(normal) > 0) || !std::isfinite(glm::length(normal))) {
        error(b.find("normal") ? b.find("normal")->valueLoc() : s.loc,
              "disc normal must be a finite, non-zero vector, got " + formatVector(normal));
        return nullptr;
    }
    return noteSurface(makeDisc(center, normal, radius, inner), s.loc);
}

NodePtr Lowering::lowerTriangle(const Solid& s) {
    const PropertyBlock b(s.properties,
                          {{"a", PropertyType::Vector, true},
                           {"b", PropertyType::Vector, true},
                           {"c", PropertyType::Vector, true}},
                          "triangle", s.loc, mSink);
    Vec3 p[3];
    bool ok = b.ok();
    ok &= readVector(b, "a", p[0]);
    ok &= readVector(b, "b", p[1]);
    ok &= readVector(b, "c", p[2]);
    if (!ok) return nullptr;
    for (int i = 0; i < 3; ++i)
        if (!allFinite(p[i])) {
            error(s.loc, std::string("triangle corner ") + char('a' + i) + " is not finite, got " +
                             formatVector(p[i]));
            return nullptr;
        }
    const Vec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
    if (!(glm::length(n) > 0) || !std::isfinite(glm::length(n))) {
        error(s.loc, "triangle has no area: its corners " + formatVector(p[0]) + ", " +
                         formatVector(p[1]) + " and " + formatVector(p[2]) + " are on one line");
        return nullptr;
    }
    return noteSurface(makeTriangle(p[0], p[1], p[2]), s.loc);
}

bool Lowering::checkSurfaceOperands(const std::vector<NodePtr>& operands, const std::string& use,
                                    SourcePos at) {
    if (mSurfaces.empty()) return true;  // no surface made: nothing to look for
    bool ok = true;
    for (const NodePtr& operand : operands) {
        const Node* surface = surfaceBelow(operand.get());
        if (!surface) continue;
        ok = false;
        const auto it = mSurfaces.find(surface);
        const SourcePos where = it != mSurfaces.end() ? it->second.second : at;
        const SourceLoc used = mSink.locate(at);
        error(where,
              std::string("this ") + describeSurface(*surface) +
                  " is a surface, not a solid: it has no inside and cannot be " + use + " (line " +
                  std::to_string(used.line) + ", column " + std::to_string(used.col) + ")",
              "to keep the part of a surface inside a solid write 'clip SURFACE by SOLID'; a "
              "solid's boundary "
              "as a surface is 'surface SOLID'");
    }
    return ok;
}

NodePtr Lowering::interiorOf(const NodePtr& node, int32_t material) {
    if (node->kind() == NodeKind::Material)  // below it: a material fills what interior leaves
        return node->withChildren({interiorOf(node->children()[0], material)});
    return makeInterior(node, material);
}

}  // namespace kerf
