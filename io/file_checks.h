/// @file io/file_checks.h
/// @brief Whether a path can be read as a data file, by stat() alone: a FIFO or a device is
/// refused without being opened (opening a FIFO waits for a writer; /dev/zero never ends).
#pragma once

#include <string>

namespace kerf {

/// Why `path` cannot be read as a file ("no such file", "it is a folder", "not a regular
/// file (a device, FIFO or socket)", or the errno text of stat or access), or "".
std::string readableFileProblem(const std::string& path);

}  // namespace kerf
