// A .vdb file's layout is checked before OpenVDB reads it (volume/grids/checked_vdb_layout.h):
// every 32-bit word of the header, the metadata and the grid descriptors of a small valid
// file, set to 0xFFFFFFF0 and to 0x7FFFFFFF, gives a reader's error or a file that still reads,
// never another exception (OpenVDB trusted those lengths: 4–6 GB and "out of memory"); a
// truncated file says it is truncated; through the CLI each kind exits 2 with the file named,
// and its peak memory stays within the baseline plus 4× the file plus 64 MB.
#include "volume/grids/checked_vdb_layout.h"
#include "volume/grids/vdb_fog.h"
#include "volume/grids/vdb_level_set.h"

#include "../app/kerf_peak_memory.h"
#include "util/level_set_files.h"
#include "util/vdb_file_bytes.h"

#include <catch2/catch.hpp>

#include <cstring>
#include <fstream>

using namespace kerf;
using kerf::test::TempDir;

namespace {

std::string vdbBytes(const std::string& path) { return test::fileBytes(path); }
void writeVdbBytes(const std::string& path, const std::string& bytes) {
    test::writeBytes(path, bytes);
}
std::string levelSetVerdict(const std::string& path) { return test::readerVerdict(path, false); }
std::string fogVerdict(const std::string& path) { return test::readerVerdict(path, true); }

/// Where the first grid's transform type string starts: the end of the part kerf checks.
size_t transformStart(const std::string& bytes) {
    for (const char* type : {"UniformScaleMap", "ScaleMap", "AffineMap", "UniformScaleTranslateMap",
                             "ScaleTranslateMap", "TranslationMap"}) {
        const size_t at = bytes.find(type);
        if (at != std::string::npos) return at - 4;
    }
    return bytes.size();
}

}  // namespace

TEST_CASE("checkVdbLayout/every header and metadata word corrupted is a reader's error",
          "[volume]") {
    TempDir dir;
    const std::string good = dir.file("good.vdb");
    const std::string bad = dir.file("bad.vdb");
    for (const bool fog : {false, true}) {
        CAPTURE(fog);
        test::writeGrids(good, {fog ? test::fogGrid() : test::sphereGrid(0.5, Vec3(0.0), 0.1)});
        CHECK(checkVdbLayout(good).empty());
        const std::string bytes = vdbBytes(good);
        const size_t end = transformStart(bytes);
        REQUIRE(end < bytes.size());
        for (const uint32_t word : {0xFFFFFFF0u, 0x7FFFFFFFu}) {
            for (size_t at = 0; at + 4 <= end; ++at) {
                std::string corrupt = bytes;
                std::memcpy(&corrupt[at], &word, 4);
                writeVdbBytes(bad, corrupt);
                CAPTURE(at, word);
                const std::string verdict = fog ? fogVerdict(bad) : levelSetVerdict(bad);
                CHECK(verdict.rfind("UNEXPECTED", 0) == std::string::npos);
                CHECK(verdict.find("out of memory") == std::string::npos);
                CHECK(verdict.find("bad_alloc") == std::string::npos);
            }
        }
    }
}

TEST_CASE("checkVdbLayout/what is wrong and where", "[volume]") {
    TempDir dir;
    const std::string path = dir.file("fog.vdb");
    test::writeGrids(path, {test::fogGrid()});
    const std::string bytes = vdbBytes(path);
    const auto corrupted = [&](size_t at, uint32_t word) {
        std::string c = bytes;
        std::memcpy(&c[at], &word, 4);
        writeVdbBytes(path, c);
        return checkVdbLayout(path);
    };
    // The grid's name length (after the 57-byte header, the file's empty metadata and the
    // grid count).
    CHECK(corrupted(65, 0xFFFFFFF0u) ==
          "bad length at byte 65: the name of grid 1 claims 4294967280 bytes, " +
              std::to_string(bytes.size() - 69) + " remain");
    CHECK(corrupted(57, 0x7FFFFFFFu)
              .rfind("bad count at byte 57: the file claims 2147483647 "
                     "metadata items",
                     0) == 0);
    CHECK(corrupted(8, 300u) ==
          "file version 300 at byte 8; kerf reads 220 to 224 (OpenVDB 3 to 10)");
    // Truncated: the reader says so, with the bytes expected (it said "has no grids").
    writeVdbBytes(path, bytes.substr(0, bytes.size() / 2));
    CHECK(checkVdbLayout(path) == "truncated: grid 'density' ends at byte " +
                                      std::to_string(bytes.size()) + " but the file has " +
                                      std::to_string(bytes.size() / 2) + " bytes");
    CHECK(fogVerdict(path) == checkVdbLayout(path));
    CHECK(levelSetVerdict(path) == checkVdbLayout(path));
    writeVdbBytes(path, bytes.substr(0, 40));
    CHECK(checkVdbLayout(path) == "truncated at byte 21: the UUID needs 36 bytes, 19 remain of 40");
}

TEST_CASE("checkVdbLayout/the CLI names the file, exits 2, and memory stays bounded", "[volume]") {
    TempDir dir;
    test::writeGrids(dir.file("ls.vdb"), {test::sphereGrid(0.5, Vec3(0.0), 0.1)});
    test::writeGrids(dir.file("fog.vdb"), {test::fogGrid()});
    dir.write("ls.kerf", "object volume \"ls.vdb\";\n");
    dir.write("fog.kerf", "mist { density volume \"fog.vdb\" }\n");
    for (const std::string kind : {"ls", "fog"}) {
        CAPTURE(kind);
        const test::KerfPeakRun baseline =
            test::runKerfMeasuringPeak(dir, {"check", kind + ".kerf"});
        REQUIRE(baseline.exitCode == 0);
        const std::string bytes = vdbBytes(dir.file(kind + ".vdb"));
        // The grid's name length, the file's metadata count, and the grid's first metadata
        // item's name length, each claiming 4 GB.
        for (const size_t at : {size_t(65), size_t(57), size_t(bytes.find("class") - 4)}) {
            CAPTURE(at);
            std::string c = bytes;
            const uint32_t word = 0xFFFFFFF0u;
            std::memcpy(&c[at], &word, 4);
            writeVdbBytes(dir.file("bad.vdb"), c);
            dir.write("bad.kerf", kind == "ls" ? "object volume \"bad.vdb\";\n"
                                               : "mist { density volume \"bad.vdb\" }\n");
            const test::KerfPeakRun run = test::runKerfMeasuringPeak(dir, {"check", "bad.kerf"});
            INFO(run.err);
            CHECK(run.exitCode == 2);
            CHECK(run.err.find("'bad.vdb'") != std::string::npos);
            CHECK(run.err.find("out of memory") == std::string::npos);
            if (!test::kUnderAddressSanitizer)
                CHECK(run.peakRss <= baseline.peakRss + 4 * int64_t(c.size()) + (64 << 20));
        }
    }
}
