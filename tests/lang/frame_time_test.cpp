// The predefined names `frame` and `time` (lang/sequence_frame.h): their values in
// expressions, checked by the hit distance of a ray on a sphere whose radius uses them
// (closed form 10 − r), their defaults, and definitions of the same names hiding them.
#include "lang_test_util.h"

#include "csg/trace_context.h"

using namespace kerf;
using namespace kerf::test;

namespace {

Compiled compileFrame(const std::string& text, SequenceFrame frame) {
    Compiled c;
    c.scene = compileString(text, "frame.kerf", c.sink, EvalLimits{}, frame);
    return c;
}

/// The distance from (0, 0, −10) along +z to the scene's only object: 10 − r for a sphere of
/// radius r at the origin.
double hitDistance(const Compiled& c) {
    INFO(c.sink.format());
    REQUIRE(c.scene.has_value());
    REQUIRE(c.scene->objects.size() == 1);
    TraceContext ctx;
    Boundary hit;
    bool entering = false;
    const Ray ray{Vec3(0.0, 0.0, -10.0), Vec3(0.0, 0.0, 1.0)};
    REQUIRE(c.scene->objects[0]->firstSurface(ray, 0.0, kInf, ctx, hit, entering));
    return hit.t;
}

}  // namespace

TEST_CASE("frame/a sphere of radius 1 + frame is hit at 10 - (1 + frame) at two frames") {
    const std::string model = "object sphere { center <0, 0, 0> radius 1 + frame };";
    for (int64_t frame : {2, 5}) {
        INFO("frame " << frame);
        const double t = hitDistance(compileFrame(model, SequenceFrame{frame, 0.0}));
        CHECK(t == Approx(10.0 - (1.0 + double(frame))).epsilon(1e-12));
    }
}

TEST_CASE("frame/time reaches every kind of expression: lets, functions, loops, implicit fields") {
    const SequenceFrame f{7, 0.25};
    // Through a let and a function call: r = 1 + 4 · 0.25 = 2.
    CHECK(hitDistance(compileFrame("fn grow(a) = a + 4 * time; let r = grow(1);\n"
                                   "object sphere { radius r };",
                                   f)) == Approx(8.0).epsilon(1e-12));
    // A loop bound: frame 7 makes 7 shells of radius 0.5 … 3.5 whose union is hit at the outer.
    CHECK(hitDistance(compileFrame(
              "object union { for i in 1 .. frame { sphere { radius i / 2 } } };", f)) ==
          Approx(10.0 - 3.5).epsilon(1e-12));
    // Inside an implicit f, where x, y, z are free: the sphere of radius 1 + 2 · time = 1.5.
    CHECK(hitDistance(compileFrame("object implicit { f x*x + y*y + z*z - (1 + 2*time)^2\n"
                                   "  bound box { min <-3, -3, -3> max <3, 3, 3> } };",
                                   f)) == Approx(10.0 - 1.5).epsilon(1e-9));
}

TEST_CASE("frame/without a sequence frame and time are 0") {
    const Compiled c = compileText("object sphere { radius 1 + frame + 8 * time };");
    CHECK(hitDistance(c) == Approx(9.0).epsilon(1e-12));
}

TEST_CASE("frame/a definition of frame or time in the model hides the predefined value") {
    const SequenceFrame f{4, 0.5};
    // Older models that use the names keep their meaning.
    CHECK(hitDistance(compileFrame("let time = 3; object sphere { radius time };", f)) ==
          Approx(7.0).epsilon(1e-12));
    CHECK(hitDistance(compileFrame(
              "object union { for frame in 2 .. 2 { sphere { radius frame } } };", f)) ==
          Approx(8.0).epsilon(1e-12));
    CHECK(hitDistance(compileFrame("fn r(frame) = frame + 1; object sphere { radius r(1) };", f)) ==
          Approx(8.0).epsilon(1e-12));
}

TEST_CASE("frame/a misspelt time is an undefined name with a suggestion") {
    const Compiled c = compileText("object sphere { radius 1 + tme };");
    INFO(c.sink.format());
    REQUIRE_FALSE(c.scene.has_value());
    REQUIRE(c.sink.errorCount() == 1);
    CHECK_THAT(c.sink.diagnostics().front().message,
               Catch::Matchers::Contains("undefined name 'tme'"));
    CHECK_THAT(c.sink.diagnostics().front().hint, Catch::Matchers::Contains("time"));
}
