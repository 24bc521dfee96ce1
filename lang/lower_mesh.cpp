// Lowering, part 3d: `mesh "file" smooth B`, a triangle mesh got from the asset provider
// (scene/assets.h). Each file is asked for once per compile, whatever its transforms: every use
// is its own leaf over one shared mesh (one copy of the triangles, one BVH). A mesh that is not a
// solid (open, non-manifold, inconsistently oriented) renders as a surface on its own, and is
// refused wherever a solid is needed: as a Boolean operand, displaced, or cut by a section plane.
#include "lang/lower.h"

#include "csg/primitives/surfaces.h"

#include <filesystem>
#include <system_error>
#include <utility>

namespace kerf {

namespace {

namespace fs = std::filesystem;

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

std::string Lowering::resolvedPath(const std::string& written, SourcePos at) const {
    const fs::path model = *mSink.locate(at).file;
    return fs::path(written).is_absolute()
               ? written
               : (model.parent_path() / written).lexically_normal().string();
}

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
    std::shared_ptr<const MeshAsset> mesh = meshAsset(v->string(), at);
    if (!mesh) return nullptr;
    NodePtr leaf = mesh->leaf(smooth);
    if (!mesh->isSolid()) mOpenMeshes.emplace(leaf.get(), OpenMesh{leaf, s.loc, mesh});
    return leaf;
}

std::shared_ptr<const MeshAsset> Lowering::meshAsset(const std::string& written, SourcePos at) {
    const std::string path = resolvedPath(written, at);
    std::error_code ec;
    fs::path canonical = fs::weakly_canonical(path, ec);
    const std::string key = ec ? path : canonical.string();
    if (const auto it = mMeshFiles.find(key); it != mMeshFiles.end())
        return it->second;  // failures once
    Loaded<MeshAsset> mesh = mAssets.mesh(path);
    if (!mesh && !mesh.error.skipped)
        error(at, "cannot load mesh '" + written + "': " + mesh.error.reason,
              path == written
                  ? std::string()
                  : "mesh files are relative to the model file's folder; looked for " + path);
    mMeshFiles.emplace(key, mesh.value);
    return mesh.value;
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
        const SourcePos meshAt = it->second.at;
        if (!mReportedOpenMeshes.insert(uint64_t(meshAt.file) << 32 | meshAt.offset).second)
            continue;
        const MeshAsset& mesh = *it->second.mesh;
        std::string why = mesh.whyNotSolid();
        if (why.empty()) why = "it has no closed surface";
        const SourceLoc used = mSink.locate(at);
        error(
            meshAt, "mesh '" + mesh.source() + "' is not a solid: " + why,
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
