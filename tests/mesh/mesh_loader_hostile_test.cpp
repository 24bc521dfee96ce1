// Issue 24, hostile mesh files (round 3): each case failed on the code before its fix.
#include "mesh/half_edges.h"
#include "mesh/mesh_error_check.h"
#include "mesh/mesh_files.h"
#include "mesh/mesh_loader.h"

#include "app/kerf_runner.h"

#include <catch2/catch.hpp>

#include <limits>

using namespace kerf;
using namespace kerf::test;

namespace {

/// The octahedron glTF with `extraNodes` more nodes chained below node 0 (each the only
/// child of the one before).
std::string gltfWithNodeChain(int extraNodes) {
    std::string json = gltfText();
    std::string nodes = R"("nodes": [{"mesh": 0, "children": [1]})";
    for (int i = 1; i <= extraNodes; ++i)
        nodes += i < extraNodes ? ",{\"children\": [" + std::to_string(i + 1) + "]}" : ",{}";
    const size_t at = json.find(R"("nodes": [{)");
    const size_t end = json.find("}],", at) + 2;
    return json.replace(at, end - at, nodes + "]");
}

}  // namespace

TEST_CASE("loadMesh::a glTF node chain 30,000 deep is refused before the importer recurses") {
    TempDir dir;
    const std::string text = gltfWithNodeChain(30000);
    CHECK(text.size() > 500000);
    requireMeshError(dir.write("chain.gltf", text), "node hierarchy deeper than 1024");
    SECTION("a chain within the limit loads") {
        CHECK(loadMesh(dir.write("short_chain.gltf", gltfWithNodeChain(100))).triangles.size() ==
              8);
    }
    SECTION("a cycle") {
        std::string cyc = gltfText();
        cyc.replace(cyc.find(R"("nodes": [{)"), 11,
                    R"("nodes": [{"children": [1]}, {"children": [0]}, {)");
        requireMeshError(dir.write("cycle.gltf", cyc), "glTF node hierarchy has a cycle");
    }
    SECTION("a child that does not exist") {
        std::string bad = gltfText();
        bad.replace(bad.find(R"("nodes": [{)"), 11, R"("nodes": [{"children": [7], )");
        requireMeshError(dir.write("child.gltf", bad), "has child 7, but the file has 1");
    }
    SECTION("JSON nested 100,000 deep") {
        std::string deep = gltfText();
        deep.insert(deep.size() - 1,
                    ", \"extras\": " + std::string(100000, '[') + std::string(100000, ']'));
        requireMeshError(dir.write("deep.gltf", deep), "nests deeper than 128");
    }
}

TEST_CASE("loadMesh::NaN and infinite vertices are refused in every format") {
    TempDir dir;
    SECTION("OBJ v nan 1 0") {
        requireMeshError(dir.write("nan.obj", "v 0 0 0\nv nan 1 0\nv 1 0 0\nf 1 2 3\n"),
                         "non-finite coordinate (NaN)");
    }
    SECTION("ASCII PLY") {
        std::string text = plyHeader("ascii", 3, 1) + "0 0 0\nnan 1 0\n1 0 0\n3 0 1 2\n";
        requireMeshError(dir.write("nan.ply", text), "non-finite coordinate (NaN)");
    }
    SECTION("binary PLY") {
        std::string text = plyHeader("binary_little_endian", 3, 1);
        const float coords[9] = {0, 0, 0, std::numeric_limits<float>::quiet_NaN(), 1, 0, 1, 0, 0};
        for (float c : coords) appendBytes(text, c);
        appendBytes(text, static_cast<uint8_t>(3));
        for (int32_t v : {0, 1, 2}) appendBytes(text, v);
        requireMeshError(dir.write("nanb.ply", text), "non-finite coordinate (NaN)");
    }
    SECTION("glTF") {
        std::string json = gltfJson("data:application/octet-stream;base64,", false);
        std::string buffer = gltfBuffer();
        const float nan = std::numeric_limits<float>::quiet_NaN();
        std::memcpy(buffer.data() + 4, &nan, 4);
        const std::string uri = "data:application/octet-stream;base64,";
        json.insert(json.find(uri) + uri.size(), base64(buffer));
        requireMeshError(dir.write("nan.gltf", json), "non-finite coordinate (NaN)");
    }
    SECTION("1e308 in an OBJ is beyond single precision, not called plain non-finite") {
        requireMeshError(dir.write("big.obj", "v 0 0 0\nv 1e308 1 0\nv 1 0 0\nf 1 2 3\n"),
                         "beyond the single-precision range (±3.4e38)");
    }
}

