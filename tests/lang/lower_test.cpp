// Lowering: the Scene built from the issue's example, expression values, transform order,
// shared instances and implicit functions.
#include "lang/lower.h"
#include "lang/lexer.h"
#include "lang/parser.h"

#include "lang_test_util.h"

#include <cmath>

using namespace kerf;
using kerf::test::compileText;

namespace {

const char* const kExample = R"(
let R = 1.2;                                // numbers (1, 0.5, 2e-3), vectors <x, y, z>
let wall = R / 10;                          // + - * / ^, unary -, ( ); sin cos tan asin acos atan atan2 sqrt abs exp log pow min max floor ceil clamp mix; pi
solid body = difference {                   // union | intersection | difference (the first minus all the rest) | xor
    cylinder { from <0, 0, 0> to <0, 2.4, 0> radius R }
    cylinder { from <0, wall, 0> to <0, 2.5, 0> radius R - wall }
};
solid handle = difference {
    cylinder { from <0, 0, -0.1> to <0, 0, 0.1> radius 0.7 }
    cylinder { from <0, 0, -0.2> to <0, 0, 0.2> radius 0.5 }
    halfspace { normal <1, 0, 0> offset 0 }          // all points p with normal·p <= offset: here x <= 0
} translate <R - 0.05, 1.2, 0>;
solid cup = union { body handle };
solid gyroid = implicit {
    f sin(4*x)*cos(4*y) + sin(4*y)*cos(4*z) + sin(4*z)*cos(4*x)   // inside where f <= 0; x y z in object space
    bound box { min <-1, -1, -1> max <1, 1, 1> }
};
material clay  { color <0.8, 0.5, 0.3> ambient 0.1 diffuse 0.8 specular 0.3 shininess 20 }
material glass { color <0.95, 1, 0.97> transmit 0.9 ior 1.5 absorb <0.2, 0.05, 0.2> reflect 0.05 }
material mirror { color <0.9, 0.9, 0.9> reflect 0.85 specular 0.5 shininess 80 }
material lamp  { color <1, 0.9, 0.7> emit <4, 3.6, 2.8> }
object cup material clay rotate <0, 30, 0>;
object gyroid material glass scale 0.8 translate <3, 1, 0>;
object cup material mirror translate <-3, 0, 0>;            // a second instance of the same solid
object sphere { center <0, 4, 2> radius 0.3 } material lamp;
object halfspace { normal <0, 1, 0> offset 0 } material clay; // the floor
camera { eye <0, 3, -9> look_at <0, 1, 0> up <0, 1, 0> fov 35 }
light point { at <5, 8, -5> color <1, 1, 1> power 300 }     // inverse-square falloff
light directional { direction <-1, -2, 1> color <0.2, 0.2, 0.25> }
mist { color <0.85, 0.88, 0.95> distance 30 }               // colour blends to the mist colour by exp(-d / distance)
background <0.1, 0.1, 0.15>;
render { width 800 height 600 spp 4 max_depth 8 }
)";

void checkVec(const Vec3& v, const Vec3& expected, double tol = 0.0) {
    CHECK(v.x == Approx(expected.x).margin(tol));
    CHECK(v.y == Approx(expected.y).margin(tol));
    CHECK(v.z == Approx(expected.z).margin(tol));
}

/// The value of a number expression, read back through a light's position.
double numberOf(const std::string& expr) {
    const auto c = compileText("light point { at <" + expr + ", 0, 0> }");
    INFO(expr << "\n" << c.sink.format());
    REQUIRE(c.scene.has_value());
    return c.scene->lights.at(0).position.x;
}

Vec3 vectorOf(const std::string& expr) {
    const auto c = compileText("light point { at " + expr + " }");
    INFO(expr << "\n" << c.sink.format());
    REQUIRE(c.scene.has_value());
    return c.scene->lights.at(0).position;
}

Bounds3 boundsOf(const std::string& solid) {
    const auto c = compileText("object " + solid + ";");
    INFO(solid << "\n" << c.sink.format());
    REQUIRE(c.scene.has_value());
    REQUIRE(c.scene->objects.size() == 1);
    return c.scene->objects[0]->bounds();
}

}  // namespace

