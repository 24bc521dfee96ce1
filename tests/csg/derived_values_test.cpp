// The hand-written value evaluations of the older leaves against the ones Primitive derives
// from their implicit forms (csg/primitives/primitive.h): double and long double values within
// a stated bound, and each interval holding the other evaluation's values at points of its box.
#include "csg/primitives/primitive.h"
#include "csg/tree/solids.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

using namespace kerf;

namespace {

std::vector<std::pair<std::string, NodePtr>> leaves() {
    return {
        {"sphere", makeSphere(Vec3(0.3, -0.2, 0.1), 0.9)},
        {"box", makeBox(Vec3(-1, -0.5, -0.25), Vec3(0.5, 1, 0.75))},
        {"cylinder", makeCylinder(Vec3(-0.5, -0.3, 0.2), Vec3(0.6, 0.4, -0.3), 0.4)},
        {"cone", makeCone(Vec3(-0.5, 0.3, 0.2), Vec3(0.6, -0.4, -0.3), 0.6, 0.1)},
        {"torus", makeTorus(0.8, 0.25)},
        {"halfspace", makeHalfSpace(Vec3(0.3, -1, 0.4), 0.2)},
        {"capsule", makeCapsule(Vec3(-0.5, -0.3, 0.2), Vec3(0.6, 0.4, -0.3), 0.4)},
    };
}

}  // namespace

TEST_CASE("Primitive: hand-written values agree with the derived ones") {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    for (const auto& [name, node] : leaves()) {
        const auto* p = dynamic_cast<const Primitive*>(node.get());
        REQUIRE(p);
        INFO(name);
        for (int i = 0; i < 2000; ++i) {
            const Vec3 q(u(rng), u(rng), u(rng));
            // Both are the same formula in a different order of operations (and the long
            // double ones from the exact end points or the rounded frame): a few ulps of the
            // coordinates' scale, 4.
            CHECK(std::fabs(p->value(q) - p->derivedValue(q)) <= 1e-14);
            CHECK(std::fabs(p->valueExtended(LVec3(q)) - p->derivedValueExtended(LVec3(q))) <=
                  1e-14L);
        }
    }
}

TEST_CASE("Primitive: hand-written intervals hold the derived values, and back") {
    std::mt19937_64 rng(6);
    std::uniform_real_distribution<double> u(-2.0, 2.0), w(0.0, 0.5), s01(0.0, 1.0);
    for (const auto& [name, node] : leaves()) {
        const auto* p = dynamic_cast<const Primitive*>(node.get());
        INFO(name);
        for (int i = 0; i < 300; ++i) {
            const Vec3 lo(u(rng), u(rng), u(rng));
            const Vec3 hi = lo + Vec3(w(rng), w(rng), w(rng));
            const IntervalVec3 box{Interval(lo.x, hi.x), Interval(lo.y, hi.y),
                                   Interval(lo.z, hi.z)};
            const Interval hand = p->valueInterval(box), derived = p->derivedValueInterval(box);
            for (int k = 0; k < 20; ++k) {
                const Vec3 q = lo + Vec3(s01(rng), s01(rng), s01(rng)) * (hi - lo);
                CHECK(hand.contains(p->derivedValue(q)));
                CHECK(derived.contains(p->value(q)));
            }
        }
    }
}
