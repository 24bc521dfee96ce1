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

#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace kerf {

namespace {

/// Thrown inside the check with what is wrong; checkVdbLayout returns its text.
struct VdbLayoutProblem : std::runtime_error {
    using std::runtime_error::runtime_error;
};

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

class VdbLayoutReader {
public:
    explicit VdbLayoutReader(const std::string& path) : mIn(path, std::ios::binary) {
        if (!mIn) throw VdbLayoutProblem("cannot open it for reading");
        mIn.seekg(0, std::ios::end);
        const std::streamoff end = mIn.tellg();
        if (end < 0) throw VdbLayoutProblem("cannot find its size");
        mSize = uint64_t(end);
        mIn.seekg(0);
    }

    uint64_t size() const { return mSize; }
    uint64_t at() const { return mPos; }
    uint64_t left() const { return mSize - mPos; }

    void seek(uint64_t pos) {
        mPos = pos;
        mIn.seekg(std::streamoff(pos));
    }

    /// n bytes of `what`, or the truncation named.
    void read(void* out, uint64_t n, const std::string& what) {
        need(n, what);
        mIn.read(static_cast<char*>(out), std::streamsize(n));
        if (!mIn)
            throw VdbLayoutProblem("cannot read " + what + " at byte " + std::to_string(mPos));
        mPos += n;
    }
    void need(uint64_t n, const std::string& what) const {
        if (n > left())
            throw VdbLayoutProblem("truncated at byte " + std::to_string(mPos) + ": " + what +
                                   " needs " + std::to_string(n) + " bytes, " +
                                   std::to_string(left()) + " remain of " + std::to_string(mSize));
    }
    template <typename T>
    T value(const std::string& what) {
        T v;
        read(&v, sizeof v, what);
        return v;
    }
    /// A length-prefixed string, its length checked against the bytes left (and `most`).
    std::string string(const std::string& what, uint64_t most = UINT64_MAX) {
        const uint64_t start = mPos;
        const uint64_t n = value<uint32_t>("the length of " + what);
        if (n > left() || n > most)
            throw VdbLayoutProblem("bad length at byte " + std::to_string(start) + ": " + what +
                                   " claims " + std::to_string(n) + " bytes, " +
                                   (n > left() ? std::to_string(left()) + " remain"
                                               : "at most " + std::to_string(most) + " allowed"));
        std::string s(n, '\0');
        if (n) read(s.data(), n, what);
        return s;
    }
    void skip(uint64_t n, const std::string& what) {
        need(n, what);
        seek(mPos + n);
    }

private:
    std::ifstream mIn;
    uint64_t mSize = 0;
    uint64_t mPos = 0;
};

/// OpenVDB's compression flags: zip, active mask, Blosc.
constexpr uint32_t kVdbCompressionFlags = 1 | 2 | 4;

/// Names and types of OpenVDB's objects are short; 4 kB is far beyond any written.
constexpr uint64_t kMaxVdbName = 4096;

/// One array of delayed-load metadata: a uint32 compressed size, then that many bytes of Blosc
/// data, or (size 0) `count · element` raw bytes. Returns the bytes it takes after its size.
uint64_t delayedLoadArray(VdbLayoutReader& in, uint64_t count, uint64_t element,
                          const std::string& what) {
    const uint64_t compressed = in.value<uint32_t>("the compressed size in " + what);
    const uint64_t bytes = compressed == 0 ? count * element : compressed;
    in.skip(bytes, what);
    return bytes;
}

/// OpenVDB's delayed-load metadata: a uint32 count of leaves, then a byte per leaf and an
/// int64 per leaf, each array raw or compressed. OpenVDB allocates 9 bytes a leaf from the
/// count, so the count is held to the leaves the file can hold (each takes at least its 64-byte
/// mask), and the arrays must fill the item's size exactly.
void checkDelayedLoad(VdbLayoutReader& in, uint64_t size, const std::string& what) {
    if (size == 0) return;
    const uint64_t start = in.at();
    const uint64_t leaves = in.value<uint32_t>(what + "'s leaf count");
    if (leaves > in.size() / 64)
        throw VdbLayoutProblem("bad count at byte " + std::to_string(start) + ": " + what +
                               " claims " + std::to_string(leaves) + " leaves, more than a " +
                               std::to_string(in.size()) + "-byte file can hold");
    uint64_t used = 4 + 4 + delayedLoadArray(in, leaves, 1, what);
    used += 4 + delayedLoadArray(in, leaves, 8, what);
    if (used != size)
        throw VdbLayoutProblem("bad size at byte " + std::to_string(start - 4) + ": " + what +
                               " claims " + std::to_string(size) + " bytes, its arrays take " +
                               std::to_string(used));
}

void checkMetadata(VdbLayoutReader& in, const std::string& owner) {
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
        const std::string type = in.string("the type of " + what, kMaxVdbName);
        const uint64_t sizeAt = in.at();
        const uint64_t size = in.value<uint32_t>("the size of " + what);
        in.need(size, what);
        const uint64_t fixed = fixedMetadataSize(type);
        if (fixed && size != fixed)
            throw VdbLayoutProblem("bad size at byte " + std::to_string(sizeAt) + ": " + what +
                                   " of type " + type + " claims " + std::to_string(size) +
                                   " bytes, a " + type + " has " + std::to_string(fixed));
        if (type == "__delayedload")
            checkDelayedLoad(in, size, what);
        else
            in.skip(size, what);
    }
}

void checkHeader(VdbLayoutReader& in) {
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
}

/// Grid `index`'s descriptor at the reader's position, its section's offsets, and at its
/// offset its compression, metadata and transform type. Returns where the next one starts.
uint64_t checkGrid(VdbLayoutReader& in, int64_t index) {
    const std::string which = "grid " + std::to_string(index + 1);
    const std::string name = in.string("the name of " + which, kMaxVdbName);
    const std::string grid = "grid '" + name + "'";
    in.string("the type of " + grid, kMaxVdbName);
    in.string("the instance parent of " + grid, kMaxVdbName);
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
    checkMetadata(in, grid);
    in.string("the transform type of " + grid, kMaxVdbName);
    if (in.at() > uint64_t(pos[1]))
        throw VdbLayoutProblem("bad offsets: " + grid + "'s metadata runs to byte " +
                               std::to_string(in.at()) + ", past its data at byte " +
                               std::to_string(pos[1]));
    return uint64_t(pos[2]);
}

}  // namespace

std::string checkVdbLayout(const std::string& path) {
    try {
        VdbLayoutReader in(path);
        checkHeader(in);
        checkMetadata(in, "the file");
        const uint64_t countAt = in.at();
        const int64_t grids = in.value<int32_t>("the grid count");
        // A descriptor takes at least three string lengths and three offsets: 36 bytes.
        if (grids < 0 || uint64_t(grids) > in.left() / 36)
            throw VdbLayoutProblem("bad count at byte " + std::to_string(countAt) + ": " +
                                   std::to_string(grids) + " grids, " + std::to_string(in.left()) +
                                   " bytes remain");
        for (int64_t g = 0; g < grids; ++g) in.seek(checkGrid(in, g));
        return "";
    } catch (const VdbLayoutProblem& e) {
        return e.what();
    }
}

}  // namespace kerf
