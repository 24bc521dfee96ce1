// A binary PLY whose data starts with the byte '\n' (mesh/ply_line_end.h): Assimp 5.2 alone read
// it one byte off ("no triangles"); kerf reads the values as written.
#include "mesh/half_edges.h"
#include "mesh/mesh_files.h"
#include "mesh/mesh_loader.h"

#include "app/kerf_runner.h"

#include <catch2/catch.hpp>

#include <cstring>

using namespace kerf;
using namespace kerf::test;

TEST_CASE("loadMesh::a binary PLY whose data begins with a newline byte is read as written") {
    const unsigned char xBytes[4] = {0x0a, 0x00, 0x00, 0xbd};  // about -0.03125, low byte '\n'
    float x0;
    std::memcpy(&x0, xBytes, 4);
    const float v[4][3] = {{x0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const uint32_t f[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    std::string text =
        "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\n"
        "property float y\nproperty float z\nelement face 4\n"
        "property list uchar uint vertex_indices\nend_header\n";
    for (const auto& p : v)
        for (float c : p) appendBytes(text, c);
    for (const auto& t : f) {
        appendBytes(text, uint8_t(3));
        for (uint32_t i : t) appendBytes(text, i);
    }
    TempDir dir;
    const TriangleMesh mesh = loadMesh(dir.write("newline.ply", text));
    REQUIRE(mesh.triangles.size() == 4);
    REQUIRE(mesh.positions.size() == 4);
    bool found = false;
    for (const Vec3& p : mesh.positions) found = found || (p.x == double(x0) && p.y == 0.0);
    CHECK(found);
    CHECK(validateMesh(mesh).solid);
}
