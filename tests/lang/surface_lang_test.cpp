// The surfaces in the language (lang/lower_surfaces.cpp): what each keyword builds, the
// interior modifier's place under the material, and the errors where a solid is needed.
#include "lang_test_util.h"

#include "csg/primitives/surfaces.h"

using namespace kerf;
using namespace kerf::test;

namespace {

const char* kMaterials = "material red { color <1, 0, 0> }\nmaterial blue { color <0, 0, 1> }\n";

/// The kinds from the object down its first children.
std::string kinds(const NodePtr& n) {
    std::string out = nodeKindName(n->kind());
    if (!n->children().empty()) out += " " + kinds(n->children()[0]);
    return out;
}

Scene scene(const std::string& text) {
    const Compiled c = compileText(std::string(kMaterials) + text);
    INFO(c.sink.format());
    REQUIRE(c.scene.has_value());
    return *c.scene;
}

int32_t materialSeen(const NodePtr& object, const Ray& ray) {
    TraceContext ctx;
    Boundary b;
    bool entering = false;
    REQUIRE(object->firstSurface(ray, 0.0, kInf, ctx, b, entering));
    return b.material;
}

}  // namespace

TEST_CASE("surfaces: each keyword builds its surface node") {
    const Scene s = scene(
        "object disc { center <0, 1, 0> normal <0, 0, 1> radius 2 inner 0.5 };\n"
        "object triangle { a <0, 0, 0> b <1, 0, 0> c <0, 1, 0> };\n"
        "object cylinder { from <0, 0, 0> to <0, 1, 0> radius 1 open true };\n"
        "object cone { from <0, 0, 0> to <0, 1, 0> radius1 1 radius2 0.5 open true };\n"
        "object surface sphere { radius 1 };\n"
        "object clip disc { radius 1 } by box { min <-1, -1, -1> max <0, 1, 1> } translate <0, 2, "
        "0>;\n"
        "object cylinder { from <0, 0, 0> to <0, 1, 0> radius 1 open false };\n");
    REQUIRE(s.objects.size() == 7);
    CHECK(kinds(s.objects[0]) == "disc");
    const DiscParams d = std::get<DiscParams>(s.objects[0]->params());
    CHECK(d.center == Vec3(0, 1, 0));
    CHECK(d.radius == 2.0);
    CHECK(d.inner == 0.5);
    CHECK(kinds(s.objects[1]) == "triangle");
    CHECK(kinds(s.objects[2]) == "open cone");
    const OpenConeParams c = std::get<OpenConeParams>(s.objects[2]->params());
    CHECK(c.r1 == 1.0);
    CHECK(c.r2 == 1.0);
    CHECK(kinds(s.objects[3]) == "open cone");
    CHECK(kinds(s.objects[4]) == "surface sphere");
    // The modifiers after clip's solid move the whole clip.
    CHECK(kinds(s.objects[5]) == "transform clip disc");
    CHECK(s.objects[5]->children()[0]->children()[1]->kind() == NodeKind::Box);
    CHECK(kinds(s.objects[6]) == "cylinder");
    for (int i = 0; i < 6; ++i) CHECK(isSurfaceTree(*s.objects[i]));
    CHECK_FALSE(isSurfaceTree(*s.objects[6]));
}

TEST_CASE("surfaces: surfaces are values: lets, functions and loops make them") {
    const Scene s = scene(
        "let d = disc { radius 2 };\n"
        "fn sail(h) = triangle { a <0, 0, 0> b <1, 0, 0> c <0, h, 0> };\n"
        "object d;\nobject sail(3) material red;\n"
        "for i in 1 .. 2 { object disc { center <i, 0, 0> }; }\n");
    REQUIRE(s.objects.size() == 4);
    CHECK(std::get<DiscParams>(s.objects[0]->params()).radius == 2.0);
    CHECK(std::get<TriangleParams>(s.objects[1]->children()[0]->params()).c == Vec3(0, 3, 0));
    CHECK(std::get<DiscParams>(s.objects[3]->params()).center == Vec3(2, 0, 0));
}

