/// @file mesh/gltf_prescan.h
/// @brief What a glTF file's JSON declares, read by an iterative scan before Assimp sees it.
/// Assimp's glTF2 importer (and the JSON parser under it) recurse as deep as the file nests:
/// a 30,000-node chain overflowed the stack before kerf's own depth check. This scan keeps
/// its own stack, bounded by kGltfMaxJsonNesting, and refuses what would recurse too deep.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace kerf {

/// JSON nesting a glTF may have: the format itself needs 7 levels; extras are user data.
inline constexpr size_t kGltfMaxJsonNesting = 128;
/// Node hierarchy depth a mesh file may have (glTF nodes, and any format's scene graph).
inline constexpr int kMeshMaxNodeDepth = 1024;

/// The triangles a glTF declares (mode-4 primitives, by their index or position counts), or
/// nothing when a primitive's count is unknown or it is a strip or fan.
struct GltfDeclared {
    std::optional<uint64_t> triangles;
};

/// @brief Scans the glTF JSON of `path` (`json`: the file, or a GLB's JSON chunk): nesting
/// within kGltfMaxJsonNesting, every child index a node that exists, one parent per node,
/// no cycle, depth within kMeshMaxNodeDepth, every primitive's accessors exist.
/// @throws MeshError naming `path` and what is wrong.
GltfDeclared prescanGltf(const std::string& path, std::string_view json);

/// The JSON chunk of a GLB whose chunk lengths were checked against the file, or an empty
/// view when the first chunk is not JSON.
std::string_view glbJsonChunk(std::string_view glb);

}  // namespace kerf
