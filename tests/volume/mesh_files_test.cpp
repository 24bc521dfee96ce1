// The mesh writers read back: OBJ to the same doubles, PLY and STL to the same floats, the same
// triangles in the same order and winding; a small reader per format, written from the specs.
#include "io/mesh_weld.h"
#include "io/mesh_writers.h"
#include "volume/export/mesh_export.h"

#include "util/compiled_scene.h"
#include "util/scratch_folder.h"

#include <catch2/catch.hpp>

#include <array>
#include <cstdlib>
#include <cstring>
#include <set>
#include <sstream>

using namespace kerf;

namespace {

struct ReadMesh {
    std::vector<double> xyz;
    std::vector<uint32_t> indices;
    std::vector<float> normals;  ///< STL only
};

ReadMesh readObj(const std::string& bytes) {
    ReadMesh m;
    std::istringstream in(bytes);
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("v ", 0) == 0) {
            const char* p = line.c_str() + 2;
            for (int a = 0; a < 3; ++a) {
                char* end;
                m.xyz.push_back(std::strtod(p, &end));
                REQUIRE(end != p);
                p = end;
            }
        } else if (line.rfind("f ", 0) == 0) {
            std::istringstream f(line.substr(2));
            for (int k = 0; k < 3; ++k) {
                uint64_t i = 0;
                REQUIRE(f >> i);
                REQUIRE(i >= 1);
                m.indices.push_back(uint32_t(i - 1));
            }
        } else {
            REQUIRE((line.empty() || line[0] == '#'));
        }
    }
    return m;
}

template <class T>
T take(const std::string& bytes, size_t& at) {
    REQUIRE(at + sizeof(T) <= bytes.size());
    T v;
    std::memcpy(&v, bytes.data() + at, sizeof(T));
    at += sizeof(T);
    return v;
}

ReadMesh readPly(const std::string& bytes) {
    const size_t end = bytes.find("end_header\n");
    REQUIRE(end != std::string::npos);
    std::istringstream header(bytes.substr(0, end));
    std::string line;
    size_t vertices = 0, faces = 0;
    std::vector<std::string> lines;
    while (std::getline(header, line)) lines.push_back(line);
    REQUIRE(lines.at(0) == "ply");
    REQUIRE(lines.at(1) == "format binary_little_endian 1.0");
    for (const std::string& l : lines) {
        if (l.rfind("element vertex ", 0) == 0) vertices = std::stoul(l.substr(15));
        if (l.rfind("element face ", 0) == 0) faces = std::stoul(l.substr(13));
    }
    const std::vector<std::string> properties = {"property float x", "property float y",
                                                 "property float z",
                                                 "property list uchar uint vertex_indices"};
    for (const std::string& p : properties)
        REQUIRE(std::find(lines.begin(), lines.end(), p) != lines.end());
    ReadMesh m;
    size_t at = end + 11;
    for (size_t i = 0; i < 3 * vertices; ++i) m.xyz.push_back(take<float>(bytes, at));
    for (size_t t = 0; t < faces; ++t) {
        REQUIRE(take<uint8_t>(bytes, at) == 3);
        for (int k = 0; k < 3; ++k) m.indices.push_back(take<uint32_t>(bytes, at));
    }
    CHECK(at == bytes.size());
    return m;
}

/// STL has no shared vertices: xyz holds each triangle's three corners.
ReadMesh readStl(const std::string& bytes) {
    REQUIRE(bytes.size() >= 84);
    CHECK(bytes.compare(0, 5, "solid") != 0);  // or readers take it for ASCII
    size_t at = 80;
    const uint32_t count = take<uint32_t>(bytes, at);
    REQUIRE(bytes.size() == 84 + 50 * size_t(count));
    ReadMesh m;
    for (uint32_t t = 0; t < count; ++t) {
        for (int a = 0; a < 3; ++a) m.normals.push_back(take<float>(bytes, at));
        for (int k = 0; k < 9; ++k) m.xyz.push_back(take<float>(bytes, at));
        CHECK(take<uint16_t>(bytes, at) == 0);
    }
    return m;
}

/// The exported sphere with one vertex doubled: a second vertex at the position of the first
/// triangle's first corner, which that triangle then uses (what the mesher wrote where the
/// surface passed through a lattice point before the lattice moved off round coordinates).
WatertightMesh sphereMesh() {
    const Scene scene = test::compiledScene("object sphere { center <0.1, -2, 3e3> radius 1.5 };");
    MeshExportOptions options;
    options.voxel = 0.25;
    MeshExportStats stats;
    WatertightMesh mesh = exportMesh(scene.objects, options, stats);
    mesh.vertices.push_back(mesh.vertices[mesh.triangles[0][0]]);
    mesh.triangles[0][0] = uint32_t(mesh.vertices.size() - 1);
    return mesh;
}

