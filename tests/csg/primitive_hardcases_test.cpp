// The cases that break naive ray/primitive code: signed-zero directions, rays in face planes,
// grazing rays a few ulps from tangency, far-away origins, huge and tiny scales, rays parallel
// to a plane, along a cone's axis or its slant.
#include "csg/tree/solids.h"
#include "util/oracles.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

using namespace kerf;
using namespace kerf::test;

namespace {

/// All spans of the node along the whole line, zero-width ones included.
SpanList spansOf(const Node& node, const Ray& ray) {
    TraceContext ctx;
    SpanList out;
    node.spans(ray, -kInf, kInf, ctx, out);
    return out;
}

/// The spans that callers keep: no NaN anywhere, in ≤ out, zero-width ones dropped.
std::vector<Span> kept(const Node& node, const Ray& ray) {
    std::vector<Span> r;
    for (const Span& s : spansOf(node, ray)) {
        REQUIRE_FALSE(std::isnan(s.in.t));
        REQUIRE_FALSE(std::isnan(s.out.t));
        REQUIRE(s.in.t <= s.out.t);
        for (int a = 0; a < 3; ++a) {
            REQUIRE_FALSE(std::isnan(s.in.normal[a]));
            REQUIRE_FALSE(std::isnan(s.out.normal[a]));
        }
        if (s.in.t < s.out.t) r.push_back(s);
    }
    return r;
}

/// Each test case reseeds, so its rays do not depend on which other cases ran.
Random gRnd;

}  // namespace

TEST_CASE("Box::spans with signed-zero directions and rays in face planes") {
    const NodePtr box = makeBox(Vec3(-1), Vec3(1));
    SECTION("axis-aligned views with every sign of zero") {
        for (int axis = 0; axis < 3; ++axis) {
            for (int zeros = 0; zeros < 4; ++zeros) {
                for (double sign : {1.0, -1.0}) {
                    Ray ray;
                    ray.origin = Vec3(0.3, -0.2, 0.6);
                    ray.origin[axis] = -5.0 * sign;
                    int k = 0;
                    for (int a = 0; a < 3; ++a)
                        ray.dir[a] = a == axis ? 2.0 * sign : ((zeros >> k++) & 1 ? -0.0 : 0.0);
                    const std::vector<Span> s = kept(*box, ray);
                    CAPTURE(axis, zeros, sign);
                    REQUIRE(s.size() == 1);
                    CHECK(s[0].in.t == 2.0);  // (−1 + 5)/2, exactly
                    CHECK(s[0].out.t == 3.0);
                    Vec3 n(0);
                    n[axis] = -sign;
                    CHECK(s[0].in.normal == n);
                    CHECK(s[0].out.normal == -n);
                }
            }
        }
    }
    SECTION("oblique ray with one -0 component") {
        const std::vector<Span> s = kept(*box, Ray{Vec3(-3, 0.5, -4), Vec3(1, -0.0, 2)});
        REQUIRE(s.size() == 1);
        CHECK(s[0].in.t == 2.0);   // x = −1 at t = 2 (z = 0 there)
        CHECK(s[0].out.t == 2.5);  // z = 1 at t = 2.5
        CHECK(s[0].in.normal == Vec3(-1, 0, 0));
        CHECK(s[0].out.normal == Vec3(0, 0, 1));
    }
    SECTION("a ray in a face plane or along an edge is inside the closed box") {
        for (const Vec3& o :
             {Vec3(1, 0.3, -5), Vec3(-1, 0.3, -5), Vec3(1, 1, -5), Vec3(-1, 1, -5)}) {
            const std::vector<Span> s = kept(*box, Ray{o, Vec3(-0.0, 0.0, 2)});
            REQUIRE(s.size() == 1);
            CHECK(s[0].in.t == 2.0);
            CHECK(s[0].out.t == 3.0);
            CHECK(s[0].in.normal == Vec3(0, 0, -1));
        }
        // One ulp outside the face plane: a miss.
        CHECK(kept(*box, Ray{Vec3(std::nextafter(1.0, 2.0), 0.3, -5), Vec3(0, 0, 2)}).empty());
        CHECK(kept(*box, Ray{Vec3(0.3, std::nextafter(-1.0, -2.0), -5), Vec3(-0.0, 0, 2)}).empty());
    }
}

TEST_CASE("Sphere::spans on grazing rays") {
    gRnd.seed(7);
    SECTION("axis-aligned, where the miss distance is exact: hit iff inside by one ulp") {
        const NodePtr sphere = makeSphere(Vec3(0), 0.7);
        for (int k = 1; k <= 64; k *= 2) {
            for (int side : {-1, 1}) {
                double b = 0.7;
                for (int i = 0; i < k; ++i) b = std::nextafter(b, side * 2.0);
                const std::vector<Span> s = kept(*sphere, Ray{Vec3(-20, b, 0), Vec3(1, 0, 0)});
                CAPTURE(k, side);
                CHECK(s.size() == (side < 0 ? 1u : 0u));
                if (!s.empty()) CHECK(0.5 * (s[0].in.t + s[0].out.t) == 20.0);
            }
        }
    }
    SECTION("oblique: hit iff the long-double distance says so, beyond 8 ulps of it") {
        int hits = 0, misses = 0;
        for (int i = 0; i < 2000; ++i) {
            const Vec3 c(gRnd.uniform(-5, 5), gRnd.uniform(-5, 5), gRnd.uniform(-5, 5));
            const double r = std::exp(gRnd.uniform(-2, 2));
            const Vec3 u = gRnd.unitVector(), v = gRnd.perpendicular(u);
            const double k = std::exp(gRnd.uniform(0, std::log(1e4)));
            const double b = r * (1 + (i % 2 ? k : -k) * kUlp);
            const Ray ray{c + b * v - 10 * r * u, u * std::exp(gRnd.uniform(-3, 3))};
            // The true miss distance of the rounded ray, in long double.
            const LVec3 f = ld(ray.origin) - ld(c), d = ld(ray.dir);
            const LD tc = -glm::dot(f, d) / glm::dot(d, d);
            const LD dist = glm::length(f + tc * d);
            const LD margin = (dist - r) / r;
            const std::vector<Span> s = kept(*makeSphere(c, r), ray);
            CAPTURE(i, double(margin / kUlp));
            if (margin < -8 * kUlp) {
                REQUIRE(s.size() == 1);
                // The chord's middle is well-conditioned even where its ends are not.
                CHECK(std::fabs(0.5L * (s[0].in.t + s[0].out.t) - tc) <= 1e-12L * tc);
                ++hits;
            } else if (margin > 8 * kUlp) {
                CHECK(s.empty());
                ++misses;
            }
        }
        CHECK(hits > 500);
        CHECK(misses > 500);
    }
}

