// The language for issue 10's render settings: area and sphere lights, light falloff and
// shadows, the thin-lens camera, glossy and translucent materials, the sampler, a gradient
// sky and no_shadow objects, each lowered to the scene's values or refused with a message.
#include "lang_test_util.h"

using namespace kerf;
using namespace kerf::test;

TEST_CASE("area and sphere lights, falloff, fade_distance and shadows") {
    const Compiled c = compileText(R"(
light area { corner <-1, 6, -3> edge1 <2, 0, 0> edge2 <0, 0, 2> power 900 falloff linear }
light sphere { at <4, 5, -4> radius 0.5 power 300 shadows false fade_distance 3 }
light point { at <0, 9, 0> falloff none }
light directional { direction <0, -1, 0> shadows false }
)");
    INFO(c.sink.format());
    REQUIRE(c.scene.has_value());
    const std::vector<Light>& l = c.scene->lights;
    REQUIRE(l.size() == 4);
    CHECK(l[0].kind == Light::Kind::Area);
    CHECK(l[0].position == Vec3(-1.0, 6.0, -3.0));
    CHECK(l[0].edgeU == Vec3(2.0, 0.0, 0.0));
    CHECK(l[0].edgeV == Vec3(0.0, 0.0, 2.0));
    CHECK(l[0].power == 900.0);
    CHECK(l[0].falloff == Falloff::Linear);
    CHECK(l[0].shadows);
    CHECK(l[1].kind == Light::Kind::Sphere);
    CHECK(l[1].radius == 0.5);
    CHECK_FALSE(l[1].shadows);
    CHECK(l[1].fadeDistance == 3.0);
    CHECK(l[1].falloff == Falloff::InverseSquare);
    CHECK(l[2].falloff == Falloff::None);
    CHECK_FALSE(l[3].shadows);
}

TEST_CASE("camera lens, materials' cones, the sampler, a gradient sky, no_shadow") {
    const Compiled c = compileText(R"(
material m { glossy 8 translucent 12.5 }
camera { eye <0, 2, -7> look_at <0, 1, 0> aperture 0.3 focus_distance 6.5 }
render { spp 5 sampler lattice }
background gradient { horizon <0.8, 0.8, 0.9> zenith <0.2, 0.3, 0.7> up <0, 2, 0> }
object sphere { radius 1 } material m;
object sphere { radius 1 } no_shadow;
object sphere { radius 2 };
)");
    INFO(c.sink.format());
    REQUIRE(c.scene.has_value());
    const Scene& s = *c.scene;
    CHECK(s.materials[1].glossy == 8.0);
    CHECK(s.materials[1].translucent == 12.5);
    CHECK(s.camera.aperture == 0.3);
    CHECK(s.camera.focusDistance == 6.5);
    CHECK(s.settings.spp == 5);
    CHECK(s.settings.sampler == SamplerKind::Lattice);
    CHECK(s.sky.gradient);
    CHECK(s.sky.horizon == Vec3(0.8, 0.8, 0.9));
    CHECK(s.sky.nadir == s.sky.horizon);     // the horizon's colour below it, unless given
    CHECK(s.sky.up == Vec3(0.0, 1.0, 0.0));  // normalised
    REQUIRE(s.objectFlags.size() == 3);
    CHECK(s.objectFlags[0].castsShadow);
    CHECK_FALSE(s.objectFlags[1].castsShadow);
    CHECK(s.objectFlags[2].castsShadow);
}

TEST_CASE("issue 10's properties refuse bad values with the line and column") {
    requireOneError("light area { corner <0, 5, 0> edge1 <1, 0, 0> edge2 <2, 0, 0> }\n", 1, 53,
                    "area light edges <1, 0, 0> and <2, 0, 0> span no area");
    requireOneError("light sphere { at <0, 5, 0> radius 0 }\n", 1, 36,
                    "sphere light radius must be positive, got 0");
    requireOneError("light point { at <0, 5, 0> falloff quadratic }\n", 1, 36,
                    "unknown falloff 'quadratic' in point light");
    requireOneError("light point { at <0, 5, 0> falloff 2 }\n", 1, 36,
                    "property 'falloff' of point light expects one of inverse_square, linear");
    requireOneError("light point { at <0, 5, 0> fade_distance -1 }\n", 1, 42,
                    "light fade_distance must be positive, got -1");
    requireOneError("light point { at <0, 5, 0> shadows 1 }\n", 1, 36,
                    "property 'shadows' of point light expects true or false, got a number");
    requireOneError("render { sampler sobol }\n", 1, 18, "unknown sampler 'sobol' in render");
    requireOneError("material m { glossy 100 }\n", 1, 21,
                    "material glossy must be an angle from 0 to 90 degrees, got 100");
    requireOneError("camera { aperture -0.1 }\n", 1, 19, "camera aperture must not be negative");
    requireOneError("camera { focus_distance 0 }\n", 1, 25,
                    "camera focus_distance must be positive");
    requireOneError("background gradient { horizon <1, 1, 1> }\n", 1, 1,
                    "background gradient needs the property 'zenith'");
    requireOneError("light spot { at <0, 1, 0> }\n", 1, 7, "unknown light kind 'spot'");
}

