// Properties that hold for any scene: the nearest of several objects is the hit found, and a
// scene seen under a random rigid motion (camera included) gives the same image: the same
// hit/miss mask except within tangency bands, and depths within the tolerance. (Interval
// containment for every operation, with divisors holding 0 and sqrt/log at 0, is property-
// tested in tests/csg/interval_test.cpp.)
#include "render/camera.h"
#include "render/render.h"
#include "render/render_test_util.h"
#include "util/oracles.h"

#include <catch2/catch.hpp>

#include <cstdio>

using namespace kerf;
using namespace kerf::test;

namespace {

/// A rotation by a random unit quaternion (uniform on SO(3)) and a translation of up to 10.
Affine randomRigid(Random& rng) {
    std::normal_distribution<double> n;
    double q[4];
    double len = 0;
    for (double& x : q) {
        x = n(rng.engine());
        len += x * x;
    }
    for (double& x : q) x /= std::sqrt(len);
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    const double m[12] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
                          rng.uniform(-10, 10),    2 * (x * y + w * z),     1 - 2 * (x * x + z * z),
                          2 * (y * z - w * x),     rng.uniform(-10, 10),    2 * (x * z - w * y),
                          2 * (y * z + w * x),     1 - 2 * (x * x + y * y), rng.uniform(-10, 10)};
    return Affine::fromRowMajor(m);
}

/// The solids of the test scene, as one object (the invariance under test is the geometry's).
NodePtr sceneSolid() {
    return makeBoolean(
        BoolOp::Union,
        {makeBoolean(BoolOp::Difference,
                     {makeBox(Vec3(-1.2, -0.5, -0.6), Vec3(0.2, 0.7, 0.6)),
                      makeCylinder(Vec3(-0.5, 0.1, -1.0), Vec3(-0.5, 0.1, 1.0), 0.35)}),
         makeSphere(Vec3(0.9, 0.4, 0.2), 0.6),
         makeTransform(makeTorus(0.5, 0.15), Affine::translate(Vec3(0.3, -0.6, -0.5))),
         makeCone(Vec3(-0.2, -1.0, 0.8), Vec3(0.4, 0.3, 1.1), 0.4, 0.05)});
}

Scene sceneUnder(const Affine& motion) {
    Scene scene;
    addObject(scene, makeTransform(sceneSolid(), motion), 0);
    scene.camera.eye = motion.point(Vec3(0.6, 1.5, -5.0));
    scene.camera.lookAt = motion.point(Vec3(0.0, 0.0, 0.0));
    scene.camera.up = motion.vector(Vec3(0.0, 1.0, 0.0));
    return scene;
}

/// Whether the pixel-centre ray of (i, j) is within `band` (relative, in direction) of a
/// silhouette: some nudge of its direction by that much changes hit or miss.
bool nearSilhouette(const SceneGeometry& geometry, const Ray& ray, double band) {
    TraceContext ctx;
    ctx.relTolerance = 1e-12;
    const bool centre = bool(geometry.nearestHit(ray, 0.0, kInf, ctx));
    const Vec3 a = unit(glm::cross(ray.dir, Vec3(0.3, 1.0, 0.1))), b = glm::cross(unit(ray.dir), a);
    for (const Vec3& e : {a, -a, b, -b})
        if (bool(geometry.nearestHit(Ray{ray.origin, ray.dir + band * e}, 0.0, kInf, ctx)) !=
            centre)
            return true;
    return false;
}

}  // namespace

