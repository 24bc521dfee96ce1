// Issue 24: no mesh reader allocates more than 4x the file's size plus kMeshPeakAllowance
// before it has validated the file. `kerf check` of a model naming a hostile file is measured
// against the same command on the format's tiny valid octahedron (docs/robustness.md).
#include "mesh/mesh_files.h"

#include "app/kerf_peak_memory.h"

#include <catch2/catch.hpp>

using namespace kerf::test;

namespace {

/// The documented constant above the baseline (docs/robustness.md, "Limits").
constexpr int64_t kMeshPeakAllowance = 64ll << 20;

KerfPeakRun checkMeshModel(const TempDir& dir, const std::string& name, const std::string& bytes) {
    dir.write(name, bytes);
    dir.write("model.kerf", "object mesh \"" + name + "\";\n");
    return runKerfMeasuringPeak(dir, {"check", "model.kerf"});
}

std::string glbHeaderClaiming(uint32_t jsonLength) {
    std::string glb = "glTF";
    appendBytes(glb, uint32_t(2));
    appendBytes(glb, uint32_t(640));
    appendBytes(glb, jsonLength);
    glb += "JSON";
    glb.resize(640, ' ');
    return glb;
}

std::string stlClaimingFacets(uint32_t facets) {
    auto octa = octahedronFacets();
    return stlBinary(octa, facets);
}

std::string octahedronOff() {
    return "OFF\n6 8 0\n1.25 0 0\n-1.25 0 0\n0 1.25 0\n0 -1.25 0\n0 0 1.25\n0 0 -1.25\n"
           "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n";
}

std::string gltfClaimingAccessorCount() {
    std::string json = gltfText();
    const std::string count = R"("count": 6,)";
    return json.replace(json.find(count), count.size(), R"("count": 4000000000,)");
}

}  // namespace

TEST_CASE("loadMesh::hostile headers and counts cost no more than the file justifies") {
    struct Case {
        const char* format;
        std::string validName, valid, hostileName, hostile;
    };
    const Case cases[] = {
        {"OBJ", "ok.obj", objText(), "bad.obj", "v 0 0 0\nv 1 0 0\nf 1 2 4294967295\n"},
        {"PLY ASCII", "ok.ply", plyAsciiText(), "bad.ply",
         plyHeader("ascii", 4000000000u, 4000000000u) + "0 0 0\n"},
        {"PLY binary", "ok.ply", plyBinaryText(), "bad.ply",
         plyHeader("binary_little_endian", 1000000000u, 1000000000u)},
        {"STL ASCII", "ok.stl", stlAsciiText(), "bad.stl",
         "solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"},
        {"STL binary", "ok.stl", stlBinaryText(), "bad.stl", stlClaimingFacets(0xFFFFFFFFu)},
        {"glTF", "ok.gltf", gltfText(), "bad.gltf", gltfClaimingAccessorCount()},
        {"GLB", "ok.glb", glbText(), "bad.glb", glbHeaderClaiming(0xFFFFFFF0u)},
        {"OFF", "ok.off", octahedronOff(), "bad.off", "OFF\n4000000000 4000000000 0\n0 0 0\n"},
    };
    for (const Case& c : cases) {
        SECTION(c.format) {
            TempDir good, bad;
            const KerfPeakRun baseline = checkMeshModel(good, c.validName, c.valid);
            const KerfPeakRun hostile = checkMeshModel(bad, c.hostileName, c.hostile);
            INFO(c.format << ": " << hostile.err);
            CHECK(baseline.exitCode == 0);
            CHECK(hostile.exitCode == 2);
            CHECK(hostile.err.find(c.hostileName) != std::string::npos);
            if (kUnderAddressSanitizer) return;
            const int64_t bound =
                baseline.peakRss + 4 * int64_t(c.hostile.size()) + kMeshPeakAllowance;
            INFO("peak " << hostile.peakRss << " bytes, baseline " << baseline.peakRss);
            CHECK(hostile.peakRss <= bound);
            WARN(c.format << ": baseline " << baseline.peakRss / 1024 << " kB, hostile "
                          << hostile.peakRss / 1024 << " kB, file " << c.hostile.size() << " B");
        }
    }
}
