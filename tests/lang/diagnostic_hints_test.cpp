// The messages for habits from POV-Ray and OpenSCAD (issue 9 §4): each checked for its text,
// line and column, and each hint that shows kerf's form is compiled and its solid checked
// against the solid the user's values describe.
#include "lang/diagnostic_hints.h"

#include "lang_test_util.h"

using namespace kerf;
using Catch::Matchers::Contains;
using Catch::Matchers::EndsWith;
using Catch::Matchers::StartsWith;
using kerf::test::compileText;

namespace {

const char* const kSolidList =
    "The solids are: sphere, box, cylinder, cone, torus, halfspace, implicit, extrude, revolve, "
    "union, "
    "intersection, difference, xor";

/// The one error of `text`, checked for its message and place.
Diagnostic oneError(const std::string& text, int line, int col, const std::string& message) {
    const test::Compiled c = compileText(text);
    INFO(c.sink.format());
    REQUIRE_FALSE(c.scene.has_value());
    REQUIRE(c.sink.errorCount() == 1);
    const Diagnostic& d = c.sink.diagnostics().front();
    CHECK(d.message == message);
    CHECK(d.loc.line == line);
    CHECK(d.loc.col == col);
    return d;
}

/// The text between "write '" and the next "'" in a hint: kerf's form of the solid.
std::string suggestedForm(const std::string& hint) {
    const size_t start = hint.find("write '");
    REQUIRE(start != std::string::npos);
    const size_t end = hint.find('\'', start + 7);
    REQUIRE(end != std::string::npos);
    return hint.substr(start + 7, end - start - 7);
}

/// Compiles `object FORM;` and returns the bounds of its one object.
Bounds3 boundsOf(const std::string& form) {
    const test::Compiled c = compileText("object " + form + ";");
    INFO(form << "\n" << c.sink.format());
    REQUIRE(c.scene.has_value());
    REQUIRE(c.scene->objects.size() == 1);
    return c.scene->objects[0]->bounds();
}

void requireBounds(const Bounds3& b, const Vec3& lo, const Vec3& hi) {
    for (int i = 0; i < 3; ++i) {
        CHECK(b.lo[i] == Approx(lo[i]).margin(1e-12));
        CHECK(b.hi[i] == Approx(hi[i]).margin(1e-12));
    }
}

}  // namespace

TEST_CASE("hints: an unknown solid used like a primitive") {
    SECTION("POV-Ray's merge: one error at its name, the body skipped") {
        const Diagnostic d = oneError(
            "object sphere {};\nobject merge {\n  sphere { radius 1 }\n  sphere { center <1, 0, 0> "
            "}\n};",
            2, 8, "unknown solid 'merge'");
        CHECK(d.hint ==
              std::string(
                  "use 'union': kerf's union keeps no inner surfaces, like POV-Ray's merge. ") +
                  kSolidList);
    }
    SECTION("OpenSCAD's cube, an ellipsoid, an isosurface") {
        CHECK_THAT(
            oneError("object cube { size 1 };", 1, 8, "unknown solid 'cube'").hint,
            StartsWith("use 'box': write box { min <0, 0, 0> max <s, s, s> }. The solids are:"));
        CHECK_THAT(oneError("object ellipsoid { };", 1, 8, "unknown solid 'ellipsoid'").hint,
                   StartsWith("use 'sphere': write sphere { radius 1 } scale <a, b, c>."));
        CHECK_THAT(
            oneError("object isosurface { function { x } };", 1, 8, "unknown solid 'isosurface'")
                .hint,
            StartsWith("use 'implicit':"));
    }
    SECTION("shapes kerf does not have say so") {
        CHECK_THAT(oneError("object lathe { linear_spline 2, <0, 0>, <1, 1> };", 1, 8,
                            "unknown solid 'lathe'")
                       .hint,
                   StartsWith("lathes are not supported yet. The solids are:"));
        CHECK_THAT(
            oneError("object union { blob { threshold 0.5 } };", 1, 16, "unknown solid 'blob'")
                .hint,
            StartsWith("blobs are not supported yet"));
    }
    SECTION("a near miss within two edits is suggested, a farther one is not") {
        CHECK(oneError("object cylindr { };", 1, 8, "unknown solid 'cylindr'").hint ==
              std::string("did you mean 'cylinder'? ") + kSolidList);
        CHECK(oneError("object unoin { sphere {} };", 1, 8, "unknown solid 'unoin'").hint ==
              std::string("did you mean 'union'? ") + kSolidList);
        CHECK(oneError("object  sph { };", 1, 9, "unknown solid 'sph'").hint ==
              "the solids are: sphere, box, "
              "cylinder, cone, torus, halfspace, implicit, extrude, revolve, union, intersection, "
              "difference, xor");
    }
    SECTION("as the bound of an implicit") {
        CHECK_THAT(
            oneError("object implicit { f x bound cube { } };", 1, 29, "unknown solid 'cube'").hint,
            StartsWith("use 'box'"));
    }
    SECTION("a name, not a block: undefined, with what kerf has instead") {
        CHECK(oneError("object cube;", 1, 8, "undefined solid 'cube'").hint ==
              "use 'box': write box { min <0, 0, 0> max <s, s, s> }");
    }
    SECTION("the kinds the parser knows are the ones lowering builds") {
        // A new primitive added to lowering but not to the hint table would be "unknown".
        for (const std::string& kind : primitiveKinds()) {
            const test::Compiled c = compileText("object " + kind + " { };");
            for (const Diagnostic& d : c.sink.diagnostics())
                CHECK_THAT(d.message, !StartsWith("unknown solid"));
        }
    }
}

