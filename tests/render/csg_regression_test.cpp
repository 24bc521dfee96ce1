/// @file tests/render/csg_regression_test.cpp
/// @brief CSG bugs found by rendering models, kept as models: the text goes through lang/ and
/// the renderer exactly as a user's would.
#include "lang/compile.h"
#include "render_test_util.h"

#include <catch2/catch.hpp>

#include <string>

using namespace kerf;
using namespace kerf::test;

namespace {

/// The depth and normal at the centre pixel of an 81×61 render of `text`.
void centreHit(const std::string& text, float& depth, Vec3& normal) {
    DiagnosticSink sink;
    const std::optional<Scene> scene = compileString(text, "regression.kerf", sink);
    INFO(sink.format());
    REQUIRE(scene);
    RenderOptions options = smallImage(81, 61);
    options.wantDepth = true;
    options.wantNormal = true;
    const RenderResult r = render(*scene, options);
    depth = r.depth.at(40, 30, 0);
    normal = pixel(r.normal, 40, 30);
}

const char* kScene = R"(
    camera { eye <0, 4, -3> look_at <0, 0, 0> fov 40 }
    light point { at <0, 10, -5> power 1500 }
)";

}  // namespace

TEST_CASE("intersection: an implicit operand after the first keeps the entry face of the first") {
    // The centre ray meets the box's top face at the origin (t = 5) inside the implicit's
    // bound; the implicit, searched only from t = 5 on, comes back clipped there. Once that clip
    // won the tie with the box's face, the hit fell to the bound's far side (t = 6.25, −y).
    const std::string box = "box { min <-5, -5, -5> max <5, 0, 5> }";
    const std::string halfspace = "halfspace { normal <0, 1, 0> offset 0 }";
    const std::string implicit = "implicit { f -1 bound box { min <-1, -1, -1> max <1, 1, 1> } }";
    for (const std::string& first : {box, halfspace}) {
        for (bool implicitFirst : {false, true}) {
            const std::string a = implicitFirst ? implicit : first,
                              b = implicitFirst ? first : implicit;
            const std::string text = "object intersection {\n" + a + "\n" + b + "\n};\n" + kScene;
            INFO(text);
            float depth = 0;
            Vec3 normal(0.0);
            centreHit(text, depth, normal);
            CHECK(depth == Approx(5.0).epsilon(1e-6));
            CHECK(glm::length(normal - Vec3(0, 1, 0)) <= 1e-6);
        }
    }
}
