/// @file io/mesh_writers.h
/// @brief Triangle meshes to OBJ (text), PLY (binary little-endian) and STL (binary), through
/// io/atomic_file.h. io/ knows nothing of solids: the caller hands plain arrays.
#pragma once

#include "io/atomic_file.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace kerf {

enum class MeshFormat { Obj, Ply, Stl };

/// A mesh as plain arrays: `vertexCount` points as x, y, z doubles, and `triangleCount`
/// triangles as three vertex indices each, counter-clockwise seen from outside.
struct MeshArrays {
    const double* xyz = nullptr;
    size_t vertexCount = 0;
    const uint32_t* indices = nullptr;
    size_t triangleCount = 0;
};

/// The format named by the path's extension (.obj, .ply, .stl, any case); false for others.
bool meshFormatFromPath(const std::string& path, MeshFormat& format);

/// The file's bytes, with vertices at one written position joined first (io/mesh_weld.h).
/// OBJ: `v x y z` with the shortest decimal that reads back to the same
/// double, `f a b c` 1-based. PLY: float x, y, z and a uchar-counted list of uint indices.
/// STL: an 80-byte header, the count, and per triangle its unit normal (float zeros for a
/// degenerate one), its corners as floats and a zero attribute word.
std::string encodeMesh(MeshFormat format, const MeshArrays& mesh);

/// Thrown when a mesh file cannot be written; what() is "cannot write 'F': <reason>".
struct MeshWriteError : FileWriteError {
    using FileWriteError::FileWriteError;
};

/// Writes the mesh to `path` all at once (temporary file and rename). Throws MeshWriteError.
void writeMeshFile(const std::string& path, MeshFormat format, const MeshArrays& mesh);

}  // namespace kerf
