// Boolean and transform nodes against independent oracles: brute-force span combination,
// closed-form ellipsoids, and the point-wise definition of each operation.
#include "csg/bvh/scene_geometry.h"
#include "csg/tree/solids.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace kerf;

namespace {

bool insideSpans(const SpanList& s, double t) {
    for (const Span& x : s)
        if (x.in.t < t && t < x.out.t) return true;
    return false;
}

std::vector<NodePtr> randomSpheres(std::mt19937_64& rng, int n) {
    std::uniform_real_distribution<double> pos(-2.0, 2.0), rad(0.05, 0.2);
    std::vector<NodePtr> spheres;
    for (int i = 0; i < n; ++i)
        spheres.push_back(makeSphere({pos(rng), pos(rng) * 0.5, pos(rng)}, rad(rng)));
    return spheres;
}

Ray randomRayThrough(std::mt19937_64& rng, double spread) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const Vec3 origin(u(rng) * 2, u(rng) * 2 + 5.0, -8.0);
    const Vec3 target(u(rng) * spread, u(rng) * spread * 0.5, u(rng) * spread);
    return {origin, target - origin};
}

}  // namespace

TEST_CASE("makeBoolean: a box minus 1000 spheres equals the brute-force combination", "[boolean]") {
    std::mt19937_64 rng(7);
    std::vector<NodePtr> children{makeBox({-2, -1, -2}, {2, 1, 2})};
    const std::vector<NodePtr> spheres = randomSpheres(rng, 1000);
    children.insert(children.end(), spheres.begin(), spheres.end());
    const NodePtr diff = makeBoolean(BoolOp::Difference, children);

    TraceContext ctx;
    ctx.relTolerance = 1e-12;
    uint64_t primitiveTests = 0;
    const int rays = 300;
    for (int r = 0; r < rays; ++r) {
        const Ray ray = randomRayThrough(rng, 2.5);
        SpanList fast;
        ctx.stats = {};
        diff->spans(ray, 0.0, kInf, ctx, fast);
        primitiveTests += ctx.stats.primitiveTests;

        SpanList slow, tmp, child;
        children[0]->spans(ray, 0.0, kInf, ctx, slow);
        for (size_t i = 1; i < children.size(); ++i) {
            children[i]->spans(ray, 0.0, kInf, ctx, child);
            combineSpans(BoolOp::Difference, slow, child, 1e-12, tmp);
            slow.swap(tmp);
        }
        REQUIRE(fast.size() == slow.size());
        for (int k = 0; k < fast.size(); ++k) {
            CHECK(fast[k].in.t == slow[k].in.t);
            CHECK(fast[k].out.t == slow[k].out.t);
            CHECK(fast[k].in.primitive == slow[k].in.primitive);
        }
    }
    // The BVH finds the few cutters along each ray instead of testing all 1000.
    const double perRay = double(primitiveTests) / rays;
    INFO("primitive tests per ray: " << perRay);
    CHECK(perRay < 40.0);
}

TEST_CASE("makeBoolean: membership along rays matches value() for every operation", "[boolean]") {
    std::mt19937_64 rng(11);
    const NodePtr a = makeSphere({0, 0, 0}, 1.0);
    const NodePtr b = makeBox({-0.3, -2, -0.7}, {1.5, 0.4, 0.9});
    const NodePtr c = makeSphere({0.5, 0.5, 0}, 0.6);
    TraceContext ctx;
    for (BoolOp op : {BoolOp::Union, BoolOp::Intersection, BoolOp::Difference, BoolOp::Xor}) {
        const NodePtr node = makeBoolean(op, {a, b, c});
        for (int r = 0; r < 200; ++r) {
            const Ray ray = randomRayThrough(rng, 1.5);
            SpanList s;
            node->spans(ray, 0.0, kInf, ctx, s);
            for (int k = 0; k <= 400; ++k) {
                const double t = 0.025 * k + 1e-7;
                const double v = node->value(ray.at(t));
                if (std::fabs(v) < 1e-6) continue;  // too near a surface to judge
                INFO("op " << int(op) << " ray " << r << " t " << t << " value " << v);
                REQUIRE(insideSpans(s, t) == (v < 0));
            }
        }
    }
}