TEST_CASE("Cylinder::spans on grazing rays") {
    gRnd.seed(11);
    SECTION("axis-aligned: hit iff inside by one ulp") {
        const NodePtr cylinder = makeCylinder(Vec3(0, -1, 0), Vec3(0, 1, 0), 0.7);
        for (int k = 1; k <= 64; k *= 2) {
            for (int side : {-1, 1}) {
                double b = 0.7;
                for (int i = 0; i < k; ++i) b = std::nextafter(b, side * 2.0);
                CAPTURE(k, side);
                CHECK(kept(*cylinder, Ray{Vec3(-20, 0.3, b), Vec3(1, 0, -0.0)}).size() ==
                      (side < 0 ? 1u : 0u));
                // Parallel to the axis, at the same distance: inside only if not outside.
                CHECK(kept(*cylinder, Ray{Vec3(-0.0, -5, b), Vec3(0, 2, 0)}).size() ==
                      (side < 0 ? 1u : 0u));
            }
        }
        // On the surface line, parallel to the axis: the closed solid holds it.
        const std::vector<Span> s = kept(*cylinder, Ray{Vec3(0.7, -5, 0), Vec3(-0.0, 2, 0)});
        REQUIRE(s.size() == 1);
        CHECK(s[0].in.t == 2.0);
        CHECK(s[0].out.t == 3.0);
        CHECK(s[0].in.normal == Vec3(0, -1, 0));
        CHECK(s[0].out.normal == Vec3(0, 1, 0));
    }
    SECTION("oblique: hit iff the long-double line distance says so, beyond 8 ulps of it") {
        int hits = 0, misses = 0;
        for (int i = 0; i < 2000; ++i) {
            const Vec3 a(gRnd.uniform(-5, 5), gRnd.uniform(-5, 5), gRnd.uniform(-5, 5));
            const Vec3 u = gRnd.unitVector();
            const double len = std::exp(gRnd.uniform(-1, 1)), r = std::exp(gRnd.uniform(-2, 1));
            const Vec3 v = gRnd.perpendicular(u), w = glm::cross(u, v);
            const double k = std::exp(gRnd.uniform(0, std::log(1e4)));
            const double b = r * (1 + (i % 2 ? k : -k) * kUlp);
            const Ray ray{a + 0.5 * len * u + b * v - 10 * r * w,
                          w * std::exp(gRnd.uniform(-3, 3))};
            // Distance between the ray's line and the axis line, in long double.
            const LVec3 ua = ld(a + len * u) - ld(a);
            const LVec3 nrm = glm::cross(ld(ray.dir), ua);
            const LD dist = std::fabs(glm::dot(ld(ray.origin) - ld(a), nrm)) / glm::length(nrm);
            const LD margin = (dist - r) / r;
            const std::vector<Span> s = kept(*makeCylinder(a, a + len * u, r), ray);
            CAPTURE(i, double(margin / kUlp));
            if (margin < -8 * kUlp) {
                REQUIRE(s.size() == 1);
                ++hits;
            } else if (margin > 8 * kUlp) {
                CHECK(s.empty());
                ++misses;
            }
        }
        CHECK(hits > 500);
        CHECK(misses > 500);
    }
}

TEST_CASE("Cylinder::spans parallel to the caps") {
    const NodePtr cylinder = makeCylinder(Vec3(0, 0, 0), Vec3(0, 2, 0), 1.0);
    for (double y : {1.0, 2.0, 0.0}) {  // inside, and in each cap plane (closed: inside)
        for (const Vec3& d : {Vec3(1, 0, 0), Vec3(1, -0.0, -0.0)}) {
            const std::vector<Span> s = kept(*cylinder, Ray{Vec3(-5, y, 0), d});
            REQUIRE(s.size() == 1);
            CHECK(s[0].in.t == 4.0);
            CHECK(s[0].out.t == 6.0);
            CHECK(s[0].in.normal == Vec3(-1, 0, 0));
            CHECK(s[0].out.normal == Vec3(1, 0, 0));
        }
    }
    CHECK(kept(*cylinder, Ray{Vec3(-5, std::nextafter(2.0, 3.0), 0), Vec3(1, -0.0, 0)}).empty());
    CHECK(kept(*cylinder, Ray{Vec3(-5, -0x1p-1074, 0), Vec3(1, 0, 0)}).empty());
}