TEST_CASE("hints: POV-Ray's positional values") {
    struct Case {
        const char* text;
        int col;
        const char* found;
        const char* form;
        Vec3 lo, hi;  // the bounds of the solid the values describe
    };
    const Case cases[] = {
        {"object sphere { <1, 2, 3>, 0.5 };",
         17,
         "'<'",
         "sphere { center <1, 2, 3> radius 0.5 }",
         {0.5, 1.5, 2.5},
         {1.5, 2.5, 3.5}},
        {"object box { <0,0,0>, <1,2,3> };",
         14,
         "'<'",
         "box { min <0,0,0> max <1,2,3> }",
         {0, 0, 0},
         {1, 2, 3}},
        {"object cylinder { <0, 0, 0>, <0, 2, 0>, 0.5 };",
         19,
         "'<'",
         "cylinder { from <0, 0, 0> to <0, 2, 0> radius 0.5 }",
         {-0.5, 0, -0.5},
         {0.5, 2, 0.5}},
        {"object cone { <0, 0, 0>, 1, <0, 3, 0>, 0 };",
         15,
         "'<'",
         "cone { from <0, 0, 0> radius1 1 to <0, 3, 0> radius2 0 }",
         {-1, 0, -1},
         {1, 3, 1}},
        {"object torus { 2, 0.5 };",
         16,
         "'2'",
         "torus { major 2 minor 0.5 }",
         {-2.5, -0.5, -2.5},
         {2.5, 0.5, 2.5}},
    };
    for (const Case& k : cases) {
        const std::string kind = std::string(k.form).substr(0, std::string(k.form).find(' '));
        INFO(k.text);
        const Diagnostic d = oneError(k.text, 1, k.col,
                                      "expected a property name in " + kind + ", found " + k.found);
        CHECK(d.hint == std::string("kerf names each property: write '") + k.form + "'");
        requireBounds(boundsOf(suggestedForm(d.hint)), k.lo, k.hi);
    }
    SECTION("expressions and lets keep their spelling, line breaks become blanks") {
        const Diagnostic d = oneError("let c = <1, 2, 3>;\nobject sphere { c,\n    2 * 0.25 };", 2,
                                      17, "expected a property name in sphere, found 'c'");
        CHECK(suggestedForm(d.hint) == "sphere { center c radius 2 * 0.25 }");
    }
    SECTION("POV-Ray's open after the values") {
        const Diagnostic d = oneError("object cylinder { <0, 0, 0>, <0, 1, 0>, 1 open };", 1, 19,
                                      "expected a property name in cylinder, found '<'");
        CHECK_THAT(
            d.hint,
            EndsWith("'; kerf writes it 'open true' (the side alone: a surface, not a solid)"));
    }
    SECTION("a count POV-Ray does not take shows the form with placeholders") {
        CHECK(
            oneError("object sphere { 1 };", 1, 17, "expected a property name in sphere, found '1'")
                .hint == "kerf names each property: write 'sphere { center <x, y, z> radius r }'");
    }
    SECTION("POV-Ray's plane becomes a halfspace with the same values") {
        const Diagnostic d =
            oneError("object plane { <0, 1, 0>, -1 };", 1, 8, "unknown solid 'plane'");
        CHECK_THAT(d.hint,
                   StartsWith("write 'halfspace { normal <0, 1, 0> offset -1 }' (POV-Ray's plane"));
        const test::Compiled c = compileText("object " + suggestedForm(d.hint) + ";");
        REQUIRE(c.scene.has_value());
        // n·p <= d: below y = -1, as POV-Ray's plane { y, -1 }.
        CHECK(c.scene->objects[0]->value(Vec3(0, -1.5, 0)) < 0);
        CHECK(c.scene->objects[0]->value(Vec3(0, -0.5, 0)) > 0);
    }
}

