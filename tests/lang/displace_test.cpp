// `displace PATTERN by D`: the displaced solid against closed forms (a pattern constant over
// the solid moves a sphere's surface by exactly ±D), its material, its bound, and the
// messages for what cannot be displaced.
#include "lang_test_util.h"

#include "csg/tape/noise.h"
#include "csg/trace_context.h"

#include <random>
#include <variant>

using namespace kerf;
using namespace kerf::test;

namespace {

/// The first hit of a ray from outside along -z through (x, y, 5) on the scene's only object.
double hitDepth(const Scene& scene, double x, double y) {
    TraceContext ctx;
    Boundary hit;
    bool entering = false;
    const Ray ray{Vec3(x, y, 5.0), Vec3(0.0, 0.0, -1.0)};
    REQUIRE(scene.objects[0]->firstSurface(ray, 0.0, kInf, ctx, hit, entering));
    return 5.0 - hit.t;
}

}  // namespace

TEST_CASE("noise nearly constant over the solid displaces a sphere by D times its value") {
    // Scaled up a millionfold, the noise barely changes over the unit sphere (its slope is at
    // most 8.5 per unit of its own space): the surface is the sphere of radius 1 + D·n₀,
    // n₀ = noise(0.3, 0.6, 0.2), up to 8.5·D·1e-6.
    const double n0 = gradientNoise(Vec3(0.3, 0.6, 0.2), 0);
    REQUIRE(std::fabs(n0) > 0.05);
    for (double depth : {0.25, -0.25}) {
        const Compiled c = compileText(
            "object sphere { radius 1 } displace noise { } translate <-0.3, -0.6, "
            "-0.2> scale 1e6 by " +
            std::to_string(depth) + ";");
        INFO(c.sink.format());
        REQUIRE(c.scene.has_value());
        REQUIRE(c.scene->objects.size() == 1);
        CHECK(c.scene->objects[0]->kind() == NodeKind::Implicit);
        const double radius = 1.0 + depth * n0;
        for (double x : {0.0, 0.3, -0.5}) {
            const double expected = std::sqrt(radius * radius - x * x);
            CHECK(std::fabs(hitDepth(*c.scene, x, 0.0) - expected) <= 8.5 * 0.25 * 1e-6 * 2.0);
        }
    }
}

TEST_CASE("a noise-displaced sphere: every hit is on f − D·noise = 0 and within D of the sphere") {
    const Compiled c = compileText(R"(
material rock { color <0.6, 0.5, 0.4> }
object sphere { radius 1 } material rock displace noise { seed 4 } scale 0.3 by 0.1;
)");
    INFO(c.sink.format());
    REQUIRE(c.scene.has_value());
    const NodePtr& node = c.scene->objects[0];
    // The material around the sphere stays around the displaced solid.
    REQUIRE(node->kind() == NodeKind::Material);
    CHECK(std::get<MaterialParams>(node->params()).material == 1);
    // Its bound holds the whole displaced surface: at least the sphere grown by D.
    CHECK(node->bounds().hi.x >= 1.1);
    CHECK(node->bounds().lo.y <= -1.1);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int hits = 0;
    for (int i = 0; i < 300; ++i) {
        // Inside the radius 0.85 < 1 − 0.1 every ray from above meets the displaced sphere.
        const double r = 0.85 * std::sqrt(unit(rng)), angle = 6.283185307179586 * unit(rng);
        const double x = r * std::cos(angle), y = r * std::sin(angle);
        const double z = hitDepth(*c.scene, x, y);
        const Vec3 p(x, y, z);
        const double radius = glm::length(p);
        // The surface is |p| − 1 = 0.1·noise(p / 0.3) (seed 4), and so within 0.1 of the sphere.
        CHECK(std::fabs(radius - 1.0 - 0.1 * gradientNoise(p / 0.3, 4)) <= 1e-7);
        CHECK(std::fabs(radius - 1.0) <= 0.1 + 1e-9);
        ++hits;
    }
    CHECK(hits == 300);
}

TEST_CASE("displace: what cannot be displaced is an error at its place") {
    requireOneError("object sphere { radius 1 } displace 0.1;", 1, 37,
                    "expected a pattern after 'displace'");
    requireOneError("object sphere { radius 1 } displace noise { } 0.1;", 1, 47,
                    "expected 'by DEPTH'");
    requireOneError("object sphere { radius 1 } displace noise { } by <1, 2, 3>;", 1, 50,
                    "depth must be a finite number");
    requireOneError("object sphere { radius 1 } move <1, 0, 0> displace noise { } by 0.1;", 1, 43,
                    "a moving solid cannot be displaced");
    requireOneError("object halfspace { normal <0, 1, 0> } displace noise { } by 0.1;", 1, 39,
                    "only a bounded solid can be displaced");
    requireOneError("object sphere { radius 1 } displace marble { } by 0.1;", 1, 37,
                    "unknown pattern 'marble'");
    requireOneError("object sphere { radius 1 } displace checker { } by 0.1;", 1, 37,
                    "displace takes a continuous pattern");
    requireOneError("object sphere { radius 1 } displace noise { } move <1, 0, 0> by 0.1;", 1, 47,
                    "a pattern takes only translate, rotate, scale and matrix");
}

TEST_CASE("noise() in an implicit function is the gradient noise") {
    const Compiled c = compileText(R"(
object implicit { f sqrt(x*x + y*y + z*z) - 1 - 0.1 * noise(3*x, 3*y, 3*z) bound box { min <-2, -2, -2> max <2, 2, 2> } };
let n = noise(0.5, 0.25, 0.125);
assert abs(n) <= 1;
)");
    INFO(c.sink.format());
    REQUIRE(c.scene.has_value());
    const double z = hitDepth(*c.scene, 0.2, 0.1);
    const Vec3 p(0.2, 0.1, z);
    CHECK(std::fabs(glm::length(p) - 1.0 - 0.1 * gradientNoise(3.0 * p, 0)) <= 1e-7);
}
