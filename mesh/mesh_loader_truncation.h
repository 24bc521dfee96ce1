/// @file mesh/mesh_loader_truncation.h
/// @brief Whether a binary STL or PLY file holds all the data its header declares. Checked
/// before Assimp reads it: Assimp takes garbage for a short binary PLY's missing data (which
/// failed as "index out of range" at every cut we tried) and calls a short binary STL
/// "undetermined"; this check says what is wrong.
#pragma once

#include <optional>
#include <string>

namespace kerf {

/// @brief For a binary STL (not starting with "solid"), a PLY, a binary glTF or an OFF
/// (mesh/off_counts.h): what is missing
/// ("truncated: …"), or nothing when the file is complete, ASCII, or of another format (then
/// the importer decides). Reads only the header and, for PLY lists, their counts.
std::optional<std::string> binaryMeshTruncation(const std::string& path);

}  // namespace kerf