// Two spheres at z = 0 and z = 3 along one ray: the nearer must win whatever order the BVH
// visits them in (a regression: the search once kept the last object with a surface).
TEST_CASE("SceneGeometry::nearestHit keeps the nearest object", "[properties]") {
    TraceContext ctx;
    for (bool swap : {false, true}) {
        std::vector<NodePtr> objects{makeSphere(Vec3(0, 0, 0), 1.0),
                                     makeSphere(Vec3(0, 0, 3), 1.0)};
        if (swap) std::swap(objects[0], objects[1]);
        const SceneGeometry scene(objects);
        const auto hit = scene.nearestHit(Ray{Vec3(0, 0, -5), Vec3(0, 0, 1)}, 0.0, kInf, ctx);
        CAPTURE(swap);
        REQUIRE(hit);
        CHECK(hit->t == 4.0);
        CHECK(hit->object == (swap ? 1 : 0));
    }
    // Many objects: every ray's hit is the minimum over the objects' own first hits.
    Random rng(801);
    std::vector<NodePtr> spheres;
    for (int i = 0; i < 40; ++i)
        spheres.push_back(makeSphere(rng.inBall() * 3.0, rng.uniform(0.2, 0.6)));
    const SceneGeometry scene(spheres);
    int wrong = 0;
    for (int i = 0; i < 500; ++i) {
        const Vec3 o = rng.unitVector() * 8.0;
        const Ray ray{o, rng.inBall() * 3.0 - o};
        double best = kInf;
        for (const NodePtr& s : spheres) {
            const auto h = SceneGeometry({s}).nearestHit(ray, 0.0, kInf, ctx);
            if (h) best = std::min(best, h->t);
        }
        const auto hit = scene.nearestHit(ray, 0.0, kInf, ctx);
        wrong += hit ? hit->t != best : !std::isinf(best);
    }
    CHECK(wrong == 0);
}

TEST_CASE("render: a scene under 20 random rigid motions gives the same image") {
    // Tolerance 1e-9 explicit. The bound: twice the tolerance (the root-found torus, bracketed
    // on each side) plus the rounding of the moved camera and geometry, ~ulp·(|translation| +
    // size)/depth ≈ 1e-14. Measured: the float films are identical; in double (nearestHit on
    // every camera ray of both scenes) the worst difference is printed.
    const int W = 48, H = 36;
    const double tolerance = 1e-9;
    RenderOptions options = smallImage(W, H);
    options.wantDepth = true;
    options.tolerance = tolerance;
    const Scene base = sceneUnder(Affine{});
    const RenderResult ref = render(base, options);
    const SceneGeometry baseGeometry(base.objects);
    const Camera baseCamera(base.camera, W, H);
    Random rng(802);
    double worst = 0, worstDouble = 0;
    int banded = 0, hits = 0;
    TraceContext ctx;
    ctx.relTolerance = tolerance;
    for (int k = 0; k < 20; ++k) {
        const Affine motion = randomRigid(rng);
        const Scene moved = sceneUnder(motion);
        const RenderResult r = render(moved, options);
        const SceneGeometry movedGeometry(moved.objects);
        const Camera movedCamera(moved.camera, W, H);
        for (int j = 0; j < H; ++j)
            for (int i = 0; i < W; ++i) {
                const float a = ref.depth.at(i, j, 0), b = r.depth.at(i, j, 0);
                INFO("motion " << k << " pixel " << i << "," << j << " depth " << a << " vs " << b);
                if (std::isinf(a) != std::isinf(b)) {
                    // Allowed only within 1e-9 (in direction) of a silhouette.
                    CHECK(nearSilhouette(baseGeometry, baseCamera.rayThrough(i + 0.5, j + 0.5),
                                         1e-9));
                    ++banded;
                    continue;
                }
                if (std::isinf(a)) continue;
                ++hits;
                const double e = std::fabs(double(b) - a) / a;
                worst = std::max(worst, e);
                CHECK(e <= 2 * tolerance + 0x1p-23);  // plus the float film's rounding
                const auto ha = baseGeometry.nearestHit(baseCamera.rayThrough(i + 0.5, j + 0.5),
                                                        0.0, kInf, ctx);
                const auto hb = movedGeometry.nearestHit(movedCamera.rayThrough(i + 0.5, j + 0.5),
                                                         0.0, kInf, ctx);
                REQUIRE(ha);
                REQUIRE(hb);
                const double ed = std::fabs(hb->t - ha->t) / ha->t;
                worstDouble = std::max(worstDouble, ed);
                CHECK(ed <= 2 * tolerance + 1e-12);
            }
    }
    std::printf(
        "rigid motions: %d hits compared, %d in tangency bands, worst relative depth "
        "difference %.3g (film), %.3g (double)\n",
        hits, banded, worst, worstDouble);
    CHECK(hits > 20 * W * H / 6);
    CHECK(banded <= 2);
}