TEST_CASE("validateMesh::a mesh of only degenerate triangles is not a solid") {
    TriangleMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
    m.triangles = {{0, 1, 2}, {0, 2, 1}};
    const MeshReport report = validateMesh(m);
    CHECK(report.degenerateTriangles == 2);
    CHECK_FALSE(report.solid);
}

TEST_CASE("loadMesh::a glTF index out of range is an error, not a dropped face") {
    TempDir dir;
    std::string buffer = gltfBuffer();
    const uint16_t bad = 60;
    std::memcpy(buffer.data() + 6 * 3 * sizeof(float) + 2, &bad, 2);
    const std::string uri = "data:application/octet-stream;base64,";
    std::string json = gltfJson(uri, false);
    json.insert(json.find(uri) + uri.size(), base64(buffer));
    requireMeshError(dir.write("index.gltf", json), "vertex index out of range");
}

TEST_CASE("loadMesh::files outside the mesh's folder are refused") {
    TempDir dir;
    dir.write("secret.bin", gltfBuffer());
    fs::create_directories(dir.path() / "meshes");
    SECTION("glTF buffer ../secret.bin") {
        requireMeshError(dir.write("meshes/up.gltf", gltfJson("../secret.bin", false)),
                         "outside the mesh's folder");
    }
    SECTION("OBJ mtllib ../secret.mtl") {
        dir.write("secret.mtl", "newmtl a\nKd 1 0 0\n");
        requireMeshError(dir.write("meshes/up.obj", "mtllib ../secret.mtl\n" + objText()),
                         "outside the mesh's folder");
    }
    SECTION("a buffer beside the mesh loads") {
        dir.write("meshes/octa.bin", gltfBuffer());
        CHECK(loadMesh(dir.write("meshes/beside.gltf", gltfJson("octa.bin", false)))
                  .triangles.size() == 8);
    }
}

TEST_CASE("loadMesh::a PLY property of an unknown type is refused before the importer reserves") {
    // Found by kerf_fuzz_mesh: Assimp reserved the 4e9 declared vertices (48 GB) first.
    TempDir dir;
    std::string text = plyHeader("ascii", 4000000000u, 1) + "0 0 0\n";
    text.replace(text.find("uchar int"), 9, "uchar dddd int");
    requireMeshError(dir.write("type.ply", text), "has a type PLY does not have");
}

TEST_CASE("loadMesh::an ASCII PLY face row of garbage bytes is an error, not abort()") {
    // Found by kerf_fuzz_mesh: Assimp's Triangulate asserted on primitive types the faces
    // did not have, and Debian's Assimp aborts on a failed assertion.
    TempDir dir;
    std::string text = plyAsciiText();
    const size_t faces = text.find("3 ", text.find("end_header"));
    const size_t fifth = [&] {
        size_t at = faces;
        for (int i = 0; i < 5; ++i) at = text.find('\n', at) + 1;
        return at;
    }();
    text.insert(fifth, std::string(120, '\xff'));
    const std::string path = dir.write("garbage.ply", text);
    try {
        const TriangleMesh mesh = loadMesh(path);
        CHECK(mesh.triangles.size() <= 8);
    } catch (const MeshError& e) {
        CHECK(std::string(e.what()).find(path) != std::string::npos);
    }
}

TEST_CASE("loadMesh::a PLY whose end_header is not a line of its own is refused, not endless") {
    // Found by kerf_fuzz_mesh: "end_header;1.25 0 0" made Assimp read at the end for ever.
    TempDir dir;
    std::string text = plyAsciiText();
    text[text.find("end_header") + 10] = ';';
    requireMeshError(dir.write("joined.ply", text), "PLY header has no end_header line");
}

TEST_CASE("loadMesh::PLY rows of no properties are refused, however many are declared") {
    // Found by kerf_fuzz_mesh (tests/fuzz/corpus/mesh/ply-rows-without-properties): misspelt
    // property lines left 4e9 vertex rows of no bytes, which Assimp walked for minutes. The
    // misspelt lines are now refused themselves; rows of no property lines at all too.
    TempDir dir;
    for (const char* format : {"ascii", "binary_little_endian"}) {
        INFO(format);
        const std::string header = plyHeader(format, 4000000000u, 1);
        std::string misspelt = header, bare = header;
        for (const char* axis : {"x", "y", "z"}) {
            const std::string line = std::string("property float ") + axis + "\n";
            misspelt.replace(misspelt.find(line), line.size(),
                             "xroperty float " + std::string(axis) + "\n");
            bare.erase(bare.find(line), line.size());
        }
        requireMeshError(dir.write(std::string(format) + "_misspelt.ply", misspelt + "0 0 0\n"),
                         "PLY header line 4 does not start with format");
        requireMeshError(dir.write(std::string(format) + "_bare.ply", bare + "0 0 0\n"),
                         "PLY element 'vertex' declares 4000000000 rows but no properties");
    }
}

