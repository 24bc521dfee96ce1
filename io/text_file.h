/// @file io/text_file.h
/// @brief Writing text outputs (CSV, SVG, Markdown) like images are written (io/image_io.cpp):
/// to a temporary file beside the target, then renamed onto it, so a failed run never leaves a
/// half file nor clobbers an earlier one.
#pragma once

#include <stdexcept>
#include <string>

namespace kerf {

/// Thrown when a text file cannot be written; what() names the file and the reason.
struct TextWriteError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Writes `text` to `path` through a temporary file and a rename. Throws TextWriteError.
void writeTextFileAtomically(const std::string& path, const std::string& text);

}  // namespace kerf
