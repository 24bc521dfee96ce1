// `mesh "file"` in the language: lowering with modifiers (bounds against the transformed box),
// paths relative to the model file, one shared shape per file, and each mistake as one error
// at its own line and column.
#include "lang_test_util.h"
#include "mesh/mesh_files.h"
#include "mesh/mesh_shape.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

using namespace kerf;
using namespace kerf::test;
namespace fs = std::filesystem;

namespace {

/// The unit cube [0, 1]³ as OBJ, faces counter-clockwise from outside; `open` leaves out the
/// two triangles of the top face (z = 1), which leaves four boundary edges.
std::string cubeObj(bool open = false) {
    std::ostringstream s;
    for (int i = 0; i < 8; ++i)
        s << "v " << (i & 1) << ' ' << ((i >> 1) & 1) << ' ' << ((i >> 2) & 1) << '\n';
    // Vertex i + 1 (OBJ counts from 1) is at (i&1, i>>1&1, i>>2&1).
    const int faces[12][3] = {{1, 3, 4}, {1, 4, 2},   // z = 0, normal −z
                              {5, 6, 8}, {5, 8, 7},   // z = 1, normal +z
                              {1, 2, 6}, {1, 6, 5},   // y = 0
                              {3, 7, 8}, {3, 8, 4},   // y = 1
                              {1, 5, 7}, {1, 7, 3},   // x = 0
                              {2, 4, 8}, {2, 8, 6}};  // x = 1
    for (int f = 0; f < 12; ++f) {
        if (open && (f == 2 || f == 3)) continue;
        s << "f " << faces[f][0] << ' ' << faces[f][1] << ' ' << faces[f][2] << '\n';
    }
    return s.str();
}

/// A folder with models/parts/{cube,open,octa}.obj and a cut STL, removed at the end.
struct MeshFolder {
    fs::path root;
    MeshFolder() {
        std::string pattern = (fs::temp_directory_path() / "kerf-mesh-lang-XXXXXX").string();
        REQUIRE(mkdtemp(pattern.data()) != nullptr);
        root = pattern;
        fs::create_directories(root / "models" / "parts");
        write("parts/cube.obj", cubeObj());
        write("parts/open.obj", cubeObj(true));
        write("parts/octa.obj", objText());
        const std::string stl = stlBinaryText();
        write("parts/cut.stl", stl.substr(0, stl.size() - 30));
    }
    ~MeshFolder() { fs::remove_all(root); }
    void write(const std::string& name, const std::string& bytes) const {
        std::ofstream(root / "models" / name, std::ios::binary) << bytes;
    }
    std::string model() const { return (root / "models" / "scene.kerf").string(); }
};

const MeshShape* shapeBelow(const NodePtr& node) {
    const Node* n = node.get();
    while (n->kind() != NodeKind::Mesh) {
        REQUIRE(n->children().size() == 1);
        n = n->children()[0].get();
    }
    return std::get<MeshParams>(n->params()).shape.get();
}

void requireBounds(const Bounds3& b, const Vec3& lo, const Vec3& hi) {
    // Transforms round outward by a few ulps at most (csg/tree/transform.cpp).
    for (int i = 0; i < 3; ++i) {
        CHECK(b.lo[i] == Approx(lo[i]).margin(1e-12));
        CHECK(b.hi[i] == Approx(hi[i]).margin(1e-12));
        CHECK(b.lo[i] <= lo[i]);
        CHECK(b.hi[i] >= hi[i]);
    }
}

}  // namespace

TEST_CASE("mesh: lowered with modifiers, the bounds are the moved cube's") {
    MeshFolder folder;
    const Compiled c = compileText(R"(material red { color <1, 0, 0> }
object mesh "parts/cube.obj" translate <1, 2, 3>;
object mesh "parts/cube.obj" smooth false scale <2, 1, 1> rotate <0, 0, 90> material red;
let m = mesh ("parts/" + "cube.obj");
object m translate <-5, 0, 0>;
let name = "parts/cube.obj";
object mesh name smooth false;
)",
                                   folder.model());
    INFO(c.sink.format());
    REQUIRE(c.scene);
    REQUIRE(c.scene->objects.size() == 4);
    const NodePtr& moved = c.scene->objects[0];
    CHECK(moved->kind() == NodeKind::Transform);
    requireBounds(moved->bounds(), Vec3(1, 2, 3), Vec3(2, 3, 4));
    // scale x by 2, then a quarter turn about z: (x, y) -> (-y, x); [0,2]×[0,1] -> [-1,0]×[0,2].
    const NodePtr& turned = c.scene->objects[1];
    REQUIRE(turned->kind() == NodeKind::Material);
    requireBounds(turned->bounds(), Vec3(-1, 0, 0), Vec3(0, 2, 1));
    requireBounds(c.scene->objects[2]->bounds(), Vec3(-5, 0, 0), Vec3(-4, 1, 1));

    const auto leaf = [](const NodePtr& node) {
        const Node* n = node.get();
        while (n->kind() != NodeKind::Mesh) n = n->children()[0].get();
        return std::get<MeshParams>(n->params());
    };
    CHECK(leaf(moved).smooth);
    CHECK_FALSE(leaf(turned).smooth);
    CHECK_FALSE(leaf(c.scene->objects[3]).smooth);
    CHECK(leaf(c.scene->objects[3]).shape == leaf(moved).shape);
    const MeshShape& shape = *leaf(moved).shape;
    CHECK(shape.isSolid());
    CHECK(shape.mesh().triangles.size() == 12);
    CHECK(shape.source() == (folder.root / "models" / "parts" / "cube.obj").string());
}