TEST_CASE("makeBoolean: a cutter sharing faces with the body leaves a clean hole", "[boolean]") {
    // A unit box with a square hole whose cutter is exactly as tall as the box: no 1.001 trick.
    const NodePtr body = makeBox({0, 0, 0}, {1, 1, 1});
    const NodePtr cutter = makeBox({0.25, 0, 0.25}, {0.75, 1, 0.75});
    const NodePtr holed = makeBoolean(BoolOp::Difference, {body, cutter});
    TraceContext ctx;
    ctx.relTolerance = 1e-12;
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0.26, 0.74), tilt(-0.2, 0.2);
    for (int r = 0; r < 2000; ++r) {
        // Straight down through the hole, slightly tilted but never reaching the walls.
        const Vec3 o(u(rng), 3.0, u(rng));
        const Vec3 d(tilt(rng) * 0.002, -1.0, tilt(rng) * 0.002);
        SpanList s;
        holed->spans({o, d}, 0.0, kInf, ctx, s);
        INFO("ray " << r);
        REQUIRE(s.empty());
    }
    SECTION("and the walls of the hole face into the hole") {
        const Ray ray{{0.5, 0.5, 0.5}, {1, 0, 0}};  // from the hole's centre toward +x
        SpanList s;
        holed->spans(ray, 0.0, kInf, ctx, s);
        REQUIRE(s.size() == 2);  // spans cover the whole line: one wall lies behind the origin
        CHECK(s[0].out.t == -0.25);
        CHECK(s[0].out.normal.x > 0);
        CHECK(s[1].in.t == 0.25);
        CHECK(s[1].in.normal.x < 0);  // outward of the solid, so toward the hole
    }
}

TEST_CASE("makeTransform: a scaled sphere is the closed-form ellipsoid", "[transform]") {
    const Vec3 radii(2.0, 0.5, 1.25), centre(1, -2, 3);
    const NodePtr ellipsoid = makeTransform(makeSphere({0, 0, 0}, 1.0),
                                            Affine::translate(centre).after(Affine::scale(radii)));
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    TraceContext ctx;
    int hits = 0;
    for (int r = 0; r < 2000; ++r) {
        const Vec3 o = centre + Vec3(u(rng) * 10, u(rng) * 10, -20);
        const Vec3 d = centre + Vec3(u(rng) * 2.5, u(rng) * 0.7, u(rng) * 1.5) - o;
        // Long-double oracle: Σ ((o + t d - c)_i / r_i)² = 1.
        long double A = 0, B = 0, C = -1;
        for (int i = 0; i < 3; ++i) {
            const long double oc = ((long double)o[i] - centre[i]) / radii[i];
            const long double dd = (long double)d[i] / radii[i];
            A += dd * dd;
            B += 2 * oc * dd;
            C += oc * oc;
        }
        const long double disc = B * B - 4 * A * C;
        SpanList s;
        ellipsoid->spans({o, d}, 0.0, kInf, ctx, s);
        if (disc <= 0) {
            CHECK(s.empty());
            continue;
        }
        REQUIRE(s.size() == 1);
        ++hits;
        const long double t0 = (-B - std::sqrt(disc)) / (2 * A);
        CHECK(std::fabs((long double)s[0].in.t - t0) <= 1e-12L * std::fabs(t0));
        // Normal: the gradient (x/a², y/b², z/c²) at the hit.
        const Vec3 p = Vec3(o) + s[0].in.t * d - centre;
        const Vec3 expected = glm::normalize(p / (radii * radii));
        CHECK(glm::length(glm::normalize(s[0].in.normal) - expected) < 1e-9);
    }
    CHECK(hits > 500);
}

