/// @file assets/file_identity.h
/// @brief What tells one version of a file from another without reading it: its canonical
/// path, device, inode, size and modification time in nanoseconds (scene/assets.h AssetFile).
#pragma once

#include "scene/assets.h"

#include <optional>
#include <string>

namespace kerf {

/// The identity of the file at `path` (symbolic links followed), or nullopt when it cannot be
/// stat()ed (missing, no permission): such a file is never cached.
std::optional<AssetFile> fileIdentity(const std::string& path);

/// `path` made canonical as far as it exists (std::filesystem::weakly_canonical), else as written.
std::string canonicalPath(const std::string& path);

}  // namespace kerf
