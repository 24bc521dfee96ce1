// Meshes (mesh/) and .vdb level sets and fog volumes (volume/) as assets
// (assets/asset_loaders.h).
#include "assets/asset_loaders.h"

#include "mesh/mesh_loader.h"
#include "mesh/mesh_shape.h"
#include "volume/grids/level_set_node.h"
#include "volume/grids/vdb_fog.h"
#include "volume/grids/vdb_level_set.h"

namespace kerf {

namespace {

/// A MeshShape as scene/assets.h's MeshAsset.
class ShapeAsset final : public MeshAsset {
public:
    explicit ShapeAsset(std::shared_ptr<const MeshShape> shape) : mShape(std::move(shape)) {}
    NodePtr leaf(bool smooth) const override { return meshNode(mShape, smooth); }
    bool isSolid() const override { return mShape->isSolid(); }
    std::string whyNotSolid() const override {
        const MeshReport& report = mShape->report();
        return report.firstBadEdge ? describeBadEdge(*report.firstBadEdge) : std::string();
    }
    const std::string& source() const override { return mShape->source(); }

private:
    std::shared_ptr<const MeshShape> mShape;
};

class GridAsset final : public LevelSetAsset {
public:
    explicit GridAsset(std::shared_ptr<const LevelSetGrid> grid) : mGrid(std::move(grid)) {}
    NodePtr leaf() const override { return levelSetSolid(mGrid); }

private:
    std::shared_ptr<const LevelSetGrid> mGrid;
};

}  // namespace

Loaded<MeshAsset> loadMeshAsset(const std::string& path) {
    Loaded<MeshAsset> r;
    try {
        r.value = std::make_shared<const ShapeAsset>(loadMeshShape(path));
    } catch (const MeshError& e) {
        // The diagnostic names the file as written: leave out the path the message starts with.
        const std::string message = e.what();
        const std::string prefix = path + ": ";
        r.error.reason = message.compare(0, prefix.size(), prefix) == 0
                             ? message.substr(prefix.size())
                             : message;
    }
    return r;
}

std::shared_ptr<const MeshAsset> meshAssetOf(std::vector<Vec3> positions,
                                             std::vector<std::array<uint32_t, 3>> triangles,
                                             std::string source) {
    TriangleMesh mesh;
    mesh.positions = std::move(positions);
    mesh.triangles = std::move(triangles);
    mesh.source = std::move(source);
    return std::make_shared<const ShapeAsset>(std::make_shared<const MeshShape>(std::move(mesh)));
}

Loaded<LevelSetAsset> loadLevelSetAsset(const std::string& path, const std::string& grid) {
    Loaded<LevelSetAsset> r;
    try {
        r.value = std::make_shared<const GridAsset>(loadLevelSet(path, grid));
    } catch (const VdbError& e) {
        r.error.reason = e.what();
        if (e.aboutGrid()) r.error.subject = AssetError::Subject::Part;
    }
    return r;
}

Loaded<FogAsset> loadFogAsset(const std::string& path, const std::string& grid) {
    Loaded<FogAsset> r;
    try {
        VdbFog fog = loadVdbFog(path, grid);
        r.value = std::make_shared<const FogAsset>(FogAsset{fog.density, fog.bounds});
    } catch (const VdbFogError& e) {
        r.error.reason = e.what();
        if (r.error.reason.find("no grid") != std::string::npos)
            r.error.subject = AssetError::Subject::Part;
    }
    return r;
}

}  // namespace kerf
