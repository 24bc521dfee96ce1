// A .vdb file's layout checked before OpenVDB reads it (volume/grids/checked_vdb_layout.h).
// The format, as io::Archive::readHeader, io::File::open, GridDescriptor::read, MetaMap::readMeta
// and Archive::readGrid read it:
//   header: int64 magic 0x56444220, uint32 file version, uint32 library major and minor, char
//           "has grid offsets", (version 220–221: char "compressed"), 36-character UUID;
//   file metadata; int32 grid count; then per grid: descriptor (string unique name, string
//   type, string instance parent, int64 grid, block and end offsets), and at the grid offset:
//   uint32 compression, the grid's metadata, string transform type, ….
// Metadata: uint32 count, then per item string name, string type, uint32 size, value. Strings
// are a uint32 length and the bytes.
#include "volume/grids/checked_vdb_layout.h"

#include "volume/grids/checked_vdb_tree.h"
#include "volume/grids/vdb_layout_reader.h"

#include <string_view>

namespace kerf {

namespace {

using vdb_layout::VdbLayoutProblem;
using vdb_layout::VdbLayoutReader;

/// The value size OpenVDB's TypedMetadata reads for a type name (it ignores the stored size,
/// so another stored size would put every later read out of step), or 0: any size.
uint64_t fixedMetadataSize(std::string_view type) {
    static const std::pair<std::string_view, uint64_t> kSizes[] = {
        {"bool", 1},   {"int32", 4},  {"int64", 8},  {"float", 4},  {"double", 8}, {"vec2i", 8},
        {"vec2s", 8},  {"vec2d", 16}, {"vec3i", 12}, {"vec3s", 12}, {"vec3d", 24}, {"vec4i", 16},
        {"vec4s", 16}, {"vec4d", 32}, {"mat4s", 64}, {"mat4d", 128}};
    for (const auto& [name, size] : kSizes)
        if (type == name) return size;
    return 0;
}

/// OpenVDB's compression flags: zip, active mask, Blosc.
constexpr uint32_t kVdbCompressionFlags = 1 | 2 | 4;

/// Names and types of OpenVDB's objects are short; 4 kB is far beyond any written.
constexpr uint64_t kMaxVdbName = 4096;

/// One array of delayed-load metadata (io::DelayedLoadMetadata::readValue): a uint32 size,
/// then that many bytes of Blosc data whose header must say `count · element` bytes or its
/// padding (OpenVDB reserves what the header says), or (size 0) `count · element` raw bytes.
/// Returns the bytes it takes after its size.
uint64_t delayedLoadArray(VdbLayoutReader& in, uint64_t count, uint64_t element,
                          const std::string& what) {
    const uint64_t sizeAt = in.at();
    const uint64_t compressed = in.value<uint32_t>("the compressed size in " + what);
    if (compressed == 0) {
        in.skip(count * element, what);
        return count * element;
    }
    constexpr uint64_t kBloscHeader = 16;  // version, flags, type size; uint32 sizes
    if (compressed < kBloscHeader)
        throw VdbLayoutProblem("bad size at byte " + std::to_string(sizeAt) + ": " + what +
                               " holds " + std::to_string(compressed) +
                               " compressed bytes, less than a Blosc header");
    unsigned char header[kBloscHeader];
    in.read(header, kBloscHeader, "the Blosc header in " + what);
    const uint64_t unpacked = uint64_t(header[4]) | uint64_t(header[5]) << 8 |
                              uint64_t(header[6]) << 16 | uint64_t(header[7]) << 24;
    // OpenVDB pads arrays under 128 bytes to 128 before compressing (points/StreamCompression).
    constexpr uint64_t kBloscPad = 128;
    if (unpacked != count * element && !(unpacked == kBloscPad && count * element <= kBloscPad))
        throw VdbLayoutProblem("bad size at byte " + std::to_string(sizeAt + 8) + ": " + what +
                               " unpacks to " + std::to_string(unpacked) + " bytes, not the " +
                               std::to_string(count * element) + " of its " +
                               std::to_string(count) + " leaves");
    in.skip(compressed - kBloscHeader, what);
    return compressed;
}

/// OpenVDB's delayed-load metadata: a uint32 count of leaves, then a byte per leaf and
/// (unless its size is 0xFFFFFFFF, as uncompressed grids write) an int64 per leaf, each array
/// raw or compressed; bytes beyond them up to the item's size are skipped, as OpenVDB does.
/// OpenVDB allocates 9 bytes a leaf from the count, so the count is held to the leaves the
/// file can hold (each takes at least its 64-byte mask).
void checkDelayedLoad(VdbLayoutReader& in, uint64_t size, const std::string& what) {
    if (size == 0) return;
    const uint64_t start = in.at();
    const uint64_t leaves = in.value<uint32_t>(what + "'s leaf count");
    if (leaves > in.size() / 64)
        throw VdbLayoutProblem("bad count at byte " + std::to_string(start) + ": " + what +
                               " claims " + std::to_string(leaves) + " leaves, more than a " +
                               std::to_string(in.size()) + "-byte file can hold");
    uint64_t used = 4 + 4 + delayedLoadArray(in, leaves, 1, what);
    const uint64_t secondAt = in.at();
    used += 4;
    if (in.value<uint32_t>("the compressed size in " + what) != UINT32_MAX) {
        in.seek(secondAt);
        used += delayedLoadArray(in, leaves, 8, what);
    }
    if (used > size)
        throw VdbLayoutProblem("bad size at byte " + std::to_string(start - 4) + ": " + what +
                               " claims " + std::to_string(size) + " bytes, its arrays take " +
                               std::to_string(used));
    in.skip(size - used, what);
}

/// Checks a metadata map and returns whether it says "is_saved_as_half_float" (a grid's tree
/// then holds halves).
bool checkMetadata(VdbLayoutReader& in, const std::string& owner) {
    bool halfFloat = false;
    const uint64_t start = in.at();
    const uint64_t count = in.value<uint32_t>("the metadata count of " + owner);
    // Each item takes at least its two string lengths and its size: 12 bytes.
    if (count > in.left() / 12)
        throw VdbLayoutProblem("bad count at byte " + std::to_string(start) + ": " + owner +
                               " claims " + std::to_string(count) + " metadata items, " +
                               std::to_string(in.left()) + " bytes remain");
    for (uint64_t i = 0; i < count; ++i) {
        const std::string item = "metadata item " + std::to_string(i + 1) + " of " + owner;
        const std::string name = in.string("the name of " + item, kMaxVdbName);
        const std::string what = "metadata '" + name + "' of " + owner;
        const uint64_t typeAt = in.at();
        const std::string type = in.string("the type of " + what, kMaxVdbName);
        const uint64_t sizeAt = in.at();
        const uint64_t size = in.value<uint32_t>("the size of " + what);
        in.need(size, what);
        const uint64_t fixed = fixedMetadataSize(type);
        if (fixed && size != fixed)
            throw VdbLayoutProblem("bad size at byte " + std::to_string(sizeAt) + ": " + what +
                                   " of type " + type + " claims " + std::to_string(size) +
                                   " bytes, a " + type + " has " + std::to_string(fixed));
        if (name == "is_saved_as_half_float" && type != "bool")  // OpenVDB takes any type
            throw VdbLayoutProblem("bad type at byte " + std::to_string(typeAt) + ": " + what +
                                   " is not a bool");
        if (type == "__delayedload") {
            checkDelayedLoad(in, size, what);
        } else if (type == "bool") {  // OpenVDB reads the byte into a bool
            const uint64_t valueAt = in.at();
            const auto value = in.value<uint8_t>(what);
            if (value > 1)
                throw VdbLayoutProblem("bad value at byte " + std::to_string(valueAt) + ": " +
                                       what + " of type bool is " + std::to_string(value) +
                                       ", not 0 or 1");
            if (name == "is_saved_as_half_float") halfFloat = value == 1;
        } else {
            in.skip(size, what);
        }
    }
    return halfFloat;
}

/// Checks the header and returns the file version.
uint32_t checkHeader(VdbLayoutReader& in) {
    int64_t magic = 0;
    in.read(&magic, 8, "the header");
    if (magic != 0x56444220)
        throw VdbLayoutProblem("not a .vdb file: its first 8 bytes are not OpenVDB's magic number");
    const uint32_t version = in.value<uint32_t>("the file version");
    if (version < kVdbOldestFileVersion || version > kVdbNewestFileVersion)
        throw VdbLayoutProblem("file version " + std::to_string(version) +
                               " at byte 8; kerf reads " + std::to_string(kVdbOldestFileVersion) +
                               " to " + std::to_string(kVdbNewestFileVersion) +
                               " (OpenVDB 3 to 10)");
    in.skip(8, "the library version");
    if (in.value<char>("the grid-offsets flag") == 0)
        throw VdbLayoutProblem(
            "it was written as a stream, without grid offsets; kerf reads "
            ".vdb files as OpenVDB's io::File writes them");
    if (version < 222) in.skip(1, "the compression flag");
    in.skip(36, "the UUID");
    return version;
}

/// The bytes of a linear map as its read() takes them (math/Maps.h), or 0 for another map
/// (a frustum, which the readers refuse before reading the tree, or a name OpenVDB refuses).
uint64_t linearMapBytes(std::string_view type) {
    if (type == "AffineMap" || type == "UnitaryMap") return 128;  // a Mat4d
    if (type == "ScaleMap" || type == "UniformScaleMap") return 5 * 24;
    if (type == "ScaleTranslateMap" || type == "UniformScaleTranslateMap") return 6 * 24;
    if (type == "TranslationMap") return 24;
    return 0;
}

/// The tree type of every float grid; "_HalfFloat" marks a descriptor of one saved as halves.
constexpr std::string_view kFloatTreeType = "Tree_float_5_4_3";

/// Grid `index`'s descriptor at the reader's position, its section's offsets, and at its
/// offset its compression, metadata and transform type. Returns where the next one starts.
uint64_t checkGrid(VdbLayoutReader& in, int64_t index, uint32_t fileVersion) {
    const std::string which = "grid " + std::to_string(index + 1);
    const std::string name = in.string("the name of " + which, kMaxVdbName);
    const std::string grid = "grid '" + name + "'";
    const std::string type = in.string("the type of " + grid, kMaxVdbName);
    const bool instance = !in.string("the instance parent of " + grid, kMaxVdbName).empty();
    const uint64_t offsetsAt = in.at();
    int64_t pos[3];
    in.read(pos, sizeof pos, "the offsets of " + grid);
    const uint64_t size = in.size();
    if (pos[2] > 0 && uint64_t(pos[2]) > size)
        throw VdbLayoutProblem("truncated: " + grid + " ends at byte " + std::to_string(pos[2]) +
                               " but the file has " + std::to_string(size) + " bytes");
    if (!(pos[0] >= int64_t(in.at()) && pos[0] <= pos[1] && pos[1] <= pos[2]))
        throw VdbLayoutProblem("bad offsets at byte " + std::to_string(offsetsAt) + ": " + grid +
                               " at " + std::to_string(pos[0]) + ", its data at " +
                               std::to_string(pos[1]) + ", its end at " + std::to_string(pos[2]) +
                               " (they must be in order, after the descriptor)");
    in.seek(uint64_t(pos[0]));
    const uint64_t compressionAt = in.at();
    const uint32_t compression = in.value<uint32_t>("the compression of " + grid);
    if (compression & ~kVdbCompressionFlags)  // zip 1, active mask 2, Blosc 4
        throw VdbLayoutProblem("bad compression flags at byte " + std::to_string(compressionAt) +
                               ": " + grid + " has " + std::to_string(compression) +
                               ", OpenVDB's are 1, 2 and 4");
    const bool halfFloat = checkMetadata(in, grid);
    const std::string map = in.string("the transform type of " + grid, kMaxVdbName);
    if (in.at() > uint64_t(pos[1]))
        throw VdbLayoutProblem("bad offsets: " + grid + "'s metadata runs to byte " +
                               std::to_string(in.at()) + ", past its data at byte " +
                               std::to_string(pos[1]));
    // Only float trees are read (the readers refuse other grids from their metadata), and an
    // instance shares its parent's tree.
    const bool floatTree =
        type == kFloatTreeType || type == std::string(kFloatTreeType) + "_HalfFloat";
    if (floatTree && !instance && linearMapBytes(map) != 0) {
        in.skip(linearMapBytes(map), "the transform of " + grid);
        const vdb_layout::VdbTreeEnds ends =
            vdb_layout::checkFloatTreeLayout(in, {fileVersion, compression, halfFloat}, grid);
        // OpenVDB's writer records both ends; its reader reads on from the transform, so a
        // record out of step with the tree is a corrupted file.
        if (ends.topology != uint64_t(pos[1]) || ends.buffers != uint64_t(pos[2]))
            throw VdbLayoutProblem("bad offsets at byte " + std::to_string(offsetsAt) + ": " +
                                   grid + "'s tree ends at byte " + std::to_string(ends.topology) +
                                   " and its data at byte " + std::to_string(ends.buffers) +
                                   ", its offsets say " + std::to_string(pos[1]) + " and " +
                                   std::to_string(pos[2]));
    }
    return uint64_t(pos[2]);
}

}  // namespace

std::string checkVdbLayout(const std::string& path) {
    try {
        VdbLayoutReader in(path);
        const uint32_t version = checkHeader(in);
        checkMetadata(in, "the file");
        const uint64_t countAt = in.at();
        const int64_t grids = in.value<int32_t>("the grid count");
        // A descriptor takes at least three string lengths and three offsets: 36 bytes.
        if (grids < 0 || uint64_t(grids) > in.left() / 36)
            throw VdbLayoutProblem("bad count at byte " + std::to_string(countAt) + ": " +
                                   std::to_string(grids) + " grids, " + std::to_string(in.left()) +
                                   " bytes remain");
        for (int64_t g = 0; g < grids; ++g) in.seek(checkGrid(in, g, version));
        return "";
    } catch (const VdbLayoutProblem& e) {
        return e.what();
    }
}

}  // namespace kerf
