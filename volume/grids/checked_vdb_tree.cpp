// A float grid's tree walked as OpenVDB reads it (volume/grids/checked_vdb_tree.h). The layout
// of Tree_float_5_4_3, file versions 220–224:
//   topology: int32 buffer count; root: float background, uint32 tiles, uint32 children; per
//     tile int32[3] origin, float value, bool active; per child int32[3] origin and an
//     InternalNode<5>: child mask, value mask, its values (below), then its children in mask
//     order, each an InternalNode<4> of the same form whose children are leaves: a value mask.
//   buffers: per leaf, in the order of the root's table (sorted by origin, one per origin):
//     value mask, (version < 222: int32[3] origin, int8 buffer count), its values.
//   values (io::readCompressedValues): (version ≥ 222) a byte saying which inactive values
//     follow (0, 1 or 2 floats) and whether a selection mask does; then the values, all of the
//     node's or (mask compression) only its active ones, as floats or halves; zipped or Blosc
//     data is an int64 size (≤ 0: that many raw bytes) and the bytes.
#include "volume/grids/checked_vdb_tree.h"

#include <array>
#include <map>
#include <vector>

namespace kerf::vdb_layout {

namespace {

constexpr uint32_t kZip = 1;
constexpr uint32_t kActiveMask = 2;
constexpr uint32_t kBlosc = 4;
constexpr uint32_t kNodeMaskCompressionVersion = 222;

/// io::readCompressedValues' per-node byte: which inactive values and masks follow.
constexpr int8_t kOneInactiveNoMask = 2;
constexpr int8_t kMaskNoInactive = 3;
constexpr int8_t kMaskOneInactive = 4;
constexpr int8_t kMaskTwoInactive = 5;
constexpr int8_t kAllValuesNoMask = 6;

/// A node's mask of 2^(3·log2Dim) bits.
struct NodeMask {
    std::vector<uint64_t> words;

    uint64_t countOn() const {
        uint64_t n = 0;
        for (uint64_t w : words) n += uint64_t(__builtin_popcountll(w));
        return n;
    }
    bool on(uint64_t i) const { return (words[i >> 6] >> (i & 63)) & 1; }
};

uint64_t maskBytes(int log2Dim) { return (uint64_t(1) << (3 * log2Dim)) / 8; }

class TreeWalk {
public:
    TreeWalk(VdbLayoutReader& in, const VdbTreeFormat& format, const std::string& grid)
        : mIn(in), mFormat(format), mGrid(grid) {}

    uint64_t run() {
        const uint64_t countAt = mIn.at();
        const auto bufferCount = mIn.value<int32_t>("the buffer count of " + mGrid);
        if (bufferCount != 1)  // OpenVDB says so on stderr and reads on
            throw VdbLayoutProblem("bad count at byte " + std::to_string(countAt) + ": " + mGrid +
                                   " claims " + std::to_string(bufferCount) +
                                   " buffers; OpenVDB 3 and later write 1");
        root();
        mTopologyEnd = mIn.at();
        buffers();
        return mIn.at();
    }

private:
    std::string at() const { return "at byte " + std::to_string(mIn.at()); }

    NodeMask mask(int log2Dim, const std::string& what) {
        NodeMask m;
        m.words.resize(maskBytes(log2Dim) / 8);
        mIn.read(m.words.data(), maskBytes(log2Dim), what);
        return m;
    }