TEST_CASE("hints: unknown and value-less properties in every block") {
    SECTION("a flag at the end of a block, and one before another property") {
        const Diagnostic d =
            oneError("object cone {\n  from <0, 0, 0> to <0, 1, 0>\n  radius1 1 open\n};", 3, 13,
                     "property 'open' of cone has no value");
        // POV-Ray's bare `open` flag: kerf takes `open true` (an open cone is a surface).
        CHECK(d.hint == "write its value after the name: 'open true'");
        oneError("object cone { from <0, 0, 0> open to <0, 1, 0> };", 1, 30,
                 "property 'open' of cone has no value");
    }
    SECTION("a block for a value is skipped") {
        const Diagnostic d = oneError("object sphere { radius 1 pigment { color <1, 0, 0> } };", 1,
                                      26, "unknown property 'pigment' in sphere");
        CHECK_THAT(d.hint, StartsWith("colours are materials:"));
        CHECK_THAT(d.hint, EndsWith("; sphere takes: center, radius"));
    }
    SECTION("each kind of block") {
        struct Case {
            const char* text;
            int col;
            const char* message;
            const char* takes;
        };
        const Case cases[] = {
            {"object box { min <0,0,0> max <1,1,1> sturm };", 38, "unknown property 'sturm' in box",
             "box takes: min, max"},
            {"object torus { major 1 minor 0.2 open };", 34, "unknown property 'open' in torus",
             "torus takes: major, minor"},
            {"object halfspace { normal <0,1,0> inverse };", 35,
             "unknown property 'inverse' in halfspace", "halfspace takes: normal, offset"},
            {"object implicit { f x bound box { min <0,0,0> max <1,1,1> } max_gradient 4 };", 61,
             "unknown property 'max_gradient' in implicit", "implicit takes: f, bound"},
            {"material m { color <1,0,0> phong }", 28, "unknown property 'phong' in material",
             "material takes: color, ambient, diffuse, specular, shininess, reflect, transmit, "
             "ior, absorb, emit, glossy, translucent, pattern, bump, bump_depth"},
            {"camera { location <0, 0, -5> }", 10, "unknown property 'location' in camera",
             "camera takes: eye, look_at, up, fov, aperture, focus_distance, shutter_open, "
             "shutter_close"},
            {"light point { at <0,1,0> shadowless }", 26,
             "unknown property 'shadowless' in point light",
             "point light takes: color, at, power, falloff, fade_distance, shadows"},
            {"light directional { direction <0,-1,0> parallel }", 40,
             "unknown property 'parallel' in directional light",
             "directional light takes: color, direction, shadows"},
            {"mist { distance 1 fog }", 19, "unknown property 'fog' in mist",
             "mist takes: color, distance, density, bounds, min, max, extinction, albedo, "
             "emission, g, "
             "method, step, samples, bake"},
            {"render { width 10 antialias 0.3 }", 19, "unknown property 'antialias' in render",
             "render takes: width, height, spp, max_depth, sampler, filter, noise"},
        };
        for (const Case& k : cases) {
            INFO(k.text);
            CHECK_THAT(oneError(k.text, 1, k.col, k.message).hint, EndsWith(k.takes));
        }
        CHECK(oneError("camera { location <0, 0, -5> }", 1, 10,
                       "unknown property 'location' in camera")
                  .hint ==
              "the camera's position is eye; camera takes: eye, look_at, up, fov, "
              "aperture, focus_distance, shutter_open, shutter_close");
    }
    SECTION("a known property without a value, required or not: one error") {
        CHECK(
            oneError("object sphere { radius };", 1, 17, "property 'radius' of sphere has no value")
                .hint == "write its value after the name: 'radius 1'");
        CHECK(
            oneError("object box { min <0,0,0> max };", 1, 26, "property 'max' of box has no value")
                .hint == "write its value after the name: 'max <x, y, z>'");
        CHECK(oneError("object implicit { f x bound { min <0,0,0> max <1,1,1> } };", 1, 23,
                       "property 'bound' of implicit has no value")
                  .hint == "write its value after the name: 'bound box { min … max … }'");
    }
}

