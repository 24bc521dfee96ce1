/// @file io/atomic_file.h
/// @brief Replacing a file all at once: the content goes to a temporary file beside the target,
/// which is then renamed onto it, so a failure never leaves a half file nor clobbers an earlier
/// one. Used for images (io/image_io.cpp) and text files (io/text_file.h).
#pragma once

#include <functional>
#include <string>

namespace kerf {

/// Fills the temporary file, open as descriptor `fd` and also reachable by name `temporary`
/// (for writers that open files themselves); returns "" or an error message.
using TemporaryFileWriter = std::function<std::string(int fd, const std::string& temporary)>;

/// Creates "dir/.name.kerf-tmp-XXXXXX<suffix>" beside `path` (the suffix keeps the real
/// extension for writers that pick the format by it) with the permissions a plain new file
/// would get, lets `write` fill it, closes it and renames it onto `path`. Returns "" on success,
/// else the reason, the temporary file removed.
std::string writeThroughTemporary(const std::string& path, const std::string& suffix,
                                  const TemporaryFileWriter& write);

}  // namespace kerf
