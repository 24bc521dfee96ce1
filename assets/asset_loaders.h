/// @file assets/asset_loaders.h
/// @brief Inside assets/: each kind of asset read from its file by its own module (mesh/,
/// volume/, io/), the module's exception turned into scene/assets.h's AssetError. No caching
/// here (assets/asset_cache.h does it).
#pragma once

#include "scene/assets.h"

#include <string>

namespace kerf {

/// mesh/mesh_shape.h loadMeshShape; the reason leaves out the path it starts with.
Loaded<MeshAsset> loadMeshAsset(const std::string& path);
/// A mesh of the given triangles (no file).
std::shared_ptr<const MeshAsset> meshAssetOf(std::vector<Vec3> positions,
                                             std::vector<std::array<uint32_t, 3>> triangles,
                                             std::string source);
/// volume/grids/vdb_level_set.h loadLevelSet; Subject::Part when the grid is at fault.
Loaded<LevelSetAsset> loadLevelSetAsset(const std::string& path, const std::string& grid);
/// volume/grids/vdb_fog.h loadVdbFog; Subject::Part when the named grid is missing.
Loaded<FogAsset> loadFogAsset(const std::string& path, const std::string& grid);
/// io/texture.h Texture::open; a missing image plug-in is a standalone message.
Loaded<Texture> loadTextureAsset(const std::string& path);

/// The font file a text request will be laid out with, and the request as a cache key; an
/// empty file when the font cannot be found.
struct FontFile {
    std::string file;
    std::string key;
};
FontFile fontFileOf(const TextRequest& request);
/// io/font_outline.h layoutText; Subject::Part when the text (not the font) is at fault.
Loaded<TextShape> layoutTextAsset(const TextRequest& request);

}  // namespace kerf
