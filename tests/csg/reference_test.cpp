// referenceNearestHit against first hits computed independently in long double (closed forms
// for the sphere and the box, dense sampling plus bisection of the quartic for the torus), and
// its verdicts on tangent rays and coincident CSG faces.
#include "csg/primitives/reference.h"
#include "util/oracles.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "csg/tree/solids.h"

using namespace kerf;
using namespace kerf::test;

namespace {

/// Each test case reseeds, so its rays do not depend on which other cases ran.
Random gRnd;
Ray randomRay(const Vec3& centre, double spread) {
    Ray r;
    r.origin = centre + 5.0 * gRnd.gaussianUnitVector();
    const Vec3 target =
        centre + spread * Vec3(gRnd.uniform(-1, 1), gRnd.uniform(-1, 1), gRnd.uniform(-1, 1));
    r.dir = (target - r.origin) * gRnd.uniform(0.1, 3.0);
    return r;
}

ReferenceHit reference(const NodePtr& node, const Ray& ray) {
    const SceneGeometry geometry({node});
    return referenceNearestHit(geometry, ray);
}

/// The sphere's entry in long double by the cancellation-free formula; negative when the ray
/// misses, and `conditioning` = |l|/r (near 1: grazing).
LD sphereEntry(const Vec3& centre, double radius, const Ray& ray, LD& conditioning) {
    const LVec3 f = ld(ray.origin) - ld(centre), d = ld(ray.dir);
    const LD a = glm::dot(d, d), h = glm::dot(f, d);
    const LVec3 l = f - (h / a) * d;
    const LD r = radius;
    conditioning = std::sqrt(glm::dot(l, l)) / r;
    const LD disc = a * (r * r - glm::dot(l, l));
    if (!(disc > 0)) return -1;
    const LD q = -(h + std::copysign(std::sqrt(disc), h));
    const LD t0 = std::min(q / a, (glm::dot(f, f) - r * r) / q);
    return t0;
}

/// The box's entry by the slab test in long double (one rounding per division).
LD boxEntry(const Vec3& lo, const Vec3& hi, const Ray& ray) {
    const auto slab = boxOracle(ray, lo, hi);
    return slab && slab->first > 0 ? slab->first : -1;
}

/// The torus quartic (|p|² + R² − r²)² − 4R²(x² + z²) at the ray's point t, in long double.
LD torusQuartic(double R, double r, const Ray& ray, LD t) {
    const LVec3 p = ld(ray.origin) + t * ld(ray.dir);
    const LD k = glm::dot(p, p) + (LD)R * R - (LD)r * r;
    return k * k - 4 * (LD)R * R * (p.x * p.x + p.z * p.z);
}

/// The torus' first crossing: dense sampling of the quartic for its first sign change, then
/// long-double bisection. Negative for a miss; `isolated` false when two sign changes fall
/// within 1e-3 of the range of each other (near-tangent: left out).
LD torusEntry(double R, double r, const Ray& ray, bool& isolated) {
    const int n = 20000;
    const LD t1 = 2 * (glm::length(ray.origin) + R + r) / glm::length(ray.dir);
    LD prev = torusQuartic(R, r, ray, 0);
    int first = -1, second = -1;
    for (int i = 1; i <= n && second < 0; ++i) {
        const LD v = torusQuartic(R, r, ray, t1 * i / n);
        if ((v <= 0) != (prev <= 0)) (first < 0 ? first : second) = i;
        prev = v;
    }
    isolated = first < 0 || second < 0 || second - first > n / 1000;
    if (first < 0) return -1;
    LD lo = t1 * (first - 1) / n, hi = t1 * first / n;
    const bool insideLo = torusQuartic(R, r, ray, lo) <= 0;
    for (int it = 0; it < 200; ++it) {
        const LD m = 0.5L * (lo + hi);
        if (!(m > lo && m < hi)) break;
        ((torusQuartic(R, r, ray, m) <= 0) == insideLo ? lo : hi) = m;
    }
    return 0.5L * (lo + hi);
}

}  // namespace

TEST_CASE("referenceNearestHit: sphere against the long-double closed form") {
    gRnd.seed(11);
    const Vec3 centre(0.25, -0.5, 0.125);
    const double radius = 1.3;
    const NodePtr sphere = makeSphere(centre, radius);
    int hits = 0, compared = 0;
    LD worst = 0, worstNormal = 0;
    for (int i = 0; i < 1000; ++i) {
        const Ray ray = randomRay(centre, 1.8);
        LD conditioning = 0;
        const LD exact = sphereEntry(centre, radius, ray, conditioning);
        if (conditioning > 0.99 && conditioning < 1.01) continue;  // grazing: own test below
        const ReferenceHit ref = reference(sphere, ray);
        if (exact < 0) {
            CHECK(ref.kind == ReferenceHit::Kind::Miss);
            continue;
        }
        ++hits;
        REQUIRE(ref.kind == ReferenceHit::Kind::Hit);
        ++compared;
        const LD err = std::fabs(ref.t - exact) / exact;
        worst = std::max(worst, err);
        CHECK(err <= 1e-17L);
        const LVec3 p = ld(ray.origin) + exact * ld(ray.dir) - ld(centre);
        const LVec3 n = p / std::sqrt(glm::dot(p, p));
        const LVec3 diff = ld(ref.normal) - n;
        worstNormal = std::max(worstNormal, std::sqrt(glm::dot(diff, diff)));
        CHECK(ref.object == 0);
    }
    CHECK(hits > 200);
    INFO("worst relative error " << (double)worst << ", worst normal error " << (double)worstNormal
                                 << " over " << compared << " hits");
    CHECK(worst <= 1e-17L);
    CHECK(worstNormal <= 1e-14L);
}

