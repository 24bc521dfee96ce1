/// @file mesh/mesh_loader.h
/// @brief Reading triangle meshes from files (OBJ, PLY, STL, glTF 2.0) into a TriangleMesh.
/// Assimp does the parsing; it is an implementation detail of mesh_loader.cpp and never
/// appears in a header.
#pragma once

#include "mesh/triangle_mesh.h"

#include <stdexcept>
#include <string>

namespace kerf {

/// A file that cannot be a mesh: the message names the file and what is wrong with it.
class MeshError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// @brief Loads every mesh of the file's scene, each placed by its node's transform, as one
/// indexed triangle mesh (a mirroring transform swaps corners so faces keep their side, as
/// glTF specifies). Polygons are triangulated; points and lines are dropped. Vertices
/// equal in position, normal and UV are one index (STL, whose normals are per face, keeps no
/// normals and is joined by position alone). Normals and UVs are kept only when every mesh
/// of the file has them. `source` is set to `path`.
/// @throws MeshError if the file is missing or unreadable, is not a mesh the importer knows,
/// is truncated, has an index out of range or a non-finite coordinate (of a vertex a triangle
/// uses, before or after its node's transform), or has no triangle.
TriangleMesh loadMesh(const std::string& path);

}  // namespace kerf