TEST_CASE("loadMesh::a file starting 'ply' is checked as PLY, whatever its first line or name") {
    // Found by kerf_fuzz_mesh (tests/fuzz/corpus/mesh/ply-first-line-not-ply): "ply\x01…" got
    // past the PLY check and Assimp reserved 48 GB for 4e9 declared vertices.
    TempDir dir;
    std::string text = plyHeader("ascii", 4000000000u, 1) + "0 0 0\n";
    text.insert(3, std::string("\x01\0\0*", 4));
    requireMeshError(dir.write("odd.ply", text), "PLY file whose first line is not 'ply'");
    text.erase(3, 4);
    requireMeshError(dir.write("named.off", text), "more than its");
}

TEST_CASE(
    "loadMesh::PLY header lines of no PLY keyword, and element names not a word, are refused") {
    // Found by the one-hour kerf_fuzz_mesh run (tests/fuzz/corpus/mesh/ply-element-name-digits):
    // "element 111…1face 8" and a garbled property line made Assimp ask for 80 GB.
    TempDir dir;
    std::string text = plyAsciiText();
    text.replace(text.find("element face"), 12, "element 1111face");
    requireMeshError(dir.write("digits.ply", text),
                     "is not 'element NAME COUNT' with a NAME that starts with a letter");
    text = plyAsciiText();
    text.replace(text.find("property float y"), 8, "prop\x01\xdc");
    requireMeshError(dir.write("garbled.ply", text),
                     "PLY header line 5 does not start with format, comment, obj_info, element");
    SECTION("comments and obj_info lines still load") {
        text = plyAsciiText();
        text.insert(text.find("element vertex"), "comment made by hand\nobj_info nothing\n");
        CHECK(loadMesh(dir.write("comments.ply", text)).triangles.size() == 8);
    }
}

// Found by kerf_fuzz_mesh (corpus: gltf-nodes-key-twice, gltf-strip-without-corners).
TEST_CASE("loadMesh::the glTF pre-scan reads the keys the importer reads") {
    TempDir dir;
    SECTION("a key twice in one object is refused (readers differ on which one counts)") {
        std::string twice = gltfText();
        twice.insert(twice.size() - 1, R"(, "nodes": [{"mesh": 0}])");
        requireMeshError(dir.write("twice.gltf", twice), "the key \"nodes\" appears twice");
    }
    SECTION("an escaped key is the key it spells") {
        std::string escaped = gltfWithNodeChain(30000);
        escaped.replace(escaped.find(R"("nodes": [{)"), 7, R"("node\u0073")");
        requireMeshError(dir.write("escaped.gltf", escaped), "node hierarchy deeper than 1024");
    }
    SECTION("a strip or fan of fewer than 3 corners (2^32 faces to Assimp)") {
        std::string strip = gltfText();
        strip.replace(strip.find(R"("indices": 1, "mode": 4)"), 23, R"("mode": 5)");
        strip.replace(strip.find(R"("count": 6)"), 10, R"("count": 2)");
        requireMeshError(dir.write("strip.gltf", strip),
                         "a glTF primitive of mode 5 has 2 corners, fewer than the 3 it needs");
        std::string fan = gltfText();
        fan.replace(fan.find(R"({"POSITION": 0}, "indices": 1, "mode": 4)"), 40,
                    R"({}, "mode": 6)");
        requireMeshError(dir.write("fan.gltf", fan), "mode 6 has no corners");
    }
}

// Found by kerf_fuzz_mesh (corpus: off-count-80-digits): Assimp read the face count as a
// wrapping 32-bit number and asked for 53 GB before reading a row.
TEST_CASE("loadMesh::OFF counts are checked against the file before the importer allocates") {
    TempDir dir;
    const std::string rows =
        "1.25 0 0\n-1.25 0 0\n0 1.25 0\n0 -1.25 0\n0 0 1.25\n0 0 -1.25\n"
        "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n";
    CHECK(loadMesh(dir.write("octa.off", "OFF\n6 8 0\n" + rows)).triangles.size() == 8);
    requireMeshError(dir.write("digits.off", "OFF\n6 8" + std::string(80, '1') + " 0\n" + rows),
                     "OFF header: the face count '8111");
    requireMeshError(dir.write("huge.off", "OFF\n4000000000 4000000000 0\n0 0 0\n"),
                     "truncated OFF file: the header declares 4000000000 vertices");
    SECTION("by its first word whatever its name, with the rows its prefix letters ask for") {
        requireMeshError(dir.write("colours.obj", "COFF\n600 8 0\n" + rows),
                         "at least 7232 bytes");  // 600 × 2 × (3 + 3) + 8 × 4
    }
}