TEST_CASE("hints: a named solid as the bound of an implicit") {
    const Diagnostic d = oneError(
        "solid cube = box { min <-1, -1, -1> max <1, 1, 1> };\n"
        "object implicit {\n  f x^2 + y^2 + z^2 - 1\n  bound cube\n};",
        4, 9,
        "a named solid is not allowed as the bound of an implicit: write box { min … max … } in "
        "place of "
        "'cube'");
    CHECK_THAT(d.hint,
               StartsWith("the bound is an axis-aligned box in the implicit's own coordinates"));
    CHECK_THAT(d.hint, EndsWith("bound box { min lo max hi }"));
    // What the hint proposes compiles.
    const test::Compiled c = compileText(
        "let lo = <-1, -1, -1>; let hi = <1, 1, 1>;\n"
        "object implicit { f x^2 + y^2 + z^2 - 1 bound box { min lo max hi } };");
    INFO(c.sink.format());
    REQUIRE(c.scene.has_value());
    requireBounds(c.scene->objects[0]->bounds(), Vec3(-1), Vec3(1));
}

TEST_CASE("hints: OpenSCAD's call syntax and POV-Ray's statements") {
    CHECK(oneError("cube([1, 2, 3]);", 1, 1, "expected a statement, found 'cube'").hint ==
          "kerf has no call syntax for solids; a box is box { min <0, 0, 0> max <s, s, s> }");
    CHECK(
        oneError("translate([1, 0, 0]) sphere(1);", 1, 1, "expected a statement, found 'translate'")
            .hint ==
        "kerf has no call syntax for solids; transforms follow the solid: sphere { … } translate "
        "<x, y, z>");
    CHECK(
        oneError("object union {\n  sphere(1)\n};", 2, 9, "expected '{' after 'sphere', found '('")
            .hint ==
        "kerf has no call syntax for solids; a sphere is sphere { center <x, y, z> radius r }");
    CHECK_THAT(oneError("object union { rotate([0, 90, 0]) box {} };", 1, 16,
                        "expected a solid, found 'rotate'")
                   .hint,
               StartsWith("kerf has no call syntax for solids; transforms follow the solid"));
    CHECK(oneError("plane { <0, 1, 0>, 0 }", 1, 1, "expected a statement, found 'plane'").hint ==
          "use 'halfspace': POV-Ray's plane { n, d } is halfspace { normal n offset d }: all p "
          "with n·p <= d; "
          "a solid is put into the scene with 'object …;'");
    CHECK(
        oneError("light_source { <0, 10, 0> }", 1, 1, "expected a statement, found 'light_source'")
            .hint == "a light is light point { at <x, y, z> color <r, g, b> }");
}

TEST_CASE("OpenSCAD's call syntax where a solid is a function call") {
    // `object cube([1, 2, 3]);` parses as a call of a function 'cube'; the message keeps kerf's
    // form for a box as its hint.
    DiagnosticSink sink;
    const std::optional<Scene> scene =
        compileString("object cube([1, 2, 3]);\n", "scad.kerf", sink);
    CHECK_FALSE(scene.has_value());
    const std::string text = sink.format();
    INFO(text);
    CHECK(text.find("scad.kerf:1:8: error: unknown function 'cube'") != std::string::npos);
    CHECK(text.find("a box is box { min <0, 0, 0> max <s, s, s> }") != std::string::npos);
}