    void root() {
        mIn.skip(4, "the background of " + mGrid);
        const uint64_t tiles = mIn.value<uint32_t>("the tile count of " + mGrid);
        const uint64_t children = mIn.value<uint32_t>("the child count of " + mGrid);
        // A tile takes 17 bytes, a child at least its origin and two 4 kB masks.
        if (tiles > mIn.left() / 17 || children > mIn.left() / (12 + 2 * maskBytes(5)))
            throw VdbLayoutProblem("bad count " + at() + ": " + mGrid + "'s root claims " +
                                   std::to_string(tiles) + " tiles and " +
                                   std::to_string(children) + " children, " +
                                   std::to_string(mIn.left()) + " bytes remain");
        for (uint64_t t = 0; t < tiles; ++t) {
            const std::string what = "root tile " + std::to_string(t + 1) + " of " + mGrid;
            mLeavesByOrigin[origin(what)];
            mIn.skip(4, "the value of " + what);
            const uint64_t activeAt = mIn.at();
            const auto active = mIn.value<uint8_t>("the active flag of " + what);
            if (active > 1)  // OpenVDB reads it into a bool
                throw VdbLayoutProblem("bad flag at byte " + std::to_string(activeAt) + ": " +
                                       what + "'s active flag is " + std::to_string(active) +
                                       ", not 0 or 1");
        }
        for (uint64_t c = 0; c < children; ++c) {
            const std::string what = "root child " + std::to_string(c + 1) + " of " + mGrid;
            const std::array<int32_t, 3> o = origin(what);
            std::vector<uint16_t> leaves;
            internalNode(5, what, leaves);
            mLeavesByOrigin[o] = std::move(leaves);
        }
        // OpenVDB's table keeps the last entry at an origin and leaks the node it replaces
        // (kerf_fuzz_vdb); OpenVDB never writes two.
        if (mLeavesByOrigin.size() != tiles + children)
            throw VdbLayoutProblem("bad tree: " + mGrid + "'s root has " +
                                   std::to_string(tiles + children - mLeavesByOrigin.size()) +
                                   " entries at an origin an earlier one has");
    }

    /// A root entry's origin: OpenVDB writes multiples of a root child's 4,096 voxels; others
    /// put OpenVDB's coordinate sums past the int32 range.
    std::array<int32_t, 3> origin(const std::string& what) {
        const uint64_t start = mIn.at();
        std::array<int32_t, 3> o{};
        mIn.read(o.data(), sizeof o, "the origin of " + what);
        for (int32_t v : o)
            if (v % 4096 != 0)
                throw VdbLayoutProblem("bad origin at byte " + std::to_string(start) + ": " + what +
                                       " is at (" + std::to_string(o[0]) + ", " +
                                       std::to_string(o[1]) + ", " + std::to_string(o[2]) +
                                       "), not a multiple of 4096");
        return o;
    }

    /// An InternalNode of 2^log2Dim entries a side (5: the root's children, 4: theirs); its
    /// leaves' active counts are appended to `leaves` in the order their buffers are read.
    void internalNode(int log2Dim, const std::string& what, std::vector<uint16_t>& leaves) {
        const NodeMask children = mask(log2Dim, "the child mask of " + what);
        const NodeMask active = mask(log2Dim, "the value mask of " + what);
        const uint64_t entries = uint64_t(1) << (3 * log2Dim);
        const bool old = mFormat.fileVersion < kNodeMaskCompressionVersion;
        values(active, old ? entries - children.countOn() : entries, log2Dim,
               "the values of " + what);
        for (uint64_t i = 0; i < entries; ++i) {
            if (!children.on(i)) continue;
            if (log2Dim == 5) {
                internalNode(4, "a child of " + what, leaves);
            } else {
                const NodeMask leaf = mask(3, "the value mask of a leaf of " + what);
                leaves.push_back(uint16_t(leaf.countOn()));
            }
        }
    }

