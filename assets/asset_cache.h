/// @file assets/asset_cache.h
/// @brief The asset provider of the commands (scene/assets.h): meshes (mesh/), .vdb level sets
/// and fog volumes (volume/), image textures and font layouts (io/), each kept after its
/// compile, keyed by its file's canonical path and identity (device, inode, size, mtime in ns;
/// assets/file_identity.h). Compiling again reuses every file that did not change and reloads
/// one that did. A failed load is never kept: the next compile tries again.
///
/// One compile at a time: the cache is not thread-safe. The values it hands out are immutable
/// and shared, so scenes made from it stay valid after the cache reloads or is destroyed.
#pragma once

#include "scene/assets.h"

#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace kerf {

/// Loads (files actually read) and reuses (served from the cache) per kind of asset.
struct AssetCounts {
    int meshes = 0;
    int levelSets = 0;
    int fogVolumes = 0;
    int textures = 0;
    int texts = 0;
    int total() const { return meshes + levelSets + fogVolumes + textures + texts; }
};

class AssetCache final : public AssetProvider {
public:
    AssetCache();
    ~AssetCache() override;

    Loaded<MeshAsset> mesh(const std::string& path) override;
    std::shared_ptr<const MeshAsset> meshOf(std::vector<Vec3> positions,
                                            std::vector<std::array<uint32_t, 3>> triangles,
                                            std::string source) override;
    Loaded<LevelSetAsset> levelSet(const std::string& path, const std::string& grid) override;
    Loaded<FogAsset> fogVolume(const std::string& path, const std::string& grid) override;
    Loaded<Texture> texture(const std::string& path) override;
    Loaded<TextShape> text(const TextRequest& request) override;
    const std::vector<AssetFile>& inputs() const override { return mInputs; }
    void sourceRead(const std::string& path) override;

    /// Starts the list of inputs() afresh (call before each compile); the cache is kept.
    void clearInputs();
    /// How many assets were read from their files, and how many were served from the cache.
    const AssetCounts& loads() const { return mLoads; }
    const AssetCounts& reuses() const { return mReuses; }

private:
    /// A cached value with the identity of the file it was read from.
    template <class T>
    struct Entry {
        AssetFile file;
        std::shared_ptr<const T> value;
    };
    template <class T>
    using Table = std::map<std::pair<std::string, std::string>, Entry<T>>;

    /// The asset of `file` (its canonical path and `part`, a grid name or a text request)
    /// from `table` if the file is unchanged, else `load()`ed and kept; `loads`/`reuses`
    /// count which. The file is listed in inputs() either way when it could be stat()ed.
    template <class T, class Load>
    Loaded<T> cached(Table<T>& table, const std::string& path, const std::string& part, int& loads,
                     int& reuses, const Load& load);
    void noteInput(const AssetFile& file);

    Table<MeshAsset> mMeshes;
    Table<LevelSetAsset> mLevelSets;
    Table<FogAsset> mFogs;
    Table<Texture> mTextures;
    Table<TextShape> mTexts;
    AssetCounts mLoads, mReuses;
    std::vector<AssetFile> mInputs;
    std::set<std::string> mInputPaths;
};

}  // namespace kerf
