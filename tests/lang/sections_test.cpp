/// @file tests/lang/sections_test.cpp
/// @brief `section { point normal color }`: the planes a model declares, and the errors a bad
/// one gets, each at its place.
#include "lang_test_util.h"

#include <catch2/catch.hpp>

using namespace kerf;
using namespace kerf::test;

TEST_CASE("sections: planes are read, normals made unit, colours defaulted") {
    const Compiled c = compileText(R"(object sphere { center <0, 0, 0> radius 1 };
section { point <0, 0, 0.5> normal <0, 0, 2> }
section { normal <3, 0, -4> point <1, 2, 3> color <0.1, 0.2, 0.3> }
if true { section { point <0, 0, 0> normal <0, -1, 0> } }
)");
    INFO(c.sink.format());
    REQUIRE(c.scene.has_value());
    const std::vector<SectionPlane>& s = c.scene->sections;
    REQUIRE(s.size() == 3);
    CHECK(s[0].point == Vec3(0, 0, 0.5));
    CHECK(s[0].normal == Vec3(0, 0, 1));  // exact: 2 scaled by a power of two
    CHECK(s[0].color == SectionPlane{}.color);
    CHECK(s[1].point == Vec3(1, 2, 3));
    CHECK(s[1].normal.x == Approx(0.6).epsilon(1e-15));
    CHECK(s[1].normal.y == 0.0);
    CHECK(s[1].normal.z == Approx(-0.8).epsilon(1e-15));
    CHECK(s[1].color == Vec3(0.1, 0.2, 0.3));
    CHECK(s[2].normal == Vec3(0, -1, 0));
}

TEST_CASE("sections: a model without one has none") {
    const Compiled c = compileText("object sphere { center <0, 0, 0> radius 1 };\n");
    REQUIRE(c.scene.has_value());
    CHECK(c.scene->sections.empty());
}

TEST_CASE("sections: bad planes are errors at their place") {
    requireOneError("section { point <0, 0, 0> normal <0, 0, 0> }\n", 1, 34,
                    "section normal must not be zero");
    requireOneError("section { point <0, 0, 0> normal <0, 0, 1> color <1, -1, 0> }\n", 1, 50,
                    "section color must not have negative components");
    requireOneError("section { point <0, 0, 0> }\n", 1, 1, "section needs the property 'normal'");
    requireOneError("section { normal <0, 0, 1> }\n", 1, 1, "section needs the property 'point'");
    requireOneError("section { point <0, 0, 0> normal 1 }\n", 1, 34, "normal");
    requireOneError("section { point <0, 0, 0> normal <0, 0, 1> offset 2 }\n", 1, 44,
                    "unknown property 'offset'");
    requireOneError("let section = 1;\n", 1, 5, "reserved word");
}

TEST_CASE("sections: more than the limit is one error") {
    const Compiled c = compileText("for i in 1 .. " + std::to_string(kMaxSections + 10) +
                                   " { section { point <0, 0, i> normal <0, 0, 1> } }\n");
    INFO(c.sink.format());
    REQUIRE_FALSE(c.scene.has_value());
    REQUIRE(c.sink.errorCount() == 1);
    CHECK_THAT(
        c.sink.diagnostics().front().message,
        Catch::Matchers::Contains("more than " + std::to_string(kMaxSections) + " section planes"));
}
