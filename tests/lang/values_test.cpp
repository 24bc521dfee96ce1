/// @file tests/lang/values_test.cpp
/// @brief Values out of range (docs/robustness.md, "Values"): material weights that would
/// add energy, transforms that fold to inf or 0, and the checks at extreme scales that must
/// be relative and overflow-safe and say "not finite" when that is the problem. (A literal
/// beyond the double range, 1e400, is refused where it is read, before these checks.)
#include "lang_test_util.h"

#include <catch2/catch.hpp>

using namespace kerf;
using kerf::test::compileText;
using kerf::test::requireOneError;

namespace {

void requireOk(const std::string& text) {
    const auto c = compileText(text);
    INFO(text << "\n" << c.sink.format());
    REQUIRE(c.scene.has_value());
    CHECK(c.sink.errorCount() == 0);
}

}  // namespace

TEST_CASE("Lowering: reflect and transmit pass on at most the light that arrives") {
    requireOneError("material m { reflect 2 }", 1, 22, "material reflect must be at most 1, got 2");
    requireOneError("material m { transmit 1.5 }", 1, 23, "material transmit must be at most 1");
    requireOneError("material g { color <1, 1, 1> transmit 1 reflect 1 ior 1.5 }", 1, 49,
                    "material reflect + transmit must be at most 1, got 1 + 1");
    requireOneError("material g { reflect 0.5\n  transmit 0.6 }", 2, 12,
                    "reflect + transmit must be at most 1");
    requireOneError("material g { color <1.2, 1, 1> transmit 0.9 }", 1, 20,
                    "the color of a material that transmits must not exceed 1");
    requireOk("material g { color <1, 1, 1> transmit 0.95 reflect 0.05 }");
    requireOk("material m { reflect 1 }");
    requireOk("material bright { color <2, 2, 2> }");  // an opaque colour sends no rays on
}

TEST_CASE(
    "Lowering: a folded transform that is not finite or singular is an error at its modifier") {
    requireOneError("object sphere {} translate <1e308, 0, 0> translate <1e308, 0, 0>;", 1, 42,
                    "transform is not finite after this translate");
    requireOneError("object sphere {} scale 1e-200 scale 1e-200;", 1, 31,
                    "transform is singular after this scale");
    requireOneError("object sphere {} scale 1e200 scale 1e200;", 1, 30,
                    "transform is not finite after this scale");
    requireOneError("object sphere {} scale 1e-300 translate <1, 0, 0> scale 1e-10;", 1, 51,
                    "transform is singular after this scale");
    // Each fold is judged whole: large steps that cancel are fine.
    requireOk("object sphere {} scale 1e-300;");
    requireOk("object sphere {} scale 1e300;");
    requireOk("object sphere {} scale 1e-200 scale 1e150;");
    requireOk("object sphere {} translate <1e308, 0, 0> translate <-1e308, 0, 0>;");
    requireOk("object sphere {} scale <1e-300, 1, 1e300> rotate <10, 20, 30>;");
}

TEST_CASE("Lowering: a transformed solid whose extent passes the double range is an error") {
    requireOneError("object sphere { radius 1e300 } scale 1e10;", 1, 32,
                    "the solid's extent is not finite after this scale");
    // Nested transforms: each fold is finite, together they are not.
    requireOneError("object union { sphere {} scale 1e200 } scale 1e200;", 1, 40,
                    "extent is not finite after this scale");
    requireOneError("object sphere { radius 1e306 } translate <1.79e308, 0, 0> material default;",
                    1, 32, "extent is not finite after this translate");
    requireOk("object sphere { radius 1e298 } scale 1e10;");
    requireOk("object halfspace { normal <0, 1, 0> } scale 1e300;");  // unbounded to begin with
}

TEST_CASE("Lowering: a matrix is singular relative to its own scale") {
    requireOk("object sphere {} matrix [1e300 0 0 0  0 1e300 0 0  0 0 1e300 0];");
    requireOk("object sphere {} matrix [1e-300 0 0 0  0 1e-300 0 0  0 0 1e-300 0];");
    requireOk("object sphere {} matrix [1e300 1e300 0 0  0 1e300 0 0  0 0 1e-300 0];");
    requireOneError("object sphere {} matrix [1 2 3 0  2 4 6 0  0 0 1 0];", 1, 18,
                    "matrix is singular");
    requireOneError("object sphere {} matrix [1e300 2e300 0 0  2e300 4e300 0 0  0 0 1 0];", 1, 18,
                    "matrix is singular");
}

TEST_CASE("Lowering: cylinder and cone axes at extreme scales") {
    requireOk("object cylinder { from <0, -1e300, 0> to <0, 1e300, 0> radius 1 };");
    requireOk("object cylinder { from <0, 1e-300, 0> to <0, 2e-300, 0> radius 1e-300 };");
    requireOk("object cone { from <0, -1e300, 0> to <0, 1e300, 0> radius1 1e300 };");
    requireOneError("object cylinder { from <0, -1e308, 0> to <0, 1e308, 0> };", 1, 8,
                    "cylinder axis to - from is not finite");
    requireOneError("object cone { from <0, -1e308, 0> to <0, 1e308, 0> };", 1, 8,
                    "cone axis to - from is not finite");
    requireOneError("object cylinder { from <1e300, 0, 0> to <1e300, 0, 0> };", 1, 8,
                    "cylinder has zero length");
}

TEST_CASE("Lowering: camera checks at extreme scales") {
    requireOk("camera { eye <0, 0, -5e200> look_at <0, 0, 0> }");
    requireOk("camera { eye <0, 0, -5e-300> look_at <0, 0, 0> up <0, 1e-300, 0> }");
    requireOk("camera { eye <0, 0, -1> look_at <0, 0, 0> up <0, 1e300, 0> }");
    requireOneError("camera { eye <0, 0, -1> look_at <0, 0, 0> up <0, 0, 1e300> }", 1, 46,
                    "is parallel");
    requireOneError("camera { eye <0, 0, -1e308> look_at <0, 0, 1e308> }", 1, 37,
                    "camera look_at - eye is not finite");
}
