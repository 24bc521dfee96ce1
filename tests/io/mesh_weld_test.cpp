// `kerf mesh` writes one vertex per position: a mesher's two vertices at a sharp feature, or
// two doubles that PLY's and STL's floats make equal, are joined before encoding, so kerf's
// reader finds every edge shared by the two faces beside it.
#include "io/mesh_weld.h"
#include "io/mesh_writers.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

using namespace kerf;

namespace {

/// A tetrahedron whose apex is written twice (vertices 3 and 4 at one point), each copy used
/// by some of its faces: the edges to the apex do not pair unless the copies are joined.
/// `apart` is added to the second copy's x.
struct SplitTetrahedron {
    std::vector<double> xyz;
    std::vector<uint32_t> indices{0, 2, 1, 0, 1, 3, 1, 2, 4, 2, 0, 4};
    explicit SplitTetrahedron(double apart)
        : xyz{0, 0, 0, 1, 0, 0, 0, 1, 0, 0.25, 0.25, 1, 0.25 + apart, 0.25, 1} {}
    MeshArrays arrays() const { return {xyz.data(), 5, indices.data(), 4}; }
};

size_t objVertexLines(const std::string& obj) {
    size_t n = 0;
    for (size_t at = obj.find("\nv "); at != std::string::npos; at = obj.find("\nv ", at + 1)) ++n;
    return n;
}

}  // namespace

TEST_CASE("weldWrittenPositions joins exactly-equal positions") {
    const SplitTetrahedron tet(0.0);
    const WeldedMesh welded = weldWrittenPositions(tet.arrays(), false);
    CHECK(welded.xyz.size() == 12);
    CHECK(welded.indices == std::vector<uint32_t>{0, 2, 1, 0, 1, 3, 1, 2, 3, 2, 0, 3});
    CHECK(objVertexLines(encodeMesh(MeshFormat::Obj, tet.arrays())) == 4);
}

TEST_CASE("weldWrittenPositions joins positions equal as floats for PLY and STL only") {
    const SplitTetrahedron tet(1e-12);  // the same float, another double
    CHECK(weldWrittenPositions(tet.arrays(), false).xyz.size() == 15);
    CHECK(weldWrittenPositions(tet.arrays(), true).xyz.size() == 12);
    CHECK(objVertexLines(encodeMesh(MeshFormat::Obj, tet.arrays())) == 5);
    // PLY: the header's vertex count.
    CHECK_THAT(encodeMesh(MeshFormat::Ply, tet.arrays()), Catch::Contains("element vertex 4\n"));
}

TEST_CASE("weldWrittenPositions drops a triangle left with two equal corners") {
    // One triangle whose corners 1 and 2 are the same point (+0 and -0 count as equal).
    const std::vector<double> xyz{0, 0, 0, 1, 0, 0, 1, -0.0, 0};
    const std::vector<uint32_t> indices{0, 1, 2};
    const WeldedMesh welded = weldWrittenPositions({xyz.data(), 3, indices.data(), 1}, true);
    CHECK(welded.xyz.size() == 6);
    CHECK(welded.indices.empty());
}
