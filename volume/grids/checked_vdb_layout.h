/// @file volume/grids/checked_vdb_layout.h
/// @brief A .vdb file's structure checked against its size before OpenVDB reads it: OpenVDB's
/// readers trust every length they read (a corrupted string length or metadata size asked for
/// 4–6 GB and ended in "out of memory"), so kerf reads the header, the file's metadata, every
/// grid descriptor and every grid's metadata and transform name itself, in 64-bit arithmetic,
/// and says where the file is wrong. Plain C++, no OpenVDB: the layout is OpenVDB's
/// io::Archive / io::File format (file versions 220–224 as written since OpenVDB 3).
#pragma once

#include <cstdint>
#include <string>

namespace kerf {

/// The oldest file version read (OpenVDB 3.0 wrote 220; earlier layouts differ).
constexpr uint32_t kVdbOldestFileVersion = 220;
/// The newest file version read (OpenVDB 10 writes 224).
constexpr uint32_t kVdbNewestFileVersion = 224;

/// "" when the file's header, metadata, grid descriptors and each grid's metadata and
/// transform name fit the file and one another; otherwise what is wrong and at which byte
/// (without the path, which the caller's message names), e.g. "truncated at byte 120: grid
/// 'density' ends at byte 11930 but the file has 5000 bytes". Only reads: at most the bytes
/// the file holds are ever allocated (strings are checked against the bytes left first).
std::string checkVdbLayout(const std::string& path);

}  // namespace kerf