TEST_CASE("SceneGeometry::nearestHit: nearest object, instances, and rays from inside", "[scene]") {
    const NodePtr unit = makeSphere({0, 0, 0}, 1.0);
    // One shared subtree, three instances.
    std::vector<NodePtr> objects;
    for (int i = 0; i < 3; ++i)
        objects.push_back(
            makeMaterial(makeTransform(unit, Affine::translate({3.0 * i, 0, 0})), i + 1));
    objects.push_back(makeHalfSpace({0, 1, 0}, -1.0));  // floor at y = -1, default material
    const SceneGeometry scene(objects);
    TraceContext ctx;

    for (int i = 0; i < 3; ++i) {
        const auto hit = scene.nearestHit({{3.0 * i, 0, -10}, {0, 0, 1}}, 0.0, kInf, ctx);
        REQUIRE(hit);
        CHECK(hit->t == Approx(9.0).epsilon(1e-15));
        CHECK(hit->material == i + 1);
        CHECK(hit->entering);
        CHECK(hit->normal.z == Approx(-1.0));
    }
    SECTION("the floor, with the default material") {
        const auto hit = scene.nearestHit({{10, 5, 0}, {0, -2, 0}}, 0.0, kInf, ctx);
        REQUIRE(hit);
        CHECK(hit->t == Approx(3.0));  // direction is not unit: 6 units at 2 per t
        CHECK(hit->material == 0);
    }
    SECTION("from inside a sphere the hit is the way out") {
        const auto hit = scene.nearestHit({{0, 0, 0}, {1, 0, 0}}, 0.0, kInf, ctx);
        REQUIRE(hit);
        CHECK_FALSE(hit->entering);
        CHECK(hit->t == Approx(1.0));
        CHECK(hit->normal.x == Approx(1.0));
    }
    SECTION("tmax bounds the search") {
        CHECK_FALSE(scene.nearestHit({{0, 0, -10}, {0, 0, 1}}, 0.0, 8.5, ctx));
    }
}

TEST_CASE("Bounds3::clipRay handles zero and negative-zero directions", "[types]") {
    const Bounds3 box{{-1, -1, -1}, {1, 1, 1}};
    for (double zero : {0.0, -0.0}) {
        double t0 = 0, t1 = kInf;
        CHECK(box.clipRay({{0, 0.5, -5}, {zero, zero, 1}}, t0, t1));
        CHECK(t0 == 4.0);
        CHECK(t1 == 6.0);
        t0 = 0, t1 = kInf;
        CHECK_FALSE(box.clipRay({{0, 1.5, -5}, {zero, zero, 1}}, t0, t1));
        t0 = 0, t1 = kInf;
        CHECK(box.clipRay({{0, 1.0, -5}, {zero, zero, 1}}, t0, t1));  // in the face plane
    }
    double t0 = -kInf, t1 = kInf;
    CHECK(Bounds3::everything().clipRay({{0, 0, 0}, {0, -0.0, 1}}, t0, t1));
    CHECK(t0 == -kInf);
}

TEST_CASE("Affine: rotations by multiples of 90 degrees are exact", "[types]") {
    const Affine r = Affine::rotateDegrees({90, 180, -270});
    for (int c = 0; c < 3; ++c)
        for (int row = 0; row < 3; ++row) {
            const double m = r.linear[c][row];
            CHECK((m == 0.0 || m == 1.0 || m == -1.0));
        }
    const Affine a = Affine::rotateDegrees({10, 20, 30}).after(Affine::translate({1, 2, 3}));
    const Vec3 p(0.3, -0.7, 2.0);
    CHECK(glm::length(a.inverse().point(a.point(p)) - p) < 1e-14);
}

TEST_CASE("SceneGeometry::occluded: any surface within the segment blocks", "[scene]") {
    std::vector<NodePtr> objects;
    for (int i = 0; i < 20; ++i) objects.push_back(makeSphere({0, 0, 3.0 * i}, 1.0));
    objects.push_back(makeHalfSpace({0, 1, 0}, -5.0));
    const SceneGeometry scene(objects);
    TraceContext ctx;
    const Ray along{{0, 0, -10}, {0, 0, 1}};
    CHECK(scene.occluded(along, 0.0, kInf, ctx));
    CHECK(scene.occluded(along, 0.0, 9.5, ctx));
    CHECK_FALSE(scene.occluded(along, 0.0, 8.5, ctx));  // stops short of the first sphere
    CHECK_FALSE(scene.occluded({{5, 0, -10}, {0, 0, 1}}, 0.0, kInf, ctx));  // passes beside
    CHECK(scene.occluded({{5, 0, -10}, {0, -1, 0}}, 0.0, kInf, ctx));       // down to the floor
    // From inside a sphere the way out is a surface too.
    CHECK(scene.occluded({{0, 0, 3}, {1, 0, 0}}, 0.0, kInf, ctx));
}
