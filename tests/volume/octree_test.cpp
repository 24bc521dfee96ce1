// The octree gives the same first hits as the plain object tree: every pixel ray of small
// images of implicit scenes, at several octree depths, against --accel none.
#include "volume/accelerate.h"

#include "csg/scene_geometry.h"
#include "lang/compile.h"
#include "render/camera.h"
#include "render/render.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <optional>
#include <string>

using namespace kerf;

namespace {

Scene compiled(const std::string& text) {
    DiagnosticSink sink;
    std::optional<Scene> scene = compileString(text, "octree_test.kerf", sink);
    INFO(sink.format());
    REQUIRE(scene.has_value());
    return std::move(*scene);
}

const char* kGyroidBall = R"(
let k = 2*pi;
solid g = implicit {
    f sin(k*x)*cos(k*y) + sin(k*y)*cos(k*z) + sin(k*z)*cos(k*x)
    bound box { min <-3.1, -3.1, -3.1> max <3.1, 3.1, 3.1> }
};
solid ball = intersection { g sphere { radius 3 } };
object ball translate <0, 3, 0>;
object halfspace { normal <0, 1, 0> offset 0 };
camera { eye <0, 5, -12> look_at <0, 3, 0> up <0, 1, 0> fov 35 }
)";

struct Mismatch {
    int count = 0;
    std::string first;
};

/// Every pixel-centre ray of a width × height image: hit or miss and the hit distance of the
/// octree geometry against the plain one (within the tolerance: both are root-found).
Mismatch comparePixels(const Scene& scene, int width, int height, int depth) {
    const double tolerance = defaultTolerance(height, scene.camera.fovDegrees);
    const Camera camera(scene.camera, width, height);
    const SceneGeometry plain(scene.objects, false);
    OctreeOptions options;
    options.depth = depth;
    AcceleratedObjects acc = accelerate(scene.objects, Accel::Octree, options);
    const SceneGeometry fast(std::move(acc.objects), true);
    TraceContext ctx;
    ctx.relTolerance = tolerance;
    Mismatch m;
    for (int j = 0; j < height; ++j) {
        for (int i = 0; i < width; ++i) {
            const Ray ray = camera.rayThrough(i + 0.5, j + 0.5);
            const std::optional<Hit> a = plain.nearestHit(ray, 0.0, kInf, ctx);
            const std::optional<Hit> b = fast.nearestHit(ray, 0.0, kInf, ctx);
            bool same = a.has_value() == b.has_value();
            if (same && a) same = std::fabs(a->t - b->t) <= 4.0 * tolerance * a->t &&
                                  a->entering == b->entering;
            if (same) continue;
            if (m.count++ == 0)
                m.first = "pixel " + std::to_string(i) + "," + std::to_string(j) + ": plain " +
                          (a ? std::to_string(a->t) : std::string("miss")) + ", octree " +
                          (b ? std::to_string(b->t) : std::string("miss"));
        }
    }
    return m;
}

}  // namespace

TEST_CASE("octree first hits equal the plain tree's on a gyroid ball", "[octree]") {
    const Scene scene = compiled(kGyroidBall);
    for (int depth : {3, 5, 7}) {
        const Mismatch m = comparePixels(scene, 200, 150, depth);
        INFO("depth " << depth << ": " << m.count << " mismatches; first " << m.first);
        CHECK(m.count == 0);
    }
}
