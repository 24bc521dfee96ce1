// `kerf check` on models with meshes: one report per distinct file, its counts against those
// worked out by hand for crafted meshes, the BVH's node count against a BVH built here, and
// the errors of bad mesh files through the executable (line:col, caret, exit code 2).
#include "kerf_runner.h"
#include "mesh/mesh_files.h"
#include "mesh/mesh_loader.h"
#include "mesh/triangle_bvh.h"

#include <catch2/catch.hpp>

#include <sstream>

using namespace kerf;
using namespace kerf::test;

namespace {

/// OBJ text of the octahedron (mesh_files.h) with its triangles changed by `edit`.
template <class Edit>
std::string octahedronObj(Edit edit) {
    std::vector<Vec3> v = octahedronVertices();
    std::vector<std::array<uint32_t, 3>> t = octahedronTriangles();
    edit(v, t);
    std::ostringstream s;
    for (const Vec3& p : v) s << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
    for (const auto& f : t) s << "f " << f[0] + 1 << ' ' << f[1] + 1 << ' ' << f[2] + 1 << '\n';
    return s.str();
}

/// The report block of `file` in check's output (from its header to the next header or the end).
std::string meshBlock(const std::string& out, const std::string& file) {
    const size_t start = out.find("  mesh '" + file + "':\n");
    if (start == std::string::npos) return "";
    const size_t end = out.find("  mesh '", start + 1);
    return out.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

bool has(const std::string& block, const std::string& line) {
    return block.find(line + "\n") != std::string::npos;
}

}  // namespace

TEST_CASE("kerf check: a report per mesh file, with counts of crafted faults") {
    TempDir dir;
    const std::string octa = dir.write("parts/octa.obj", objText());
    // One face turned over: each of its three edges runs the same way as its neighbour's.
    const std::string flipped = dir.write(
        "parts/flipped.obj", octahedronObj([](auto&, auto& t) { std::swap(t[0][1], t[0][2]); }));
    // A fin on the edge of vertices 0 and 2: that edge has three faces, the fin's other two
    // edges one each; and a triangle with a repeated vertex.
    const std::string fin = dir.write("parts/fin.obj", octahedronObj([](auto& v, auto& t) {
                                          v.push_back(Vec3(3, 3, 3));
                                          t.push_back({0, 2, 6});
                                          t.push_back({1, 1, 3});
                                      }));
    dir.write("parts/open.obj",
              "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 4\nf 1 4 3\n");  // a square
    dir.write(
        "models/scene.kerf",
        "object mesh \"../parts/octa.obj\";\n"
        "object mesh \"../parts/octa.obj\" translate <4, 0, 0>;\n"  // the same file: one report
        "object mesh \"../parts/flipped.obj\" translate <0, 4, 0>;\n"
        "object mesh \"../parts/fin.obj\" translate <0, 0, 4>;\n"
        "object mesh \"../parts/open.obj\" smooth false translate <0, 0, -4>;\n");
    const KerfRun run = runKerf(dir, {"check", "models/scene.kerf"});
    INFO("stdout:\n" << run.out << "\nstderr:\n" << run.err);
    REQUIRE(run.exitCode == 0);
    const auto countOf = [&](const std::string& text, const std::string& what) {
        size_t n = 0;
        for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
            ++n;
        return n;
    };
    CHECK(countOf(run.out, "  mesh '") == 4);
    CHECK(countOf(run.out, "parts/octa.obj':") == 1);

    const std::string o = meshBlock(run.out, "parts/octa.obj");
    REQUIRE(!o.empty());
    CHECK(has(o, "    vertices:             6"));
    CHECK(has(o, "    triangles:            8"));
    CHECK(has(o, "    boundary edges:       0"));
    CHECK(has(o, "    non-manifold edges:   0"));
    CHECK(has(o, "    inconsistent edges:   0 (two faces running an edge the same way)"));
    CHECK(has(o, "    degenerate triangles: 0"));
    CHECK(has(o, "    solid:                yes"));
    CHECK(o.find("first bad edge") == std::string::npos);
    CHECK(has(
        o, "    BVH nodes:            " + std::to_string(TriangleBvh(loadMesh(octa)).nodeCount())));

    const std::string f = meshBlock(run.out, "parts/flipped.obj");
    CHECK(has(f, "    inconsistent edges:   3 (two faces running an edge the same way)"));
    CHECK(has(f, "    boundary edges:       0"));
    CHECK(has(f, "    solid:                no (renders as a surface; not a CSG operand)"));
    CHECK(f.find("    first bad edge:       inconsistently oriented edge from vertex") !=
          std::string::npos);

    const std::string n = meshBlock(run.out, "parts/fin.obj");
    CHECK(has(n, "    vertices:             7"));
    CHECK(has(n, "    triangles:            10"));
    CHECK(has(n, "    non-manifold edges:   1"));
    CHECK(has(n, "    boundary edges:       2"));
    CHECK(has(n, "    degenerate triangles: 1"));
    CHECK(has(
        n, "    BVH nodes:            " + std::to_string(TriangleBvh(loadMesh(fin)).nodeCount())));

    const std::string s = meshBlock(run.out, "parts/open.obj");
    CHECK(has(s, "    vertices:             4"));
    CHECK(has(s, "    triangles:            2"));
    CHECK(has(s, "    boundary edges:       4"));
    CHECK(s.find("    first bad edge:       boundary edge from vertex") != std::string::npos);
}

TEST_CASE("kerf check: a model without meshes prints no mesh report") {
    TempDir dir;
    dir.write("ball.kerf", kTinySphereModel);
    const KerfRun run = runKerf(dir, {"check", "ball.kerf"});
    REQUIRE(run.exitCode == 0);
    CHECK(run.out.find("mesh") == std::string::npos);
}

TEST_CASE("kerf check: bad mesh files are errors at the mesh with exit code 2") {
    TempDir dir;
    const std::string stl = stlBinaryText();
    dir.write("cut.stl", stl.substr(0, 84 + 50 * 3 + 20));
    dir.write("open.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    SECTION("missing") {
        dir.write("m.kerf", "object sphere { radius 1 };\nobject mesh \"nothing.stl\";\n");
        const KerfRun run = runKerf(dir, {"check", "m.kerf"});
        INFO(run.err);
        CHECK(run.exitCode == 2);
        CHECK(run.err.find("m.kerf:2:13: error: cannot load mesh 'nothing.stl': no such file") !=
              std::string::npos);
        CHECK(run.err.find("object mesh \"nothing.stl\";\n") !=
              std::string::npos);                                     // the source line
        CHECK(run.err.find("\n            ^") != std::string::npos);  // and the caret
    }
    SECTION("truncated") {
        dir.write("m.kerf", "object mesh \"cut.stl\";\n");
        const KerfRun run = runKerf(dir, {"check", "m.kerf"});
        INFO(run.err);
        CHECK(run.exitCode == 2);
        CHECK(run.err.find("m.kerf:1:13: error: cannot load mesh 'cut.stl': ") !=
              std::string::npos);
        CHECK(run.err.find("truncated") != std::string::npos);
    }
    SECTION("an open mesh cut by a box") {
        dir.write("m.kerf",
                  "object difference {\n    box { min <-1, -1, -1> max <1, 1, 1> }\n    mesh "
                  "\"open.obj\"\n};\n");
        const KerfRun run = runKerf(dir, {"check", "m.kerf"});
        INFO(run.err);
        CHECK(run.exitCode == 2);
        CHECK(run.err.find("m.kerf:3:5: error: mesh '") != std::string::npos);
        CHECK(run.err.find("open.obj' is not a solid: boundary edge from vertex 0 <0, 0, 0> to "
                           "vertex 1 <1, 0, 0>") != std::string::npos);
    }
}

TEST_CASE("kerf check: the mesh models report their knot, a closed tube of 192 × 24 quads") {
    TempDir dir;
    for (const char* model : {"mesh_knot.kerf", "mesh_csg.kerf"}) {
        const KerfRun run = runKerf(dir, {"check", (modelsDir() / model).string()});
        INFO(model << "\nstdout:\n" << run.out << "\nstderr:\n" << run.err);
        REQUIRE(run.exitCode == 0);
        // Both use the one file twice or more: one report.
        CHECK(run.out.find("  mesh '") == run.out.rfind("  mesh '"));
        CHECK(run.out.find("mesh_knot.ply':\n") != std::string::npos);
        // scripts/gen-mesh-models: 192 rings of 24 vertices, two triangles per grid quad; a
        // closed grid on a torus has every edge between two triangles.
        CHECK(has(run.out, "    vertices:             4608"));
        CHECK(has(run.out, "    triangles:            9216"));
        CHECK(has(run.out, "    boundary edges:       0"));
        CHECK(has(run.out, "    non-manifold edges:   0"));
        CHECK(has(run.out, "    inconsistent edges:   0 (two faces running an edge the same way)"));
        CHECK(has(run.out, "    degenerate triangles: 0"));
        CHECK(has(run.out, "    solid:                yes"));
    }
}
