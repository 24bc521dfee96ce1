// `mist { … }`: the homogeneous mist as before, and a heterogeneous medium from a density
// expression (scene/medium.h) with its properties; bad properties are errors at their
// line:col. Fog volumes from .vdb files: tests/volume/vdb_fog_test.cpp.
#include "lang_test_util.h"

#include <random>

using namespace kerf;
using namespace kerf::test;

TEST_CASE("mist: uniform mist stays the homogeneous special case") {
    const Compiled c = compileText("mist { color <0.5, 0.6, 0.7> distance 12 }");
    INFO(c.sink.format());
    REQUIRE(c.scene);
    CHECK(c.scene->mist.enabled);
    CHECK(c.scene->mist.distance == 12.0);
    CHECK_FALSE(c.scene->medium.enabled());
}

TEST_CASE("mist: a density expression makes a medium") {
    const Compiled c = compileText(
        "mist {\n"
        "  density 0.5 + 0.25 * noise(x, y, z)\n"
        "  bounds box { min <-1, 0, -2> max <3, 4, 5> }\n"
        "  extinction 0.3 albedo <0.9, 0.8, 0.7> emission <0.1, 0, 0> g 0.4\n"
        "  method march step 0.05\n"
        "}\n");
    INFO(c.sink.format());
    REQUIRE(c.scene);
    const Medium& m = c.scene->medium;
    REQUIRE(m.enabled());
    CHECK_FALSE(c.scene->mist.enabled);
    CHECK(m.bounds.lo == Vec3(-1, 0, -2));
    CHECK(m.bounds.hi == Vec3(3, 4, 5));
    CHECK(m.extinction == 0.3);
    CHECK(m.albedo == Vec3(0.9, 0.8, 0.7));
    CHECK(m.emission == Vec3(0.1, 0, 0));
    CHECK(m.g == 0.4);
    CHECK(m.method == MediumMethod::March);
    CHECK(m.step == 0.05);
    // The field is the expression: at a lattice point the noise is 0.
    CHECK(m.density->value(Vec3(1.0, 2.0, 3.0)) == Approx(0.5).margin(1e-12));
    const Interval r = m.density->range(Interval(-1, 3), Interval(0, 4), Interval(-2, 5));
    CHECK(r.lo <= 0.25);
    CHECK(r.hi >= 0.75);

    const Compiled d =
        compileText("mist { density 1 min <0, 0, 0> max <1, 2, 3> method delta samples 4 }");
    INFO(d.sink.format());
    REQUIRE(d.scene);
    CHECK(d.scene->medium.method == MediumMethod::Delta);
    CHECK(d.scene->medium.samples == 4);
    CHECK(d.scene->medium.bounds.hi == Vec3(1, 2, 3));
}

TEST_CASE("mist: bake N samples the density into bricked storage") {
    // A linear density is its own trilinear interpolant: the baked field equals the expression
    // within float storage (values ≤ 2, so 2⁻²³·2) at random points; its range bounds it.
    const Compiled c = compileText(
        "mist { density 0.5 + 0.25 * x + 0.125 * y - 0.0625 * z"
        " bounds box { min <0, 0, 0> max <4, 2, 1> } bake 33 }");
    INFO(c.sink.format());
    REQUIRE(c.scene);
    const Medium& m = c.scene->medium;
    REQUIRE(m.enabled());
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 p(4 * u(rng), 2 * u(rng), u(rng));
        CHECK(m.density->value(p) ==
              Approx(0.5 + 0.25 * p.x + 0.125 * p.y - 0.0625 * p.z).margin(0x1p-22));
    }
    const Interval r = m.density->range(Interval(0, 4), Interval(0, 2), Interval(0, 1));
    CHECK(r.lo <= 0.4375 + 0x1p-22);
    CHECK(r.hi >= 1.75 - 0x1p-22);
    const std::string box = " bounds box { min <0, 0, 0> max <1, 1, 1> }";
    requireOneError("mist { density 1" + box + " bake 1 }", 1, 66,
                    "mist bake must be an integer from 2 to 4096");
    requireOneError("mist { density volume \"fog.vdb\" bake 64 }", 1, 33,
                    "mist bake is for a density written as an expression");
}

TEST_CASE("mist: bad properties are errors at their position") {
    const std::string box = " bounds box { min <0, 0, 0> max <1, 1, 1> }";
    // Negative density the interval bound proves (here everywhere in the box).
    requireOneError("mist { density -1 - x" + box + " }", 1, 16, "mist density is negative");
    // Negative somewhere the bisection finds: x − 0.9 < 0 for x < 0.9.
    requireOneError("mist { density x - 0.9" + box + " }", 1, 16, "mist density is negative");
    requireOneError("mist { density 1 }", 1, 8, "a mist density needs bounds");
    requireOneError("mist { density 1" + box + " g 1 }", 1, 63, "mist g must be between -1 and 1");
    requireOneError("mist { density 1" + box + " extinction -2 }", 1, 72,
                    "mist extinction must be 0 or more");
    requireOneError("mist { density 1" + box + " albedo <1, 2, 0> }", 1, 68,
                    "mist albedo must be within 0 to 1");
    requireOneError("mist { density 1" + box + " method ray }", 1, 68,
                    "unknown method 'ray' in mist");
    requireOneError("mist { density 1" + box + " step 0.1 }", 1, 61,
                    "mist step is the march method's step");
    requireOneError("mist { density 1" + box + " color <1, 1, 1> }", 1, 61,
                    "mist color is for uniform mist");
    requireOneError("mist { color <1, 1, 1> g 0.5 distance 3 }", 1, 24, "mist g needs a density");
    requireOneError("mist { color <1, 1, 1> }", 1, 1, "mist needs a distance");
    requireOneError("mist { density 1 / x" + box + " }", 1, 16, "no finite bound");
    requireOneError("mist { density volume \"nowhere.vdb\" }", 1, 23,
                    "cannot read fog volume 'nowhere.vdb': no such file");
}
