// Lowering, part 3d: `mesh "file" smooth B`, a triangle mesh read from a file (mesh/). Each
// file is loaded once per compile, whatever its transforms: every use is its own leaf over
// one shared MeshShape (one copy of the triangles, one BVH). A mesh that is not a solid (open,
// non-manifold, inconsistently oriented) renders as a surface on its own, and is refused
// wherever a solid is needed: as a Boolean operand, displaced, or cut by a section plane.
#include "lang/lower.h"

#include "csg/primitives/surfaces.h"
#include "mesh/mesh_loader.h"
#include "mesh/mesh_shape.h"

#include <filesystem>
#include <system_error>
#include <utility>

namespace kerf {

namespace {

namespace fs = std::filesystem;

/// A MeshError's message without the path it starts with (the diagnostic names the file).
std::string reasonOf(const MeshError& e, const std::string& path) {
    const std::string message = e.what();
    const std::string prefix = path + ": ";
    return message.compare(0, prefix.size(), prefix) == 0 ? message.substr(prefix.size()) : message;
}

/// The mesh leaf under transforms, materials and motions, or null. Booleans over a mesh that
/// is not a solid are never made, so a surface can only sit under one-child nodes.
const Node* meshLeafBelow(const Node* node) {
    while (node) {
        switch (node->kind()) {
            case NodeKind::Mesh: return node;
            case NodeKind::Transform:
            case NodeKind::Material:
            case NodeKind::Motion: node = node->children()[0].get(); break;
            default: return nullptr;
        }
    }
    return nullptr;
}

}  // namespace

NodePtr Lowering::lowerMesh(const Solid& s) {
    const PropertyBlock b(s.properties,
                          {{"file", PropertyType::Word, true}, {"smooth", PropertyType::Bool}},
                          "mesh", s.loc, mSink);
    bool smooth = true;
    bool ok = b.ok();
    ok &= readBool(b, "smooth", smooth);
    const Property* file = b.find("file");
    if (!ok || !file || !file->expr) return nullptr;
    const SourcePos at = file->valueLoc();
    const auto v = evaluate(*file->expr, nullptr);
    if (!v) return nullptr;
    if (v->type != Value::Type::String) {
        error(at, "mesh expects a file name in quotes, got " + typeName(v->type),
              "write e.g. 'mesh \"part.stl\"'");
        return nullptr;
    }
    if (v->string().empty()) {
        error(at, "the mesh's file name is empty");
        return nullptr;
    }
    std::shared_ptr<const MeshShape> shape = meshShape(v->string(), at);
    if (!shape) return nullptr;
    NodePtr leaf = meshNode(shape, smooth);
    if (!shape->isSolid()) mOpenMeshes.emplace(leaf.get(), std::make_pair(leaf, s.loc));
    return leaf;
}

std::shared_ptr<const MeshShape> Lowering::meshShape(const std::string& written, SourcePos at) {
    // Relative to the folder of the model file it is written in, as includes and textures are.
    const fs::path model = *mSink.locate(at).file;
    const std::string path = fs::path(written).is_absolute()
                                 ? written
                                 : (model.parent_path() / written).lexically_normal().string();
    std::error_code ec;
    fs::path canonical = fs::weakly_canonical(path, ec);
    const std::string key = ec ? path : canonical.string();
    if (const auto it = mMeshFiles.find(key); it != mMeshFiles.end())
        return it->second;  // failures once
    std::shared_ptr<const MeshShape> shape;
    try {
        shape = loadMeshShape(path);
    } catch (const MeshError& e) {
        error(at, "cannot load mesh '" + written + "': " + reasonOf(e, path),
              path == written
                  ? std::string()
                  : "mesh files are relative to the model file's folder; looked for " + path);
    }
    mMeshFiles.emplace(key, shape);
    return shape;
}

bool Lowering::checkSolidOperands(const std::vector<NodePtr>& operands, const std::string& use,
                                  SourcePos at) {
    if (!checkSurfaceOperands(operands, use, at)) return false;
    if (mOpenMeshes.empty()) return true;  // no mesh that is not a solid: nothing to look for
    bool ok = true;
    for (const NodePtr& operand : operands) {
        const Node* leaf = meshLeafBelow(operand.get());
        const auto it = leaf ? mOpenMeshes.find(leaf) : mOpenMeshes.end();
        if (it == mOpenMeshes.end()) continue;
        ok = false;
        const SourcePos meshAt = it->second.second;
        if (!mReportedOpenMeshes.insert(uint64_t(meshAt.file) << 32 | meshAt.offset).second)
            continue;
        const MeshShape& shape = *std::get<MeshParams>(leaf->params()).shape;
        const MeshReport& report = shape.report();
        std::string why = report.firstBadEdge ? describeBadEdge(*report.firstBadEdge)
                                              : std::string("it has no closed surface");
        const SourceLoc used = mSink.locate(at);
        error(
            meshAt, "mesh '" + shape.source() + "' is not a solid: " + why,
            "it is " + use + " at line " + std::to_string(used.line) + ", column " +
                std::to_string(used.col) +
                ", which needs a closed, consistently oriented mesh; on its own (an object, under "
                "transforms and materials) it still renders as a surface");
    }
    return ok;
}

void Lowering::checkSectionedSurfaces(const Scene& scene) {
    if ((mOpenMeshes.empty() && mSurfaces.empty()) || scene.sections.empty()) return;
    for (const NodePtr& object : scene.objects) {
        if (!meshLeafBelow(object.get()) && !isSurfaceTree(*object))
            continue;  // csg/primitives/surfaces.h
        const Bounds3& box = object->bounds();
        for (size_t i = 0; i < scene.sections.size(); ++i) {
            const SectionPlane& plane = scene.sections[i];
            // The plane cuts the object when the box has corners on both sides of it.
            bool below = false, above = false;
            for (int c = 0; c < 8; ++c) {
                const Vec3 corner((c & 1) ? box.hi.x : box.lo.x, (c & 2) ? box.hi.y : box.lo.y,
                                  (c & 4) ? box.hi.z : box.lo.z);
                const double side = glm::dot(plane.normal, corner - plane.point);
                below |= side < 0;
                above |= side > 0;
            }
            if (below && above) {
                checkSolidOperands({object}, "cut by the section plane", mSectionLocs[i]);
                break;
            }
        }
    }
}

}  // namespace kerf