    /// The leaves' buffers (compressed ones hold the 64-bit sizes OpenVDB allocates).
    void buffers() {
        uint64_t n = 0;
        for (const auto& [o, leaves] : mLeavesByOrigin) {
            for (uint16_t activeCount : leaves) {
                const std::string what = "leaf " + std::to_string(++n) + " of " + mGrid;
                mIn.skip(maskBytes(3), "the value mask of " + what);
                int extraBuffers = 0;
                if (mFormat.fileVersion < kNodeMaskCompressionVersion) {
                    mIn.skip(12, "the origin of " + what);
                    const int stored = mIn.value<int8_t>("the buffer count of " + what);
                    extraBuffers = stored > 1 ? stored - 1 : 0;
                }
                // The topology's mask is the one OpenVDB uses; this copy is skipped.
                values(activeCount, 512, 3, "the values of " + what);
                // Buffers of files before OpenVDB 3 kept for compatibility: all 512 values.
                for (int b = 0; b < extraBuffers; ++b)
                    data(512, mFormat.compression & kZip, "an extra buffer of " + what);
            }
        }
    }

    void values(const NodeMask& active, uint64_t all, int log2Dim, const std::string& what) {
        values(active.countOn(), all, log2Dim, what);
    }

    /// io::readCompressedValues of a node with `all` values, `activeCount` of them active.
    void values(uint64_t activeCount, uint64_t all, int log2Dim, const std::string& what) {
        int8_t kind = kAllValuesNoMask;
        if (mFormat.fileVersion >= kNodeMaskCompressionVersion)
            kind = mIn.value<int8_t>("the compression byte of " + what);
        if (kind == kOneInactiveNoMask || kind == kMaskOneInactive || kind == kMaskTwoInactive)
            mIn.skip(kind == kMaskTwoInactive ? 8 : 4, "the inactive values of " + what);
        if (kind == kMaskNoInactive || kind == kMaskOneInactive || kind == kMaskTwoInactive)
            mIn.skip(maskBytes(log2Dim), "the selection mask of " + what);
        const bool onlyActive = (mFormat.compression & kActiveMask) && kind != kAllValuesNoMask &&
                                mFormat.fileVersion >= kNodeMaskCompressionVersion;
        data(onlyActive ? activeCount : all, mFormat.compression, what);
    }

    /// io::readData (or HalfReader, which reads nothing for no values) of `count` values.
    void data(uint64_t count, uint32_t compression, const std::string& what) {
        if (mFormat.halfFloat && count == 0) return;
        const uint64_t bytes = count * (mFormat.halfFloat ? 2 : 4);
        if (!(compression & (kZip | kBlosc))) {
            mIn.skip(bytes, what);
            return;
        }
        const uint64_t sizeAt = mIn.at();
        const int64_t stored = mIn.value<int64_t>("the compressed size of " + what);
        if (stored <= 0) {  // raw bytes, which OpenVDB requires to be exactly the values
            const uint64_t raw = uint64_t(0) - uint64_t(stored);
            if (raw != bytes)
                throw VdbLayoutProblem("bad size at byte " + std::to_string(sizeAt) + ": " + what +
                                       " are " + std::to_string(raw) +
                                       " uncompressed bytes, not the " + std::to_string(bytes) +
                                       " its masks say");
            mIn.skip(raw, what);
            return;
        }
        if (uint64_t(stored) > mIn.left())
            throw VdbLayoutProblem("bad size at byte " + std::to_string(sizeAt) + ": " + what +
                                   " claim " + std::to_string(stored) + " compressed bytes, " +
                                   std::to_string(mIn.left()) + " remain");
        mIn.skip(uint64_t(stored), what);
    }

    VdbLayoutReader& mIn;
    const VdbTreeFormat mFormat;
    const std::string& mGrid;
    /// Each root child's leaves' active counts, by origin: the order buffers are read in.
    std::map<std::array<int32_t, 3>, std::vector<uint16_t>> mLeavesByOrigin;

public:
    uint64_t mTopologyEnd = 0;
};

}  // namespace

VdbTreeEnds checkFloatTreeLayout(VdbLayoutReader& in, const VdbTreeFormat& format,
                                 const std::string& grid) {
    TreeWalk walk(in, format, grid);
    const uint64_t end = walk.run();
    return {walk.mTopologyEnd, end};
}

}  // namespace kerf::vdb_layout
