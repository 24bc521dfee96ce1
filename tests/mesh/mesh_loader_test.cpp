// loadMesh: every format gives the same octahedron (as a set of oriented triangles), and
// every malformed file is a MeshError naming the file.
#include "mesh/mesh_loader.h"
#include "mesh/half_edges.h"
#include "mesh/mesh_error_check.h"
#include "mesh/mesh_files.h"

#include "app/kerf_runner.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace kerf;
using namespace kerf::test;

TEST_CASE("loadMesh::every format gives the same solid octahedron") {
    TempDir dir;
    const auto expected = canonicalTriangles(octahedronMesh());
    const std::pair<const char*, std::string> files[] = {
        {"octa.obj", objText()},
        {"octa_ascii.ply", plyAsciiText()},
        {"octa_binary.ply", plyBinaryText()},
        {"octa_ascii.stl", stlAsciiText()},
        {"octa_binary.stl", stlBinaryText()},
        {"octa.gltf", gltfText()},
        {"octa.glb", glbText()},
        // A node that mirrors: its triangles are swapped back to face outward.
        {"octa_mirrored.gltf", gltfText(true)},
    };
    for (const auto& [name, text] : files) {
        SECTION(name) {
            const std::string path = dir.write(name, text);
            const TriangleMesh mesh = loadMesh(path);
            CHECK(mesh.source == path);
            CHECK(canonicalTriangles(mesh) == expected);
            // Shared vertices are shared indices, even in STL, which stores corners per facet.
            CHECK(mesh.positions.size() == 6);
            const MeshReport report = validateMesh(mesh);
            CHECK(report.vertices == 6);
            CHECK(report.triangles == 8);
            CHECK(report.boundaryEdges == 0);
            CHECK(report.nonManifoldEdges == 0);
            CHECK(report.inconsistentEdges == 0);
            CHECK(report.degenerateTriangles == 0);
            CHECK(report.solid);
            CHECK_FALSE(report.firstBadEdge);
        }
    }
}

TEST_CASE("loadMesh::quads are triangulated and per-face normals kept") {
    // A unit cube of quads with one normal per face: 24 distinct (position, normal) vertices,
    // which validation welds back to 8 positions.
    TempDir dir;
    const std::string path = dir.write("cube.obj", R"(v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
vn 0 0 -1
vn 0 0 1
vn 0 -1 0
vn 0 1 0
vn -1 0 0
vn 1 0 0
f 1//1 4//1 3//1 2//1
f 5//2 6//2 7//2 8//2
f 1//3 2//3 6//3 5//3
f 4//4 8//4 7//4 3//4
f 1//5 5//5 8//5 4//5
f 2//6 3//6 7//6 6//6
)");
    const TriangleMesh mesh = loadMesh(path);
    CHECK(mesh.triangles.size() == 12);
    CHECK(mesh.positions.size() == 24);
    REQUIRE(mesh.normals.size() == mesh.positions.size());
    // Each corner's normal is its face's, and faces are outward: the normal agrees with the
    // triangle's own orientation.
    for (const auto& t : mesh.triangles) {
        const Vec3 n = glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]],
                                  mesh.positions[t[2]] - mesh.positions[t[0]]);
        for (uint32_t v : t) CHECK(glm::dot(n, mesh.normals[v]) > 0.0);
    }
    const MeshReport report = validateMesh(mesh);
    CHECK(report.vertices == 8);
    CHECK(report.solid);
}

