/// @file mesh/ply_line_end.h
/// @brief A binary PLY whose data starts with the byte '\n' (a float whose low byte is 0x0a),
/// as Assimp 5.2 can read it. Assimp ends the header line "end_header\n" and then takes one
/// more '\n' for part of that line end, so it reads every value after it one byte off: a valid
/// file loads as garbage or fails ("index out of range"). Written "end_header\r\n", the same
/// data is read right; the fix is made in memory, the file is never changed.
#pragma once

#include <optional>
#include <string>

namespace kerf {

/// The file's bytes with its header's last line ended "\r\n", when it is a binary PLY whose
/// data begins with '\n' after "end_header\n"; nothing for every other file.
std::optional<std::string> plyWithCrLfHeaderEnd(const std::string& path);

}  // namespace kerf