TEST_CASE("mesh: each file is loaded once and shared by every use, however it is spelt") {
    MeshFolder folder;
    const std::string absolute = (folder.root / "models" / "parts" / "cube.obj").string();
    const Compiled c = compileText(
        "object mesh \"parts/cube.obj\";\n"
        "object mesh \"parts/../parts/cube.obj\" translate <3, 0, 0>;\n"
        "object mesh \"" +
            absolute +
            "\" smooth false rotate <0, 90, 0>;\n"
            "object mesh \"parts/octa.obj\";\n"
            "object union { mesh \"parts/cube.obj\" sphere { radius 0.1 } };\n",
        folder.model());
    INFO(c.sink.format());
    REQUIRE(c.scene);
    REQUIRE(c.scene->objects.size() == 5);
    const MeshShape* cube = shapeBelow(c.scene->objects[0]);
    CHECK(shapeBelow(c.scene->objects[1]) == cube);
    CHECK(shapeBelow(c.scene->objects[2]) == cube);
    const MeshShape* octa = shapeBelow(c.scene->objects[3]);
    CHECK(octa != cube);
    CHECK(octa->mesh().triangles.size() == 8);
    CHECK(std::get<MeshParams>(c.scene->objects[4]->children()[0]->params()).shape.get() == cube);
}

TEST_CASE("mesh: paths are relative to the model file that names them, not the working folder") {
    MeshFolder folder;
    fs::create_directories(folder.root / "models" / "sub");
    std::ofstream(folder.root / "models" / "sub" / "part.kerf")
        << "solid part = mesh \"../parts/octa.obj\";\n";
    const Compiled c = compileText("include \"sub/part.kerf\";\nobject part;\n", folder.model());
    INFO(c.sink.format());
    REQUIRE(c.scene);
    CHECK(shapeBelow(c.scene->objects[0])->source() ==
          (folder.root / "models" / "parts" / "octa.obj").string());
}

TEST_CASE("mesh: an open mesh renders alone, and is refused where a solid is needed") {
    MeshFolder folder;
    SECTION("alone, under transforms and materials: fine") {
        const Compiled c = compileText(
            "material m { color <1, 1, 1> }\n"
            "object mesh \"parts/open.obj\" translate <1, 0, 0> material m spin <0, 10, 0>;\n",
            folder.model());
        INFO(c.sink.format());
        REQUIRE(c.scene);
        CHECK_FALSE(shapeBelow(c.scene->objects[0])->isSolid());
    }
    const auto requireOpenError = [&](const std::string& text, int line, int col,
                                      const std::string& use) {
        const Compiled c = compileText(text, folder.model());
        INFO(c.sink.format());
        REQUIRE_FALSE(c.scene);
        REQUIRE(c.sink.errorCount() == 1);
        const Diagnostic& d = c.sink.diagnostics().front();
        // The first triangle of the cube with an open top that has a boundary edge: (1, 2, 6)
        // of the y = 0 face, whose edge from vertex 6 (1, 0, 1) to 5 (0, 0, 1) has no twin.
        CHECK_THAT(d.message, Catch::Matchers::Contains(
                                  "open.obj' is not a solid: boundary edge from vertex"));
        CHECK(d.loc.line == line);
        CHECK(d.loc.col == col);
        CHECK_THAT(d.hint, Catch::Matchers::Contains(use));
        CHECK_THAT(d.hint, Catch::Matchers::Contains("renders as a surface"));
    };
    SECTION("difference") {
        requireOpenError(
            "object difference {\n  box { min <0, 0, 0> max <2, 2, 2> }\n  mesh \"parts/open.obj\" "
            "translate <0.5, 0.5, 0.5>\n};\n",
            3, 3, "an operand of difference at line 1, column 8");
    }
    SECTION("a named solid under intersection") {
        requireOpenError(
            "solid lid = mesh \"parts/open.obj\" material none;\n"
            "material none { color <1, 1, 1> }\n"
            "object intersection { sphere { radius 2 } lid };\n",
            1, 13, "an operand of intersection");
    }
    SECTION("union and xor") {
        requireOpenError("object union { mesh \"parts/open.obj\" sphere { radius 2 } };\n", 1, 16,
                         "an operand of union");
        requireOpenError("object xor { sphere { radius 2 }\n mesh \"parts/open.obj\" };\n", 2, 2,
                         "an operand of xor");
    }
    SECTION("a loop's union") {
        requireOpenError(
            "object union { for i in [0, 1] { mesh \"parts/open.obj\" translate <i * 2, 0, 0> } "
            "};\n",
            1, 34, "an operand of union");
    }
    SECTION("displaced") {
        requireOpenError("object mesh \"parts/open.obj\" displace noise { } by 0.1;\n", 1, 8,
                         "displaced");
    }
    SECTION("cut by a section plane") {
        requireOpenError(
            "object mesh \"parts/open.obj\";\nsection { point <0, 0, 0.5> normal <0, 0, 1> }\n", 1,
            8, "cut by the section plane at line 2, column 1");
    }
    SECTION("a section plane that misses it: fine") {
        const Compiled c = compileText(
            "object mesh \"parts/open.obj\";\nsection { point <0, 0, 5> normal <0, 0, 1> }\n",
            folder.model());
        INFO(c.sink.format());
        CHECK(c.scene);
    }
    SECTION("a closed mesh is an operand like any solid") {
        const Compiled c =
            compileText("object difference { mesh \"parts/cube.obj\" sphere { radius 0.5 } };\n",
                        folder.model());
        INFO(c.sink.format());
        REQUIRE(c.scene);
        CHECK(c.scene->objects[0]->kind() == NodeKind::Difference);
    }
}