TEST_CASE("loadMesh::malformed files are errors naming the file") {
    TempDir dir;
    SECTION("missing file") { requireMeshError(dir.file("nothing.obj"), "no such file"); }
    SECTION("empty file") { requireMeshError(dir.write("empty.obj", ""), "empty file"); }
    SECTION("a PNG renamed .obj") {
        static const char kPngStart[] =
            "\x89PNG\r\n\x1a\n\0\0\0\rIHDR\0\0\0\x10\0\0\0\x10\x08\x02\0\0\0";
        const std::string png(kPngStart, sizeof kPngStart - 1);
        requireMeshError(dir.write("picture.obj", png), "");
    }
    SECTION("truncated binary STL") {
        auto facets = octahedronFacets();
        facets.resize(3);
        requireMeshError(dir.write("cut.stl", stlBinary(facets, 8)), "truncated binary STL");
    }
    SECTION("truncated binary PLY") {
        // Cut at every byte of the data: Assimp alone would read garbage for the missing part.
        const std::string full = plyBinaryText();
        const size_t data = full.find("end_header\n") + 11;
        for (size_t n = data; n < full.size(); ++n)
            requireMeshError(dir.write("cut.ply", full.substr(0, n)), "truncated binary PLY");
    }
    SECTION("out-of-range index in OBJ") {
        requireMeshError(dir.write("bad_index.obj", objText() + "f 1 2 99\n"), "");
    }
    SECTION("out-of-range index in PLY") {
        std::string text = plyHeader("ascii", 6, 8);
        for (const Vec3& p : octahedronVertices())
            text +=
                std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
        for (int i = 0; i < 7; ++i) text += "3 0 2 4\n";
        text += "3 0 2 99\n";
        requireMeshError(dir.write("bad_index.ply", text), "");
    }
    SECTION("NaN coordinate in binary STL") {
        auto facets = octahedronFacets();
        facets[2][4] = std::numeric_limits<float>::quiet_NaN();
        requireMeshError(dir.write("nan.stl", stlBinary(facets, 8)), "non-finite");
    }
    SECTION("infinite coordinate in binary PLY") {
        std::string text = plyHeader("binary_little_endian", 3, 1);
        const float coords[9] = {0, 0, 0, 1, 0, 0, 0, std::numeric_limits<float>::infinity(), 0};
        for (float c : coords) appendBytes(text, c);
        appendBytes(text, static_cast<uint8_t>(3));
        for (int32_t v : {0, 1, 2}) appendBytes(text, v);
        requireMeshError(dir.write("inf.ply", text), "non-finite");
    }
    SECTION("a binary PLY header declaring a million vertices it does not hold") {
        requireMeshError(
            dir.write("hollow.ply", plyHeader("binary_little_endian", 1000000, 1000000)),
            "truncated binary PLY: the data ends after 0 of the 1000000 'vertex' rows");
    }
    // Issue 24: a "solid" header skipped the check, and Assimp then called the file ASCII.
    SECTION("truncated binary STL whose header starts with solid, as CAD exporters write") {
        auto facets = octahedronFacets();
        facets.resize(3);
        std::string stl = stlBinary(facets, 8);
        stl.replace(0, 14, "solid exported");
        requireMeshError(dir.write("cad.stl", stl),
                         "truncated binary STL: the header declares 8 facets (484 bytes)");
    }
    SECTION("a complete binary STL whose header starts with solid still loads") {
        std::string stl = stlBinaryText();
        stl.replace(0, 14, "solid exported");
        CHECK(loadMesh(dir.write("cad_full.stl", stl)).triangles.size() == 8);
    }
    SECTION("a PLY header with no end_header (Assimp read on at the end for ever)") {
        requireMeshError(dir.write("endless.ply", "ply\nformat ascii 1.0\nelement vertex 3\n"),
                         "PLY header has no end_header line");
    }
    SECTION("an ASCII PLY declaring more rows than its bytes can hold") {
        requireMeshError(dir.write("huge.ply", plyHeader("ascii", 4000000000u, 1) + "0 0 0\n"),
                         "truncated ASCII PLY: the header declares 4000000000 'vertex' rows");
    }
    SECTION("a GLB whose JSON chunk claims 0xFFFFFFF0 bytes") {
        std::string glb = "glTF";
        appendBytes(glb, uint32_t(2));
        appendBytes(glb, uint32_t(640));
        appendBytes(glb, uint32_t(0xFFFFFFF0u));
        glb += "JSON";
        glb.resize(640, ' ');
        requireMeshError(dir.write("claims.glb", glb),
                         "truncated binary glTF: a chunk declares 4294967280 bytes but 620 remain");
    }
    SECTION("a GLB whose header declares more bytes than the file has") {
        std::string glb = "glTF";
        appendBytes(glb, uint32_t(2));
        appendBytes(glb, uint32_t(100000));
        requireMeshError(
            dir.write("short.glb", glb),
            "truncated binary glTF: the header declares 100000 bytes but the file has 12");
    }
    SECTION("no triangles: points only") {
        requireMeshError(dir.write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\np 1 2 3\n"), "");
    }
}

TEST_CASE("loadMesh::UVs are kept per vertex") {
    // A unit square whose UV at each corner equals its (x, y): an open sheet with 4 boundary edges.
    TempDir dir;
    const std::string path = dir.write("sheet.obj",
                                       "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                       "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                       "f 1/1 2/2 3/3 4/4\n");
    const TriangleMesh mesh = loadMesh(path);
    CHECK(mesh.triangles.size() == 2);
    CHECK(mesh.normals.empty());
    REQUIRE(mesh.uvs.size() == mesh.positions.size());
    CHECK(mesh.positions.size() == 4);
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        CHECK(mesh.uvs[v][0] == mesh.positions[v].x);
        CHECK(mesh.uvs[v][1] == mesh.positions[v].y);
    }
    const MeshReport report = validateMesh(mesh);
    CHECK(report.boundaryEdges == 4);
    CHECK_FALSE(report.solid);
}
