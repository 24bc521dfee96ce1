// Moving solids (csg/tree/motion.h): at each scene time a moving node traces as its child turned
// and moved to that time; its bounds and interval values hold for every time in [0, 1].
#include "csg/tree/motion.h"

#include "csg/tree/solids.h"

#include <catch2/catch.hpp>

#include <random>

using namespace kerf;

namespace {

const Vec3 kVelocity(2.0, -0.5, 1.0);
const Vec3 kSpin(30.0, 90.0, -45.0);

/// The child placed at time s by ordinary transforms: turned, then moved.
NodePtr placedAt(const NodePtr& child, double s) {
    return makeTransform(child,
                         Affine::translate(kVelocity * s).after(Affine::rotateDegrees(kSpin * s)));
}

}  // namespace

TEST_CASE("a moving node traces as its child placed at the scene time") {
    const NodePtr child =
        makeBoolean(BoolOp::Difference, {makeBox(Vec3(-1.0, -0.5, -0.3), Vec3(1.0, 0.5, 0.3)),
                                         makeSphere(Vec3(0.8, 0.0, 0.0), 0.4)});
    const NodePtr moving = makeMotion(child, kVelocity, kSpin);
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int hits = 0;
    for (int k = 0; k < 2000; ++k) {
        const double s = 0.5 + 0.5 * unit(rng);
        const NodePtr reference = placedAt(child, s);
        const SceneTimeScope clock(s);
        CHECK(sceneTime() == s);
        // From around the solid's place at time s, toward it.
        const Vec3 origin = Vec3(unit(rng), unit(rng), unit(rng)) * 4.0 + kVelocity * s;
        const Vec3 target = kVelocity * s + 0.8 * Vec3(unit(rng), unit(rng), unit(rng));
        const Ray ray{origin, glm::normalize(target - origin)};
        TraceContext a, b;
        Boundary ha, hb;
        bool ea = false, eb = false;
        const bool fa = moving->firstSurface(ray, 0.0, kInf, a, ha, ea);
        const bool fb = reference->firstSurface(ray, 0.0, kInf, b, hb, eb);
        REQUIRE(fa == fb);
        if (!fa) continue;
        ++hits;
        CHECK(ea == eb);
        CHECK(ha.t == Approx(hb.t).epsilon(1e-12));
        CHECK(glm::length(glm::normalize(ha.normal) - glm::normalize(hb.normal)) < 1e-9);
        const Vec3 p = ray.at(0.5 * ha.t);
        CHECK((moving->value(p) <= 0.0) == (reference->value(p) <= 0.0));
    }
    CHECK(hits > 300);
    CHECK(sceneTime() == 0.0);  // the scopes restored it
}

TEST_CASE("a moving node's bounds and interval values hold for every time") {
    const NodePtr child = makeSphere(Vec3(1.0, 0.0, 0.0), 0.5);
    for (const Vec3 spin : {Vec3(0.0), kSpin}) {
        const NodePtr moving = makeMotion(child, kVelocity, spin);
        const Bounds3 b = moving->bounds();
        std::mt19937_64 rng(5);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        for (int k = 0; k < 500; ++k) {
            const double s = unit(rng);
            // A point of the sphere at time s lies in the bounds.
            const Vec3 local =
                Vec3(1.0, 0.0, 0.0) +
                0.5 * glm::normalize(Vec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5));
            const Vec3 world = Affine::translate(kVelocity * s)
                                   .after(Affine::rotateDegrees(spin * s))
                                   .point(local);
            for (int a = 0; a < 3; ++a) {
                REQUIRE(world[a] >= b.lo[a]);
                REQUIRE(world[a] <= b.hi[a]);
            }
            // A box's interval value holds the value at any time of any point in it.
            const Vec3 c(unit(rng) * 4 - 1, unit(rng) * 2 - 1, unit(rng) * 2 - 1);
            const double h = 0.3 * unit(rng);
            const Interval v =
                moving->valueInterval({{c.x - h, c.x + h}, {c.y - h, c.y + h}, {c.z - h, c.z + h}});
            const Vec3 q = c + h * Vec3(2 * unit(rng) - 1, 2 * unit(rng) - 1, 2 * unit(rng) - 1);
            const SceneTimeScope clock(unit(rng));
            const double value = moving->value(q);
            REQUIRE(v.lo <= value);
            REQUIRE(value <= v.hi);
        }
    }
}