TEST_CASE("mesh: bad files and bad values are one error each at the file name") {
    MeshFolder folder;
    const auto requireError = [&](const std::string& text, int line, int col,
                                  const std::string& message) {
        const Compiled c = compileText(text, folder.model());
        INFO(c.sink.format());
        REQUIRE_FALSE(c.scene);
        REQUIRE(c.sink.errorCount() == 1);
        const Diagnostic& d = c.sink.diagnostics().front();
        CHECK_THAT(d.message, Catch::Matchers::Contains(message));
        CHECK(d.loc.line == line);
        CHECK(d.loc.col == col);
        return d;
    };
    SECTION("missing, with where it was looked for") {
        const Diagnostic d =
            requireError("object sphere { radius 1 };\nobject mesh \"parts/none.stl\";\n", 2, 13,
                         "cannot load mesh 'parts/none.stl': no such file");
        CHECK_THAT(d.hint, Catch::Matchers::Contains(
                               (folder.root / "models" / "parts" / "none.stl").string()));
    }
    SECTION("truncated binary STL") {
        requireError("object mesh \"parts/cut.stl\" translate <1, 0, 0>;\n", 1, 13,
                     "cannot load mesh 'parts/cut.stl': ");
        const Compiled c = compileText("object mesh \"parts/cut.stl\";\n", folder.model());
        CHECK_THAT(c.sink.diagnostics().front().message, Catch::Matchers::Contains("truncated"));
    }
    SECTION("a non-finite coordinate") {
        std::string ply = plyHeader("binary_little_endian", 3, 1);
        for (float x : {0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f,
                        std::numeric_limits<float>::quiet_NaN(), 0.0f})
            appendBytes(ply, x);
        appendBytes(ply, uint8_t(3));
        for (int32_t i : {0, 1, 2}) appendBytes(ply, i);
        folder.write("parts/nan.ply", ply);
        requireError("object mesh \"parts/nan.ply\";\n", 1, 13,
                     "cannot load mesh 'parts/nan.ply': vertex 2 has a non-finite coordinate");
    }
    SECTION("no triangles") {
        folder.write("parts/points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
        // Assimp's own validation refuses it before the loader counts triangles.
        requireError("object mesh \"parts/points.obj\";\n", 1, 13,
                     "cannot load mesh 'parts/points.obj': not a readable mesh");
    }
    SECTION("not a mesh") {
        folder.write("parts/notes.txt", "these are not the triangles you are looking for\n");
        requireError("object mesh \"parts/notes.txt\";\n", 1, 13,
                     "cannot load mesh 'parts/notes.txt': not a readable mesh");
    }
    SECTION("a bad file used twice is reported once") {
        const Compiled c = compileText(
            "object mesh \"parts/none.stl\";\nobject mesh \"parts/none.stl\";\n", folder.model());
        CHECK(c.sink.errorCount() == 1);
    }
    SECTION("not a string") {
        requireError("object mesh (1 + 2);\n", 1, 13,
                     "mesh expects a file name in quotes, got a number");
    }
    SECTION("smooth must be a boolean") {
        requireError("object mesh \"parts/cube.obj\" smooth <1, 0, 0>;\n", 1, 37, "smooth");
    }
    SECTION("smooth after the modifiers") {
        const Compiled c = compileText(
            "object mesh \"parts/cube.obj\" translate <1, 0, 0> smooth false;\n", folder.model());
        REQUIRE(c.sink.errorCount() == 1);
        const Diagnostic& d = c.sink.diagnostics().front();
        CHECK(d.message == "'smooth' after the modifiers of a mesh");
        CHECK(d.loc.col == 50);
    }
    SECTION("POV-Ray's mesh block") {
        const Compiled c = compileText("object mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } };\n",
                                       folder.model());
        REQUIRE_FALSE(c.scene);
        CHECK_THAT(c.sink.format(), Catch::Matchers::Contains("mesh \"file.stl\""));
    }
}
