/// @file io/text_file.h
/// @brief Writing text outputs (CSV, SVG, Markdown) like images are written: through
/// io/atomic_file.h, so a failed run never leaves a half file nor clobbers an earlier one.
#pragma once

#include "io/atomic_file.h"

#include <string>

namespace kerf {

/// Thrown when a text file cannot be written; what() is "cannot write 'F': <reason>".
struct TextWriteError : FileWriteError {
    using FileWriteError::FileWriteError;
};

/// Writes `text` to `path` through a temporary file and a rename. Throws TextWriteError.
void writeTextFileAtomically(const std::string& path, const std::string& text);

}  // namespace kerf