TEST_CASE("referenceNearestHit: box against the long-double slab test") {
    gRnd.seed(12);
    const Vec3 lo(-1.0, -0.75, -0.5), hi(1.25, 0.5, 0.875);
    const NodePtr box = makeBox(lo, hi);
    int hits = 0;
    for (int i = 0; i < 1000; ++i) {
        Ray ray = randomRay(Vec3(0.0), 1.6);
        if (i % 10 == 0) ray.dir.x = (i % 20 == 0) ? 0.0 : -0.0;  // the −0 trap of the slab test
        const LD exact = boxEntry(lo, hi, ray);
        const ReferenceHit ref = reference(box, ray);
        if (exact < 0) {
            // A ray through an edge or corner only may be a confirmed touch or a miss.
            CHECK(ref.kind != ReferenceHit::Kind::Hit);
            continue;
        }
        ++hits;
        REQUIRE(ref.kind == ReferenceHit::Kind::Hit);
        CHECK(std::fabs(ref.t - exact) <= 1e-17L * exact);
    }
    CHECK(hits > 200);
}

TEST_CASE("referenceNearestHit: torus against dense long-double bisection of the quartic") {
    gRnd.seed(13);
    const double R = 1.0, r = 0.375;
    const NodePtr torus = makeTorus(R, r);
    int hits = 0;
    for (int i = 0; i < 300; ++i) {
        const Ray ray = randomRay(Vec3(0.0), 1.2);
        bool isolated = true;
        const LD exact = torusEntry(R, r, ray, isolated);
        if (!isolated) continue;
        const ReferenceHit ref = reference(torus, ray);
        if (exact < 0) {
            CHECK(ref.kind != ReferenceHit::Kind::Hit);
            continue;
        }
        ++hits;
        REQUIRE(ref.kind == ReferenceHit::Kind::Hit);
        CHECK(std::fabs(ref.t - exact) <= 1e-17L * exact);
    }
    CHECK(hits > 60);
}

TEST_CASE("referenceNearestHit: tangent rays are never a wrong hit") {
    const NodePtr sphere = makeSphere(Vec3(0.0), 1.0);
    SECTION("exactly tangent") {
        const ReferenceHit ref = reference(sphere, {Vec3(-5.0, 1.0, 0.0), Vec3(1.0, 0.0, 0.0)});
        CHECK(ref.kind != ReferenceHit::Kind::Hit);
    }
    SECTION("k ulps outside") {
        double y = 1.0;
        for (int k = 1; k <= 8; ++k) {
            y = std::nextafter(y, 2.0);
            const ReferenceHit ref = reference(sphere, {Vec3(-5.0, y, 0.0), Vec3(1.0, 0.0, 0.0)});
            CHECK(ref.kind != ReferenceHit::Kind::Hit);
        }
    }
    SECTION("k ulps inside: a hit, exact to long double, or uncertain") {
        double y = 1.0;
        for (int k = 1; k <= 64; ++k) {
            y = std::nextafter(y, 0.0);
            const Ray ray{Vec3(-5.0, y, 0.0), Vec3(1.0, 0.0, 0.0)};
            const ReferenceHit ref = reference(sphere, ray);
            // 5 − √(1 − y²) with 1 − y² = (1 − y)(1 + y) exact in long double.
            const LD exact = 5.0L - std::sqrt((1.0L - y) * (1.0L + y));
            CHECK(ref.kind != ReferenceHit::Kind::Miss);
            if (ref.kind == ReferenceHit::Kind::Hit)
                CHECK(std::fabs(ref.t - exact) <= 1e-17L * exact);
        }
    }
}

TEST_CASE("referenceNearestHit: a difference whose cutter shares faces with the body") {
    // [−1, 1]³ minus [0, 1] × [−1, 1]²: the cutter shares four faces with the body.
    const NodePtr solid =
        makeBoolean(BoolOp::Difference,
                    {makeBox(Vec3(-1.0), Vec3(1.0)), makeBox(Vec3(0.0, -1.0, -1.0), Vec3(1.0))});
    SECTION("through the cut: the new face at x = 0") {
        const ReferenceHit ref = reference(solid, {Vec3(5.0, 0.3, 0.2), Vec3(-1.0, 0.0, 0.0)});
        REQUIRE(ref.kind == ReferenceHit::Kind::Hit);
        CHECK(std::fabs(ref.t - 5.0L) <= 1e-17L * 5);
        CHECK(ref.normal.x == Approx(1.0).epsilon(1e-12));
    }
    SECTION("onto the removed half: nothing") {
        const ReferenceHit ref = reference(solid, {Vec3(0.5, 5.0, 0.2), Vec3(0.0, -1.0, 0.0)});
        CHECK(ref.kind == ReferenceHit::Kind::Miss);
    }
    SECTION("onto the kept half: the body's face") {
        const ReferenceHit ref = reference(solid, {Vec3(-0.5, 5.0, 0.2), Vec3(0.0, -1.0, 0.0)});
        REQUIRE(ref.kind == ReferenceHit::Kind::Hit);
        CHECK(std::fabs(ref.t - 4.0L) <= 1e-17L * 4);
        CHECK(ref.normal.y == Approx(1.0).epsilon(1e-12));
    }
}