TEST_CASE("patterns: kinds, entries, nesting, seeds and the pattern's transforms") {
    const Compiled c = compileText(R"(
let dark = <0.1, 0.1, 0.1>;
material floor { pattern checker { a <0.9, 0.9, 0.9> b dark } scale 0.5 diffuse 0.8 }
material wood { pattern rings { a <0.6, 0.4, 0.2> b pattern noise { a <0.4, 0.2, 0.1> seed 4 } scale 0.05 } rotate <90, 0, 0> }
material marble { pattern turbulence { octaves 3 } }
)");
    INFO(c.sink.format());
    REQUIRE(c.scene.has_value());
    const Material& floor = c.scene->materials[1];
    REQUIRE(floor.pattern);
    CHECK(floor.pattern->kind == Pattern::Kind::Checker);
    CHECK(floor.pattern->a.color == Vec3(0.9, 0.9, 0.9));
    CHECK(floor.pattern->b.color == Vec3(0.1, 0.1, 0.1));
    // scale 0.5: world → pattern space doubles.
    CHECK(floor.pattern->toPattern.point(Vec3(1.0, 2.0, 3.0)) == Vec3(2.0, 4.0, 6.0));
    CHECK(floor.diffuse == 0.8);
    const Material& wood = c.scene->materials[2];
    REQUIRE(wood.pattern);
    CHECK(wood.pattern->kind == Pattern::Kind::Rings);
    REQUIRE(wood.pattern->b.pattern);
    CHECK(wood.pattern->b.pattern->kind == Pattern::Kind::Noise);
    CHECK(wood.pattern->b.pattern->seed == 4);
    CHECK(wood.pattern->b.pattern->b.color == Vec3(1.0));  // b defaults to white
    CHECK(wood.pattern->b.pattern->toPattern.point(Vec3(0.05)) == Vec3(1.0));
    const Material& marble = c.scene->materials[3];
    REQUIRE(marble.pattern);
    CHECK(marble.pattern->octaves == 3);
    CHECK(marble.pattern->a.color == Vec3(0.0));
}

TEST_CASE("patterns refuse unknown kinds and bad values with the line and column") {
    requireOneError("material m { pattern chequer { } }\n", 1, 22, "unknown pattern 'chequer'");
    requireOneError("material m { pattern checker { a <-1, 0, 0> } }\n", 1, 34,
                    "pattern colour a must not have negative components");
    requireOneError("material m { pattern turbulence { octaves 40 } }\n", 1, 43,
                    "turbulence pattern octaves must be an integer from 1 to 16, got 40");
    requireOneError("material m { pattern checker { octaves 2 } }\n", 1, 32,
                    "unknown property 'octaves' in checker pattern");
    requireOneError("material m { pattern checker { } scale 0 }\n", 1, 40,
                    "scale by zero flattens");
    requireOneError("material m { pattern 3 }\n", 1, 22,
                    "property 'pattern' of material expects a pattern");
}

TEST_CASE("bump maps: a pattern and a depth") {
    const Compiled c = compileText(R"(
material rough { color <0.7, 0.7, 0.7> bump noise { seed 2 } scale 0.1 bump_depth 0.25 }
material gentle { bump checker { } }
)");
    INFO(c.sink.format());
    REQUIRE(c.scene.has_value());
    const Material& rough = c.scene->materials[1];
    REQUIRE(rough.bump);
    CHECK(rough.bump->kind == Pattern::Kind::Noise);
    CHECK(rough.bump->seed == 2);
    CHECK(rough.bumpDepth == 0.25);
    CHECK_FALSE(rough.pattern);
    CHECK(c.scene->materials[2].bumpDepth == 0.1);  // the default depth
    requireOneError("material m { bump 0.3 }\n", 1, 19,
                    "property 'bump' of material expects a pattern");
}

TEST_CASE("render: the reconstruction filter and adaptive sampling's noise target") {
    const Compiled c = compileText("render { spp 64 filter mitchell noise 0.01 }\n");
    INFO(c.sink.format());
    REQUIRE(c.scene.has_value());
    CHECK(c.scene->settings.filter == FilterKind::Mitchell);
    CHECK(c.scene->settings.noise == 0.01);
    requireOneError("render { filter tent }\n", 1, 17, "unknown filter 'tent' in render");
    requireOneError("render { noise -1 }\n", 1, 16, "render noise must be 0 or more, got -1");
}

TEST_CASE("motion: move and spin modifiers, the camera's shutter") {
    const Compiled c = compileText(R"(
object sphere { radius 1 } move <2, 0, 0> translate <0, 1, 0>;
object box { min <0, 0, 0> max <1, 1, 1> } spin <0, 90, 0>;
camera { shutter_open 0.25 shutter_close 0.75 }
)");
    INFO(c.sink.format());
    REQUIRE(c.scene.has_value());
    const Node* first = c.scene->objects[0].get();
    REQUIRE(first->kind() == NodeKind::Transform);  // translate after the move
    const Node* motion = first->children()[0].get();
    REQUIRE(motion->kind() == NodeKind::Motion);
    CHECK(std::get<MotionParams>(motion->params()).velocity == Vec3(2.0, 0.0, 0.0));
    const Node* spun = c.scene->objects[1].get();
    REQUIRE(spun->kind() == NodeKind::Motion);
    CHECK(std::get<MotionParams>(spun->params()).spin == Vec3(0.0, 90.0, 0.0));
    CHECK(c.scene->camera.shutterOpen == 0.25);
    CHECK(c.scene->camera.shutterClose == 0.75);
    requireOneError("object sphere { } move 3;\n", 1, 24, "move expects a vector, got a number");
    requireOneError(
        "camera { shutter_open 0.5 shutter_close 2 }\n", 1, 41,
        "camera shutter must open and close within the scene time 0 to 1, got 0.5 to 2");
}
