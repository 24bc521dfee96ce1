// A float grid's tree is walked before OpenVDB reads it (volume/grids/checked_vdb_tree.h).
// Found by kerf_fuzz_vdb: a compressed chunk's 64-bit size made OpenVDB's bloscFromStream ask
// for 64 GB (the release build's bad_alloc became "its grids ask for more memory than there
// is"; the fuzz build's allocator aborted). Files written in every storage OpenVDB has (Blosc,
// zip, none; with and without active-mask compression; floats and halves) pass the walk and
// load, which says the walk reads the format as OpenVDB does (it must end where the file's
// offsets say); every word of their trees corrupted is a reader's message, never an
// allocation the file cannot back.
#include "volume/grids/checked_vdb_layout.h"

#include "../app/kerf_runner.h"
#include "util/level_set_files.h"
#include "util/vdb_file_bytes.h"

#include <catch2/catch.hpp>

#include <cstring>

using namespace kerf;
using kerf::test::TempDir;

namespace {

using test::fileBytes;
using test::writeBytes;

std::string verdict(const std::string& path, bool fog) { return test::readerVerdict(path, fog); }

struct Storage {
    const char* name;
    VdbCompression compression;
    bool half;
};

using Codec = VdbCompression::Codec;
const Storage kStorages[] = {
    {"blosc, active mask", {Codec::Blosc, true}, false},
    {"zip, active mask", {Codec::Zip, true}, false},
    {"none, active mask", {Codec::None, true}, false},
    {"blosc, all values", {Codec::Blosc, false}, false},
    {"zip, all values", {Codec::Zip, false}, false},
    {"blosc, halves", {Codec::Blosc, true}, true},
    {"none, all values, halves", {Codec::None, false}, true},
};

test::Grid gridFor(bool fog, bool half) {
    test::Grid g = fog ? test::fogGrid() : test::sphereGrid(0.5, Vec3(0.0), 0.1);
    g.saveAsHalf = half;
    return g;
}

/// Where the first grid's tree starts: after its transform's type name and its 5·24 bytes
/// (the test grids have a UniformScaleMap).
size_t treeStart(const std::string& bytes) {
    const size_t name = bytes.find("UniformScaleMap");
    return name == std::string::npos ? bytes.size() : name + 15 + 5 * 24;
}

}  // namespace

TEST_CASE("checkVdbLayout/float trees in every storage pass the walk and load", "[volume]") {
    TempDir dir;
    for (const Storage& s : kStorages) {
        for (const bool fog : {false, true}) {
            CAPTURE(s.name, fog);
            const std::string path = dir.file("tree.vdb");
            test::writeGrids(path, {gridFor(fog, s.half)}, s.compression);
            const std::string problem = checkVdbLayout(path);
            CAPTURE(problem);
            CHECK(problem.empty());
            CHECK(verdict(path, fog).empty());
        }
    }
}

TEST_CASE("checkVdbLayout/every word of a float tree corrupted is a reader's message", "[volume]") {
    TempDir dir;
    const std::string good = dir.file("good.vdb");
    const std::string bad = dir.file("bad.vdb");
    // The storages whose chunks carry sizes (uncompressed ones are read in sizes the masks
    // fix).
    for (const Storage& s : {kStorages[0], kStorages[4]}) {
        for (const bool fog : {false, true}) {
            CAPTURE(s.name, fog);
            test::writeGrids(good, {gridFor(fog, s.half)}, s.compression);
            const std::string bytes = fileBytes(good);
            const size_t start = treeStart(bytes);
            REQUIRE(start < bytes.size());
            // Every offset of the root's counts and first origin, then about 120 spread over
            // the rest at a step prime to 4 and 8 (a chunk's size is an int64 at any offset;
            // its high word set to 0x7FFFFFFF asks for 9e18 bytes).
            const size_t step = ((bytes.size() - start) / 120) | 1;
            for (size_t at = start; at + 4 <= bytes.size(); at += at < start + 32 ? 1 : step) {
                for (const uint32_t word : {0xFFFFFFF0u, 0x7FFFFFFFu}) {
                    std::string corrupt = bytes;
                    std::memcpy(&corrupt[at], &word, 4);
                    writeBytes(bad, corrupt);
                    const std::string v = verdict(bad, fog);
                    CAPTURE(at, word, v);
                    CHECK(v.rfind("UNEXPECTED", 0) == std::string::npos);
                    CHECK(v.find("more memory than there is") == std::string::npos);
                    CHECK(v.find("out of memory") == std::string::npos);
                }
            }
        }
    }
}

TEST_CASE("checkVdbLayout/what is wrong in a tree and where", "[volume]") {
    TempDir dir;
    const std::string path = dir.file("fog.vdb");
    test::writeGrids(path, {test::fogGrid()});
    const std::string bytes = fileBytes(path);
    const size_t start = treeStart(bytes);
    const auto corrupted = [&](size_t at, const void* value, size_t size) {
        std::string c = bytes;
        std::memcpy(&c[at], value, size);
        writeBytes(path, c);
        return checkVdbLayout(path);
    };
    // The tree: int32 buffer count, float background, uint32 tiles, uint32 children, then the
    // first child's origin and its two 4 kB masks, its compression byte and its values' size.
    const uint32_t tiles = 0x7FFFFFFF;
    CHECK(corrupted(start + 8, &tiles, 4)
              .rfind("bad count at byte " + std::to_string(start + 16) +
                         ": grid 'density''s root claims 2147483647 tiles and 1 children, ",
                     0) == 0);
    const int32_t origin = 100;
    CHECK(corrupted(start + 16, &origin, 4) ==
          "bad origin at byte " + std::to_string(start + 16) +
              ": root child 1 of grid 'density' is at (100, 0, 0), not a multiple of 4096");
    const size_t sizeAt = start + 28 + 2 * 4096 + 1;
    const int64_t huge = int64_t(1) << 36;
    const std::string message = corrupted(sizeAt, &huge, 8);
    CHECK(message.rfind("bad size at byte " + std::to_string(sizeAt) +
                            ": the values of root child 1 of grid 'density' claim 68719476736 "
                            "compressed bytes, ",
                        0) == 0);
    CHECK(verdict(path, true) == message);
    // A raw chunk of another length than the node's values.
    const int64_t raw = -12;
    CHECK(corrupted(sizeAt, &raw, 8).find("are 12 uncompressed bytes, not the ") !=
          std::string::npos);
}

TEST_CASE("checkVdbLayout/two root entries at one origin are refused", "[volume]") {
    // Found by kerf_fuzz_vdb: OpenVDB keeps the last and leaks the node it replaces.
    TempDir dir;
    const std::string path = dir.file("two.vdb");
    test::Grid g = test::fogGrid();
    g.values.push_back({{5000, 0, 0}, 0.5f});  // a second root child, at (4096, 0, 0)
    test::writeGrids(path, {g});
    CHECK(checkVdbLayout(path).empty());
    std::string bytes = fileBytes(path);
    const std::string second("\x00\x10\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00", 12);
    const size_t at = bytes.find(second, treeStart(bytes) + 16 + 12);
    REQUIRE(at != std::string::npos);
    bytes.replace(at, 12, std::string(12, '\0'));
    writeBytes(path, bytes);
    CHECK(checkVdbLayout(path) ==
          "bad tree: grid 'density''s root has 1 entries at an origin an earlier one has");
}
