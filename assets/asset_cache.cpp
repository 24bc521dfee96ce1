// The cache of assets across compiles (assets/asset_cache.h): each lookup stats the file, and
// a file whose identity is the one cached is served without being read.
#include "assets/asset_cache.h"

#include "assets/asset_loaders.h"
#include "assets/file_identity.h"

#include <new>
#include <optional>
#include <stdexcept>

namespace kerf {

AssetCache::AssetCache() = default;
AssetCache::~AssetCache() = default;

void AssetCache::clearInputs() {
    mInputs.clear();
    mInputPaths.clear();
}

void AssetCache::sourceRead(const std::string& path) {
    if (const std::optional<AssetFile> file = fileIdentity(path)) noteInput(*file);
}

void AssetCache::noteInput(const AssetFile& file) {
    if (mInputPaths.insert(file.path).second) mInputs.push_back(file);
}

namespace {

/// load(), with running out of memory (or a size beyond what a container can hold, which only
/// a corrupt or hostile file asks for) turned into the asset's error, so the message names the
/// file instead of being the library's "std::bad_alloc" or "vector::_M_default_append". The
/// readers check sizes against the file first; this is the backstop behind those checks.
template <class T, class Load>
Loaded<T> loadNamingMemory(const Load& load, const std::optional<AssetFile>& file) {
    const std::string size =
        file ? " (" + std::to_string(file->size) + " bytes on disk)" : std::string();
    Loaded<T> failed;
    try {
        return load();
    } catch (const std::bad_alloc&) {
        failed.error.reason = "there is not enough memory to read it" + size;
    } catch (const std::length_error&) {
        failed.error.reason = "it asks for more memory than can be held" + size +
                              ": the file is corrupt or not what its name says";
    }
    return failed;
}

}  // namespace

template <class T, class Load>
Loaded<T> AssetCache::cached(Table<T>& table, const std::string& path, const std::string& part,
                             int& loads, int& reuses, const Load& load) {
    // Stat before reading: a file changed while it is read keeps the older identity, so the
    // next compile sees a difference and reads it again.
    const std::optional<AssetFile> file = fileIdentity(path);
    if (file) {
        noteInput(*file);
        const auto it = table.find({file->path, part});
        if (it != table.end() && it->second.file == *file) {
            ++reuses;
            Loaded<T> hit;
            hit.value = it->second.value;
            return hit;
        }
    }
    ++loads;
    Loaded<T> loaded = loadNamingMemory<T>(load, file);
    if (file && loaded.value)
        table[{file->path, part}] = Entry<T>{*file, loaded.value};
    else if (file)
        table.erase({file->path, part});  // a failure is never kept
    return loaded;
}

Loaded<MeshAsset> AssetCache::mesh(const std::string& path) {
    return cached(mMeshes, path, "", mLoads.meshes, mReuses.meshes,
                  [&] { return loadMeshAsset(path); });
}

std::shared_ptr<const MeshAsset> AssetCache::meshOf(std::vector<Vec3> positions,
                                                    std::vector<std::array<uint32_t, 3>> triangles,
                                                    std::string source) {
    return meshAssetOf(std::move(positions), std::move(triangles), std::move(source));
}

Loaded<LevelSetAsset> AssetCache::levelSet(const std::string& path, const std::string& grid) {
    return cached(mLevelSets, path, grid, mLoads.levelSets, mReuses.levelSets,
                  [&] { return loadLevelSetAsset(path, grid); });
}

Loaded<FogAsset> AssetCache::fogVolume(const std::string& path, const std::string& grid) {
    return cached(mFogs, path, grid, mLoads.fogVolumes, mReuses.fogVolumes,
                  [&] { return loadFogAsset(path, grid); });
}

Loaded<Texture> AssetCache::texture(const std::string& path) {
    return cached(mTextures, path, "", mLoads.textures, mReuses.textures,
                  [&] { return loadTextureAsset(path); });
}

Loaded<TextShape> AssetCache::text(const TextRequest& request) {
    const FontFile font = fontFileOf(request);
    if (font.file.empty()) {  // the font cannot be found: the layout says why
        ++mLoads.texts;
        return layoutTextAsset(request);
    }
    return cached(mTexts, font.file, font.key, mLoads.texts, mReuses.texts,
                  [&] { return layoutTextAsset(request); });
}

}  // namespace kerf
