/// @file tests/render/integrator_test.cpp
/// @brief The render loop runs any Integrator (render/integrator.h): a test integrator that
/// shows the hit normal renders a ball whose every pixel matches the ball's analytic normal,
/// through the same tiles, film and threads as Whitted, and the default factory is Whitted.
#include "render/integrator.h"
#include "render/camera.h"
#include "render/whitted_integrator.h"
#include "render_test_util.h"

#include <catch2/catch.hpp>

#include <atomic>

using namespace kerf;
using namespace kerf::test;

namespace {

/// Shows (n + 1)/2 of the first hit's outward normal, black on a miss; counts its calls.
class NormalIntegrator final : public Integrator {
public:
    NormalIntegrator(const SceneGeometry& geometry, std::atomic<int>& calls)
        : mGeometry(geometry), mCalls(calls) {}

    Vec3 traceCamera(const Ray& ray, ShadingContext& ctx, std::optional<Hit>* firstHit,
                     double tStart) const override {
        ++mCalls;
        ++ctx.rays.camera;
        const std::optional<Hit> hit = mGeometry.nearestHit(ray, tStart, kInf, ctx.trace);
        if (firstHit) *firstHit = hit;
        return hit ? 0.5 * (hit->normal + Vec3(1.0)) : Vec3(0.0);
    }

private:
    const SceneGeometry& mGeometry;
    std::atomic<int>& mCalls;
};

Scene ballScene(const Vec3& centre, double radius) {
    Scene scene;
    scene.camera.eye = Vec3(0.0, 0.0, -5.0);
    scene.camera.lookAt = Vec3(0.0);
    scene.camera.fovDegrees = 40;
    Material m;  // no lights: Whitted would show ambient only, never a normal
    addObject(scene, makeSphere(centre, radius), addMaterial(scene, m));
    return scene;
}

}  // namespace

TEST_CASE("render: the loop traces through any Integrator") {
    const Vec3 centre(0.2, -0.1, 0.3);
    const double radius = 1.2;
    const Scene scene = ballScene(centre, radius);
    const int W = 40, H = 30;
    std::atomic<int> calls{0};
    RenderOptions options = smallImage(W, H, 2);
    options.wantDepth = true;
    options.integrator = [&calls](const IntegratorInputs& in) -> std::unique_ptr<Integrator> {
        return std::make_unique<NormalIntegrator>(in.geometry, calls);
    };
    const RenderResult r = render(scene, options);
    CHECK(calls.load() == W * H);  // one call per sample, spp = 1
    CHECK(r.stats.cameraRays == uint64_t(W * H));

    const Camera camera(scene.camera, W, H);
    int hits = 0;
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            const Ray ray = camera.rayThrough(i + 0.5, j + 0.5);
            const Vec3 d = glm::normalize(ray.dir);
            const std::optional<long double> t = raySphere(ray.origin, d, centre, radius);
            const Vec3 c = pixel(r.color, i, j);
            INFO("pixel " << i << ", " << j);
            if (!t) {
                // Pixels that graze the ball's rim could go either way: only clear misses.
                if (std::isinf(r.depth.at(i, j, 0))) CHECK(c == Vec3(0.0));
                continue;
            }
            const Vec3 n = (ray.origin + double(*t) * d - centre) / radius;
            if (n.z > -0.05) continue;  // near the silhouette the rim may round either way
            ++hits;
            CHECK(glm::length(c - 0.5 * (n + Vec3(1.0))) < 1e-5);
        }
    CHECK(hits > 250);  // the ball fills about a quarter of the frame
}

TEST_CASE("makeIntegrator: the scene's settings give Whitted") {
    const Scene scene = ballScene(Vec3(0.0), 1.0);
    const SceneGeometry geometry(scene.objects);
    const std::unique_ptr<Integrator> integrator = makeIntegrator({scene, geometry, nullptr});
    CHECK(dynamic_cast<const WhittedIntegrator*>(integrator.get()) != nullptr);
}
