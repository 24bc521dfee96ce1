/// @file mesh/off_counts.h
/// @brief An OFF file's declared counts against its size, before Assimp allocates them.
///
/// Assimp 5.2's OFF reader reads the vertex and face counts as wrapping 32-bit numbers and
/// allocates for all of them before reading a row: a 356-byte file whose face count was a run
/// of 80 digits asked for 53 GB (kerf_fuzz_mesh).
#pragma once

#include <optional>
#include <string>

namespace kerf {

/// Whether `data` starts as an OFF file: a first word of letters ending in "OFF" (OFF, COFF,
/// NOFF, STOFF, nOFF, ...).
bool looksLikeOff(const std::string& data);

/// Why the OFF header in `data` cannot be true, or nullopt: a count that does not fit 32 bits,
/// or counts whose rows need more bytes than follow the header (each vertex at least two bytes
/// a coordinate, each face at least four).
std::optional<std::string> offCountsShortfall(const std::string& data);

}  // namespace kerf
