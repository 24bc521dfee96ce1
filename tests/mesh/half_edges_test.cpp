// Half-edge validation on crafted meshes whose counts are known by construction.
#include "mesh/half_edges.h"
#include "mesh/mesh_files.h"

#include <catch2/catch.hpp>

#include <stdexcept>

using namespace kerf;
using namespace kerf::test;

namespace {

/// The unit cube as 12 outward triangles over 8 vertices (vertex i has coordinates given by
/// its bits: x = bit 0, y = bit 1, z = bit 2).
TriangleMesh cubeMesh() {
    TriangleMesh m;
    for (int i = 0; i < 8; ++i) m.positions.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    const std::array<uint32_t, 4> quads[6] = {
        {0, 2, 3, 1}, {4, 5, 7, 6},  // z = 0, z = 1
        {0, 1, 5, 4}, {2, 6, 7, 3},  // y = 0, y = 1
        {0, 4, 6, 2}, {1, 3, 7, 5},  // x = 0, x = 1
    };
    for (const auto& q : quads) {
        m.triangles.push_back({q[0], q[1], q[2]});
        m.triangles.push_back({q[0], q[2], q[3]});
    }
    return m;
}

}  // namespace

TEST_CASE("validateMesh::closed meshes are solids") {
    for (const TriangleMesh& mesh : {octahedronMesh(), cubeMesh()}) {
        const MeshReport r = validateMesh(mesh);
        // Euler: V - E + F = 2 with E = 3F / 2 for a closed triangle mesh of genus 0.
        CHECK(r.vertices == mesh.positions.size());
        CHECK(r.triangles == mesh.triangles.size());
        CHECK(long(r.vertices) - long(3 * r.triangles / 2) + long(r.triangles) == 2);
        CHECK(r.boundaryEdges == 0);
        CHECK(r.nonManifoldEdges == 0);
        CHECK(r.inconsistentEdges == 0);
        CHECK(r.degenerateTriangles == 0);
        CHECK(r.solid);
        CHECK_FALSE(r.firstBadEdge);
    }
    // Every outward cube face's normal points away from the centre: the crafted cube is right.
    const TriangleMesh cube = cubeMesh();
    for (const auto& t : cube.triangles) {
        const Vec3 n = glm::cross(cube.positions[t[1]] - cube.positions[t[0]],
                                  cube.positions[t[2]] - cube.positions[t[0]]);
        CHECK(glm::dot(n, cube.positions[t[0]] - Vec3(0.5)) > 0.0);
    }
}

TEST_CASE("buildHalfEdges::twins are mutual and run the other way") {
    const TriangleMesh mesh = octahedronMesh();
    const HalfEdges he = buildHalfEdges(mesh);
    REQUIRE(he.twin.size() == 24);
    for (uint32_t h = 0; h < he.twin.size(); ++h) {
        REQUIRE(he.twin[h] != HalfEdges::kNone);
        CHECK(he.twin[he.twin[h]] == h);
        CHECK(he.origin[he.twin[h]] == he.origin[HalfEdges::next(h)]);
        CHECK(he.origin[HalfEdges::next(he.twin[h])] == he.origin[h]);
    }
}

TEST_CASE("validateMesh::split vertices are welded by position") {
    // The octahedron with every triangle on its own three vertices (as an STL keeps them).
    const TriangleMesh shared = octahedronMesh();
    TriangleMesh split;
    for (const auto& t : shared.triangles) {
        const uint32_t base = static_cast<uint32_t>(split.positions.size());
        for (uint32_t v : t) split.positions.push_back(shared.positions[v]);
        split.triangles.push_back({base, base + 1, base + 2});
    }
    const MeshReport r = validateMesh(split);
    CHECK(r.vertices == 6);
    CHECK(r.solid);
}

TEST_CASE("validateMesh::an open box has four boundary edges") {
    TriangleMesh box = cubeMesh();
    box.triangles.erase(box.triangles.begin() + 2, box.triangles.begin() + 4);  // no z = 1 face
    const MeshReport r = validateMesh(box);
    CHECK(r.triangles == 10);
    CHECK(r.boundaryEdges == 4);
    CHECK(r.nonManifoldEdges == 0);
    CHECK(r.inconsistentEdges == 0);
    CHECK_FALSE(r.solid);
    REQUIRE(r.firstBadEdge);
    CHECK(r.firstBadEdge->fault == EdgeFault::Boundary);
    // The bad edge is one of the missing face's sides: both ends at z = 1.
    CHECK(r.firstBadEdge->pa.z == 1.0);
    CHECK(r.firstBadEdge->pb.z == 1.0);
    CHECK(r.firstBadEdge->pa == box.positions[r.firstBadEdge->a]);
    CHECK(describeBadEdge(*r.firstBadEdge).find("boundary edge from vertex") == 0);
}

TEST_CASE("validateMesh::three triangles on one edge are non-manifold") {
    TriangleMesh m = octahedronMesh();
    // A fin on the edge from +x (0) to +y (2), towards a new vertex off the surface.
    m.positions.push_back(kOctaCenter + Vec3(3.0, 3.0, 0.0));
    m.triangles.push_back({0, 2, 6});
    const MeshReport r = validateMesh(m);
    CHECK(r.nonManifoldEdges == 1);
    CHECK(r.boundaryEdges == 2);  // the fin's two free sides
    CHECK(r.inconsistentEdges == 0);
    CHECK_FALSE(r.solid);
    const HalfEdges he = buildHalfEdges(m);
    CHECK(he.twin[3 * 8] == HalfEdges::kNone);  // the fin's edge 0 -> 2 has no twin
}

TEST_CASE("validateMesh::a flipped face is inconsistently oriented") {
    TriangleMesh m = octahedronMesh();
    std::swap(m.triangles[5][1], m.triangles[5][2]);
    const MeshReport r = validateMesh(m);
    CHECK(r.inconsistentEdges == 3);  // each of its edges now runs the same way as a neighbour's
    CHECK(r.boundaryEdges == 0);
    CHECK(r.nonManifoldEdges == 0);
    CHECK_FALSE(r.solid);
    REQUIRE(r.firstBadEdge);
    CHECK(r.firstBadEdge->fault == EdgeFault::Inconsistent);
}

TEST_CASE("validateMesh::degenerate triangles are counted") {
    SECTION("a repeated vertex takes no part in the edges") {
        TriangleMesh m = octahedronMesh();
        m.triangles.push_back({0, 0, 2});
        const MeshReport r = validateMesh(m);
        CHECK(r.degenerateTriangles == 1);
        CHECK(r.boundaryEdges == 0);
        CHECK(r.solid);
    }
    SECTION("a repeated position counts as a repeated vertex") {
        TriangleMesh m = octahedronMesh();
        m.positions.push_back(m.positions[0]);
        m.triangles.push_back({0, 6, 2});
        CHECK(validateMesh(m).degenerateTriangles == 1);
    }
    SECTION("three collinear corners have zero area") {
        TriangleMesh m;
        m.positions = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
        m.triangles = {{0, 1, 2}};
        const MeshReport r = validateMesh(m);
        CHECK(r.degenerateTriangles == 1);
        CHECK(r.boundaryEdges == 3);
        CHECK_FALSE(r.solid);
    }
}

TEST_CASE("validateMesh::an index past the positions is an error, not a read") {
    TriangleMesh m = octahedronMesh();
    m.triangles.push_back({0, 2, 6});
    CHECK_THROWS_AS(validateMesh(m), std::out_of_range);
}
