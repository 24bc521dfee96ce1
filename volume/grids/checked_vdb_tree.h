/// @file volume/grids/checked_vdb_tree.h
/// @brief A float grid's tree in a .vdb file walked before OpenVDB reads it. OpenVDB reads
/// each compressed chunk's 64-bit size and allocates that much before reading (a fuzzed file
/// asked for 64 GB in bloscFromStream), and reads as many root children as the file claims;
/// this walk reads the tree's layout as OpenVDB's RootNode, InternalNode, LeafNode and
/// io::readCompressedValues do (file versions 220–224, the Tree_float_5_4_3 every float grid
/// is), holding every count and size to the bytes left. Nothing is allocated from the file:
/// at most one node's masks (8 kB) at a time.
#pragma once

#include "volume/grids/vdb_layout_reader.h"

#include <cstdint>
#include <string>

namespace kerf::vdb_layout {

/// How a grid's tree is stored: read from the file header, the grid's compression word and
/// its metadata ("is_saved_as_half_float").
struct VdbTreeFormat {
    uint32_t fileVersion = 0;
    uint32_t compression = 0;  ///< zip 1, active mask 2, Blosc 4
    bool halfFloat = false;
};

/// Where a tree's topology and its buffers end.
struct VdbTreeEnds {
    uint64_t topology = 0;
    uint64_t buffers = 0;
};

/// Walks the topology and the leaf buffers of a float tree starting at the reader's position
/// (just after the grid's transform), throwing VdbLayoutProblem at the first count or size
/// the file cannot hold; `grid` names the grid in messages.
VdbTreeEnds checkFloatTreeLayout(VdbLayoutReader& in, const VdbTreeFormat& format,
                                 const std::string& grid);

}  // namespace kerf::vdb_layout