TEST_CASE("Lowering::lower: the issue's example") {
    const auto c = compileText(kExample, "example.kerf");
    INFO(c.sink.format());
    REQUIRE(c.sink.errorCount() == 0);
    REQUIRE(c.scene.has_value());
    const Scene& s = *c.scene;

    REQUIRE(s.objects.size() == 5);
    CHECK(s.objects[0]->primitiveCount() ==
          5);  // body: 2 cylinders, handle: 2 cylinders + halfspace
    CHECK(s.objects[1]->primitiveCount() == 1);
    CHECK(s.objects[2]->primitiveCount() == 5);
    CHECK(s.objects[3]->primitiveCount() == 1);

    REQUIRE(s.materials.size() == 5);
    CHECK(s.materials[0].name == "default");
    const Material& clay = s.materials[1];
    CHECK(clay.name == "clay");
    checkVec(clay.color, {0.8, 0.5, 0.3});
    CHECK(clay.ambient == 0.1);
    CHECK(clay.diffuse == 0.8);
    CHECK(clay.specular == 0.3);
    CHECK(clay.shininess == 20);
    CHECK(clay.reflect == 0.0);  // unspecified: the default
    const Material& glass = s.materials[2];
    CHECK(glass.transmit == 0.9);
    CHECK(glass.ior == 1.5);
    checkVec(glass.absorb, {0.2, 0.05, 0.2});
    CHECK(glass.reflect == 0.05);
    CHECK(glass.ambient == Material{}.ambient);
    CHECK(s.materials[3].reflect == 0.85);
    CHECK(s.materials[3].shininess == 80);
    checkVec(s.materials[4].emit, {4, 3.6, 2.8});

    checkVec(s.camera.eye, {0, 3, -9});
    checkVec(s.camera.lookAt, {0, 1, 0});
    checkVec(s.camera.up, {0, 1, 0});
    CHECK(s.camera.fovDegrees == 35);

    REQUIRE(s.lights.size() == 2);
    CHECK(s.lights[0].kind == Light::Kind::Point);
    checkVec(s.lights[0].position, {5, 8, -5});
    CHECK(s.lights[0].power == 300);
    CHECK(s.lights[1].kind == Light::Kind::Directional);
    checkVec(s.lights[1].direction, {-1, -2, 1});
    checkVec(s.lights[1].color, {0.2, 0.2, 0.25});

    CHECK(s.mist.enabled);
    checkVec(s.mist.color, {0.85, 0.88, 0.95});
    CHECK(s.mist.distance == 30);
    checkVec(s.background, {0.1, 0.1, 0.15});
    CHECK(s.settings.width == 800);
    CHECK(s.settings.height == 600);
    CHECK(s.settings.spp == 4);
    CHECK(s.settings.maxDepth == 8);

    SECTION("the lamp sphere and the gyroid bounds") {
        const Bounds3 lamp = s.objects[3]->bounds();
        checkVec(lamp.lo, {-0.3, 3.7, 1.7}, 1e-12);
        checkVec(lamp.hi, {0.3, 4.3, 2.3}, 1e-12);
        // gyroid bound [-1, 1]^3, scaled by 0.8 then moved to <3, 1, 0>
        const Bounds3 gyroid = s.objects[1]->bounds();
        CHECK(gyroid.lo.x >= 2.2 - 1e-12);
        CHECK(gyroid.hi.x <= 3.8 + 1e-12);
        CHECK(gyroid.lo.y >= 0.2 - 1e-12);
        CHECK(gyroid.hi.y <= 1.8 + 1e-12);
    }

    SECTION("the two cups share one subtree: the same primitives answer both rays") {
        // Straight down the cup's axis: inside the body between the floor of the inner cylinder
        // (y = wall = 0.12) and the bottom (y = 0).
        TraceContext ctx;
        SpanList first, second;
        s.objects[0]->spans(Ray{{0, 10, 0}, {0, -1, 0}}, 0, kInf, ctx, first);
        s.objects[2]->spans(Ray{{-3, 10, 0}, {0, -1, 0}}, 0, kInf, ctx, second);
        REQUIRE(first.size() == 1);
        REQUIRE(second.size() == 1);
        CHECK(first[0].in.t == Approx(9.88).epsilon(1e-12));
        CHECK(first[0].out.t == Approx(10.0).epsilon(1e-12));
        CHECK(first[0].in.primitive == second[0].in.primitive);
        CHECK(first[0].out.primitive == second[0].out.primitive);
        CHECK(first[0].in.primitive != first[0].out.primitive);
        CHECK(first[0].in.material == 1);   // clay
        CHECK(second[0].in.material == 3);  // mirror
    }
}

TEST_CASE("Lowering::solidNamed: one lowered tree per definition") {
    DiagnosticSink sink;
    const SourceText src{std::make_shared<const std::string>("s.kerf"),
                         std::make_shared<const std::string>(
                             "object a translate <1, 0, 0>;\nobject a;\nsolid a = union { sphere "
                             "{} box { min <0,0,0> max <2,2,2> } };")};
    Program program = parse(tokenize(src, sink), sink);
    Lowering lowering(sink);
    const auto scene = lowering.lower(program);
    REQUIRE(scene.has_value());
    const NodePtr a = lowering.solidNamed("a");
    REQUIRE(a);
    CHECK(scene->objects[1] == a);  // used before its definition, and not copied
    CHECK(a->primitiveCount() == 2);
    checkVec(scene->objects[0]->bounds().lo, {0, -1, -1}, 1e-12);
    CHECK(lowering.solidNamed("b") == nullptr);
}