MeshArrays arraysOf(const WatertightMesh& mesh) {
    return {&mesh.vertices[0].x, mesh.vertices.size(), mesh.triangles[0].data(),
            mesh.triangles.size()};
}

}  // namespace

TEST_CASE("mesh_files/OBJ, PLY and STL read back to the same mesh") {
    const WatertightMesh mesh = sphereMesh();
    REQUIRE(mesh.triangles.size() > 50);
    const MeshArrays arrays = arraysOf(mesh);
    test::ScratchFolder folder;

    // What is written is the mesh with equal written positions joined (io/mesh_weld.h).
    SECTION("OBJ: the welded doubles and triangles, no two vertices at one position") {
        const WeldedMesh w = weldWrittenPositions(arrays, false);
        CHECK(w.xyz.size() == 3 * (mesh.vertices.size() - 1));  // the double joined
        writeMeshFile(folder.file("m.obj"), MeshFormat::Obj, arrays);
        const ReadMesh r = readObj(test::slurp(folder.file("m.obj")));
        REQUIRE(r.xyz == w.xyz);
        REQUIRE(r.indices == w.indices);
        std::set<std::array<double, 3>> positions;
        for (size_t i = 0; i < r.xyz.size(); i += 3)
            positions.insert({r.xyz[i], r.xyz[i + 1], r.xyz[i + 2]});
        CHECK(positions.size() == r.xyz.size() / 3);
    }
    SECTION("PLY: the welded floats and triangles") {
        const WeldedMesh w = weldWrittenPositions(arrays, true);
        writeMeshFile(folder.file("m.ply"), MeshFormat::Ply, arrays);
        const ReadMesh r = readPly(test::slurp(folder.file("m.ply")));
        REQUIRE(r.xyz.size() == w.xyz.size());
        for (size_t i = 0; i < w.xyz.size(); ++i) REQUIRE(r.xyz[i] == double(float(w.xyz[i])));
        REQUIRE(r.indices == w.indices);
    }
    SECTION("STL: each triangle's corners as floats, in order, with its outward unit normal") {
        const WeldedMesh w = weldWrittenPositions(arrays, true);
        writeMeshFile(folder.file("m.stl"), MeshFormat::Stl, arrays);
        const ReadMesh r = readStl(test::slurp(folder.file("m.stl")));
        REQUIRE(r.xyz.size() == 3 * w.indices.size());
        const Vec3 centre(0.1, -2, 3e3);
        for (size_t t = 0; t < w.indices.size() / 3; ++t) {
            Vec3 p[3];
            for (int k = 0; k < 3; ++k)
                for (int a = 0; a < 3; ++a) {
                    p[k][a] = w.xyz[3 * size_t(w.indices[3 * t + size_t(k)]) + size_t(a)];
                    REQUIRE(r.xyz[9 * t + 3 * size_t(k) + size_t(a)] == double(float(p[k][a])));
                }
            const Vec3 n(r.normals[3 * t], r.normals[3 * t + 1], r.normals[3 * t + 2]);
            REQUIRE(glm::cross(p[1] - p[0], p[2] - p[0]) != Vec3(0.0));  // none left degenerate
            REQUIRE(glm::length(n) == Approx(1.0).epsilon(1e-6));
            // Counter-clockwise from outside: the normal points away from the centre.
            REQUIRE(glm::dot(n, p[0] - centre) > 0.0);
        }
    }
    CHECK(folder.entries() <= 1);  // no temporary left behind
}

TEST_CASE("mesh_files/the format comes from the extension") {
    MeshFormat f;
    CHECK((meshFormatFromPath("a/b.obj", f) && f == MeshFormat::Obj));
    CHECK((meshFormatFromPath("B.PLY", f) && f == MeshFormat::Ply));
    CHECK((meshFormatFromPath("x.Stl", f) && f == MeshFormat::Stl));
    CHECK_FALSE(meshFormatFromPath("x.png", f));
    CHECK_FALSE(meshFormatFromPath("dir.obj/x", f));
    CHECK_FALSE(meshFormatFromPath("obj", f));
}

TEST_CASE("mesh_files/an empty mesh is a valid empty file") {
    const MeshArrays empty;
    const ReadMesh obj = readObj(encodeMesh(MeshFormat::Obj, empty));
    CHECK(obj.xyz.empty());
    const ReadMesh ply = readPly(encodeMesh(MeshFormat::Ply, empty));
    CHECK(ply.xyz.empty());
    CHECK(encodeMesh(MeshFormat::Stl, empty).size() == 84);
}