TEST_CASE("surfaces: interior gives the back its material, before or after material") {
    for (const char* order : {"material red interior blue", "interior blue material red"}) {
        INFO(order);
        const Scene s = scene(std::string("object disc { radius 1 } ") + order + ";\n");
        const NodePtr& o = s.objects[0];
        CHECK(kinds(o) == "material interior disc");
        // The disc's front faces +y (the default normal); red from above, blue from below.
        CHECK(materialSeen(o, Ray{Vec3(0, 1, 0), Vec3(0, -1, 0)}) == 1);
        CHECK(materialSeen(o, Ray{Vec3(0, -1, 0), Vec3(0, 1, 0)}) == 2);
    }
    // A solid's interior: the boundary a ray leaves it by.
    const Scene ball = scene("object sphere { radius 1 } material red interior blue;\n");
    CHECK(materialSeen(ball.objects[0], Ray{Vec3(0, 0, -3), Vec3(0, 0, 1)}) == 1);
    CHECK(materialSeen(ball.objects[0], Ray{Vec3(0.0), Vec3(0, 0, 1)}) == 2);
}

TEST_CASE("surfaces: a surface where a solid is needed is an error at the surface") {
    requireOneError(
        "object difference {\n  box { min <-1, -1, -1> max <1, 1, 1> }\n  disc { radius 2 }\n};", 3,
        3,
        "this disc is a surface, not a solid: it has no inside and cannot be an operand of "
        "difference");
    requireOneError(
        "solid s = triangle { a <0, 0, 0> b <1, 0, 0> c <0, 1, 0> };\nobject union { s sphere { } "
        "};",
        1, 11, "is a surface, not a solid");
    requireOneError(
        "object intersection { sphere { } cylinder { from <0, 0, 0> to <0, 1, 0> open true } };", 1,
        34, "open cylinder or cone is a surface");
    requireOneError("object surface disc { radius 1 };", 1, 16,
                    "cannot be the operand of 'surface'");
    requireOneError("object clip disc { } by surface sphere { };", 1, 25,
                    "cannot be what 'clip' cuts by");
    requireOneError("object clip sphere { } by box { min <0, 0, 0> max <1, 1, 1> };", 1, 13,
                    "clip cuts a surface, but this is a solid");
    // A section plane cuts solids only; one that crosses a surface is refused as for open meshes.
    requireOneError(
        "section { point <0, 0, 0> normal <0, 0, 1> }\nobject disc { normal <0, 0, 1> };", 2, 8,
        "cannot be cut by the section plane");
    CHECK(compileText("section { point <0, 0, 5> normal <0, 0, 1> }\nobject disc { };")
              .scene.has_value());
    // The message names the use and says what to write instead.
    const Compiled c = compileText("object union {\n  disc { }\n  sphere { }\n};");
    REQUIRE(c.sink.errorCount() == 1);
    const Diagnostic& d = c.sink.diagnostics().front();
    CHECK_THAT(d.message, Catch::Matchers::Contains("(line 1, column 8)"));
    CHECK_THAT(d.hint, Catch::Matchers::Contains("clip SURFACE by SOLID"));
}

TEST_CASE("surfaces: bad surface values are errors at the value") {
    requireOneError("object disc { radius 0 };", 1, 22, "disc radius must be positive");
    requireOneError("object disc { radius 1 inner 1 };", 1, 30,
                    "disc inner radius must be at least 0 and less than");
    requireOneError("object disc { normal <0, 0, 0> };", 1, 22,
                    "disc normal must be a finite, non-zero vector");
    requireOneError("object triangle { a <0, 0, 0> b <1, 1, 1> c <2, 2, 2> };", 1, 8,
                    "triangle has no area");
    requireOneError("object clip disc { } box { };", 1, 22, "expected 'by SOLID'");
    requireOneError("object disc { } interior 3;", 1, 26,
                    "expected a material name after 'interior'");
}