TEST_CASE("Lowering::lower: the syntax tree of each solid and object is freed once lowered") {
    DiagnosticSink sink;
    const SourceText src{
        std::make_shared<const std::string>("f.kerf"),
        std::make_shared<const std::string>("let r = 2;\nobject a translate <1, 0, 0>;\nsolid a = "
                                            "union { b sphere { radius r } };\n"
                                            "solid b = box { min <0,0,0> max <1,1,1> };\nmaterial "
                                            "m { color <1, 0, 0> }\nobject b material m;")};
    Program program = parse(tokenize(src, sink), sink);
    REQUIRE(program.statements.size() == 6);
    for (const Statement& s : program.statements) CHECK(s.tree != nullptr);
    Lowering lowering(sink);
    const auto scene = lowering.lower(program);
    INFO(sink.format());
    REQUIRE(scene.has_value());
    // The compiled scene is whole: a = b ∪ sphere of radius 2, moved by 1 along x.
    REQUIRE(scene->objects.size() == 2);
    checkVec(scene->objects[0]->bounds().lo, {-1, -2, -2}, 1e-12);
    checkVec(scene->objects[0]->bounds().hi, {3, 2, 2}, 1e-12);
    // Solids and objects hold no tree any more; the let and the material keep theirs.
    for (const Statement& s : program.statements) {
        const bool freed = s.kind == Statement::Kind::SolidDef || s.kind == Statement::Kind::Object;
        INFO("statement at offset " << s.loc.offset);
        CHECK((s.tree == nullptr) == freed);
        if (freed) CHECK(s.solid == nullptr);
    }
}

TEST_CASE("Lowering: expressions fold to the right values") {
    CHECK(numberOf("-2^2") == -4);
    CHECK(numberOf("2^3^2") == 512);
    CHECK(numberOf("2^-1") == 0.5);
    CHECK(numberOf("1 - 2 - 3") == -4);
    CHECK(numberOf("12 / 3 / 2") == 2);
    CHECK(numberOf(".5 + 2e-3") == 0.502);
    CHECK(numberOf("pi") == M_PI);
    CHECK(numberOf("atan2(1, 1)") == std::atan2(1.0, 1.0));
    CHECK(numberOf("pow(2, 10)") == 1024);
    CHECK(numberOf("clamp(5, 0, 1)") == 1);
    CHECK(numberOf("clamp(-5, 0, 1)") == 0);
    CHECK(numberOf("mix(1, 3, 0.25)") == 1.5);
    CHECK(numberOf("min(3, 2) + max(3, 2)") == 5);
    CHECK(numberOf("floor(-1.5) + ceil(1.2) + abs(-3)") == 3);
    CHECK(numberOf("sqrt(16) + exp(0) + log(1)") == 5);
    CHECK(numberOf("sin(1) + cos(1) + tan(1)") == std::sin(1.0) + std::cos(1.0) + std::tan(1.0));
    CHECK(numberOf("asin(0.5) + acos(0.5) + atan(2)") ==
          std::asin(0.5) + std::acos(0.5) + std::atan(2.0));

    checkVec(vectorOf("<1, 2, 3> * 2 - <1, 1, 1>"), {1, 3, 5});
    checkVec(vectorOf("2 * <1, 2, 3> / 4"), {0.5, 1, 1.5});
    checkVec(vectorOf("-<1, -2, 3>"), {-1, 2, -3});
    checkVec(vectorOf("mix(<0, 0, 0>, <2, 4, 8>, 0.5)"), {1, 2, 4});

    SECTION("lets may be used before their definition") {
        const auto c = compileText("light point { at <a, b, 0> }\nlet a = b * 2;\nlet b = 1.5;");
        REQUIRE(c.scene.has_value());
        checkVec(c.scene->lights[0].position, {3, 1.5, 0});
    }
}

TEST_CASE("Lowering: modifiers apply left to right") {
    SECTION("translate then scale: the centre moves too") {
        const Bounds3 b = boundsOf("sphere {} translate <1, 0, 0> scale 2");
        checkVec(b.center(), {2, 0, 0}, 1e-12);
        checkVec(b.extent(), {4, 4, 4}, 1e-12);
    }
    SECTION("scale then translate") {
        const Bounds3 b = boundsOf("sphere {} scale 2 translate <1, 0, 0>");
        checkVec(b.center(), {1, 0, 0}, 1e-12);
    }
    SECTION("rotate in degrees about z") {
        const Bounds3 b = boundsOf("box { min <0, 0, 0> max <1, 1, 1> } rotate <0, 0, 90>");
        checkVec(b.lo, {-1, 0, 0}, 1e-12);
        checkVec(b.hi, {0, 1, 1}, 1e-12);
    }
    SECTION("rotate x then y") {
        // <0, 0, 1> rotated 90° about x goes to <0, -1, 0>; about y that stays put.
        const Bounds3 b = boundsOf("sphere { center <0, 0, 5> radius 1 } rotate <90, 90, 0>");
        checkVec(b.center(), {0, -5, 0}, 1e-12);
    }
    SECTION("matrix, row-major 3×4, with a scale vector") {
        const Bounds3 b = boundsOf("sphere {} matrix [2 0 0 1  0 1 0 0  0 0 1 -1] scale <1, 3, 1>");
        checkVec(b.lo, {-1, -3, -2}, 1e-12);
        checkVec(b.hi, {3, 3, 0}, 1e-12);
    }
    SECTION("a one-child Boolean is the child") {
        const Bounds3 b = boundsOf("union { box { min <0, 0, 0> max <1, 2, 3> } }");
        checkVec(b.hi, {1, 2, 3});
    }
}

TEST_CASE("Lowering: materials") {
    SECTION("innermost material wins, names may come later") {
        const auto c = compileText(
            "object sphere {} material red material blue;\nmaterial blue { color <0, 0, 1> }\n"
            "material red { color <1, 0, 0> }");
        REQUIRE(c.scene.has_value());
        TraceContext ctx;
        SpanList spans;
        c.scene->objects[0]->spans(Ray{{0, 0, -5}, {0, 0, 1}}, 0, kInf, ctx, spans);
        REQUIRE(spans.size() == 1);
        CHECK(spans[0].in.material == 2);  // red is the second material block
        CHECK(c.scene->materials[2].name == "red");
    }
    SECTION("an outer material colours only the parts without one") {
        const auto c = compileText(
            "material red { color <1, 0, 0> }\nmaterial blue { color <0, 0, 1> }\n"
            "solid a = union { sphere {} material red  box { min <3, -1, -1> max <5, 1, 1> } };\n"
            "object a material blue;");
        INFO(c.sink.format());
        REQUIRE(c.scene.has_value());
        TraceContext ctx;
        SpanList sphere, box;
        c.scene->objects[0]->spans(Ray{{0, 0, -5}, {0, 0, 1}}, 0, kInf, ctx, sphere);
        c.scene->objects[0]->spans(Ray{{4, 0, -5}, {0, 0, 1}}, 0, kInf, ctx, box);
        REQUIRE(sphere.size() == 1);
        REQUIRE(box.size() == 1);
        CHECK(sphere[0].in.material == 1);
        CHECK(box[0].in.material == 2);
    }
    SECTION("an object without material keeps none (the renderer gives it material 0)") {
        const auto c = compileText("object sphere {};");
        REQUIRE(c.scene.has_value());
        TraceContext ctx;
        SpanList spans;
        c.scene->objects[0]->spans(Ray{{0, 0, -5}, {0, 0, 1}}, 0, kInf, ctx, spans);
        REQUIRE(spans.size() == 1);
        CHECK(spans[0].in.material == Boundary::kNoMaterial);
        CHECK(c.scene->materials.size() == 1);
    }
}

TEST_CASE("Lowering: implicit functions") {
    const auto c = compileText(
        "let k = 2;\nobject implicit { f x^2 + y^2 + z^2 - k^2 + 0*sin(x) bound box { min <-10, "
        "-10, -10> max <10, 10, 10> } };");
    INFO(c.sink.format());
    REQUIRE(c.scene.has_value());
    const NodePtr& node = c.scene->objects[0];
    CHECK(node->value({1, 0, 0}) == Approx(-3).epsilon(1e-12));
    CHECK(node->value({0, 1, 1}) == Approx(-2).epsilon(1e-12));
    CHECK(node->value({0, 0, 2.5}) == Approx(2.25).epsilon(1e-12));
    TraceContext ctx;
    SpanList spans;
    node->spans(Ray{{-20, 0, 0}, {1, 0, 0}}, 0, kInf, ctx, spans);
    REQUIRE(spans.size() == 1);
    CHECK(spans[0].in.t == Approx(18).epsilon(1e-6));
    CHECK(spans[0].out.t == Approx(22).epsilon(1e-6));
}
