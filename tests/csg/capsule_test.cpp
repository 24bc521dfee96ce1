// The capsule's closed-form spans against a long-double oracle written independently here (the
// naive quadratics of the two end spheres and the body, in long double), over thousands of
// random rays including grazing ones, rays along the axis and directions with −0 components;
// its normals against the long-double gradient of the distance; its bounds against points of
// its surface; and the interval method (root isolation of its implicit form) against the
// closed form.
#include "csg/primitives/primitive.h"
#include "csg/tree/kind_registry.h"
#include "csg/tree/solids.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace kerf;

namespace {

using LD = long double;

/// The capsule's span along a ray in long double, or none.
struct OracleSpan {
    bool hit = false;
    LD tin = 0, tout = 0;
};

/// Adds the roots of |o + t·d − c|² = r² (sphere) to the span.
void sphereRoots(const LVec3& o, const LVec3& d, const LVec3& c, LD r, OracleSpan& s) {
    const LVec3 g = o - c;
    const LD a = glm::dot(d, d), h = glm::dot(g, d), cc = glm::dot(g, g) - r * r;
    const LD disc = h * h - a * cc;
    if (disc < 0) return;
    const LD t0 = (-h - std::sqrt(disc)) / a, t1 = (-h + std::sqrt(disc)) / a;
    s.tin = s.hit ? std::min(s.tin, t0) : t0;
    s.tout = s.hit ? std::max(s.tout, t1) : t1;
    s.hit = true;
}

OracleSpan oracle(const Vec3& a, const Vec3& b, double r, const Ray& ray) {
    const LVec3 la(a), lb(b), o(ray.origin), d(ray.dir);
    OracleSpan s;
    sphereRoots(o, d, la, r, s);
    sphereRoots(o, d, lb, r, s);
    const LVec3 u = (lb - la) / std::sqrt(glm::dot(lb - la, lb - la));
    const LD length = std::sqrt(glm::dot(lb - la, lb - la));
    const LVec3 g = o - la;
    const LVec3 gp = g - glm::dot(g, u) * u, dp = d - glm::dot(d, u) * u;  // across the axis
    const LD qa = glm::dot(dp, dp), qh = glm::dot(gp, dp), qc = glm::dot(gp, gp) - LD(r) * r;
    const LD disc = qh * qh - qa * qc;
    if (qa > 0 && disc >= 0) {
        for (const LD t : {(-qh - std::sqrt(disc)) / qa, (-qh + std::sqrt(disc)) / qa}) {
            const LD z = glm::dot(g + t * d, u);
            if (z < 0 || z > length) continue;
            s.tin = s.hit ? std::min(s.tin, t) : t;
            s.tout = s.hit ? std::max(s.tout, t) : t;
            s.hit = true;
        }
    }
    return s;
}

/// The outward unit normal of the capsule at p: from the segment's nearest point.
LVec3 oracleNormal(const Vec3& a, const Vec3& b, const LVec3& p) {
    const LVec3 la(a), ab = LVec3(b) - la;
    const LD s = std::clamp(glm::dot(p - la, ab) / glm::dot(ab, ab), LD(0), LD(1));
    const LVec3 n = p - (la + s * ab);
    return n / std::sqrt(glm::dot(n, n));
}

Vec3 randomUnit(std::mt19937_64& rng) {
    std::normal_distribution<double> n;
    for (;;) {
        const Vec3 v(n(rng), n(rng), n(rng));
        if (glm::length(v) > 1e-3) return glm::normalize(v);
    }
}

/// A ray from a random origin outside towards a point near the capsule's surface; every
/// fourth one grazes (aimed at a surface point along a tangent).
Ray randomRay(std::mt19937_64& rng, const Vec3& a, const Vec3& b, double r, int i) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const Vec3 onAxis = a + u(rng) * (b - a);
    const Vec3 surface = onAxis + r * randomUnit(rng);
    Ray ray;
    if (i % 4 == 0) {  // grazing: a tangent of the end sphere or body at a surface point
        const Vec3 n = glm::normalize(surface - onAxis);
        const Vec3 t = glm::normalize(glm::cross(n, randomUnit(rng)));
        ray.origin = surface - 4.0 * t;
        ray.dir = t;
    } else {
        ray.origin = onAxis + 4.0 * randomUnit(rng);
        ray.dir = surface + 0.3 * r * randomUnit(rng) - ray.origin;
    }
    return ray;
}

struct Checked {
    int hits = 0, grazing = 0;
};

/// One ray: our span against the oracle (and our normals against the oracle's).
void checkRay(const Node& capsule, const Vec3& a, const Vec3& b, double r, const Ray& ray,
              Checked& counts) {
    TraceContext ctx;
    SpanList spans;
    capsule.spans(ray, -kInf, kInf, ctx, spans);
    const OracleSpan o = oracle(a, b, r, ray);
    const LD scale = std::sqrt(glm::dot(ray.dir, ray.dir));
    const LD width = o.hit ? (o.tout - o.tin) * scale : 0;
    INFO("ray " << ray.origin.x << " " << ray.origin.y << " " << ray.origin.z << " dir "
                << ray.dir.x << " " << ray.dir.y << " " << ray.dir.z);
    REQUIRE(spans.size() <= 1);
    if (width < 1e-4 * r) {  // grazing: only a thin span, if any, on either side
        ++counts.grazing;
        if (spans.size() == 1) CHECK((spans[0].out.t - spans[0].in.t) * scale < 1e-3 * r);
        return;
    }
    REQUIRE(spans.size() == 1);
    ++counts.hits;
    const Span& s = spans[0];
    const LD tol = 1e-9L * (std::fabs(o.tin) + std::fabs(o.tout) + 1);
    CHECK(std::fabs(s.in.t - o.tin) <= tol);
    CHECK(std::fabs(s.out.t - o.tout) <= tol);
    for (const Boundary* bd : {&s.in, &s.out}) {
        const LVec3 p = LVec3(ray.origin) + LD(bd->t) * LVec3(ray.dir);
        const LVec3 n = LVec3(glm::normalize(bd->normal));
        CHECK(glm::length(n - oracleNormal(a, b, p)) < 1e-6L);
    }
}

}  // namespace

TEST_CASE("Capsule::spans against a long-double oracle") {
    std::mt19937_64 rng(20261201);
    std::uniform_real_distribution<double> u(-1.0, 1.0), ur(0.05, 0.8);
    Checked counts;
    for (int c = 0; c < 40; ++c) {
        const Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
        const double r = ur(rng);
        const NodePtr capsule = makeCapsule(a, b, r);
        for (int i = 0; i < 200; ++i)
            checkRay(*capsule, a, b, r, randomRay(rng, a, b, r, i), counts);
    }
    CHECK(counts.hits > 4000);
    CHECK(counts.grazing > 100);
}

TEST_CASE("Capsule::spans along the axis and with -0 directions") {
    const Vec3 a(0.0, 0.0, -1.0), b(0.0, 0.0, 2.0);
    const NodePtr capsule = makeCapsule(a, b, 0.5);
    Checked counts;
    for (const double sx : {0.0, -0.0})
        for (const double sy : {0.0, -0.0})
            for (const double dz : {1.0, -1.0})
                for (const double x : {0.0, 0.3, -0.45, 0.5000001, 0.7}) {
                    Ray ray;
                    ray.origin = Vec3(x, 0.1, -5.0 * dz);
                    ray.dir = Vec3(sx, sy, dz);
                    checkRay(*capsule, a, b, 0.5, ray, counts);
                    const LD reach = std::sqrt(0.25L - LD(x) * x - 0.01L);
                    if (x * x + 0.01 < 0.25) {  // the ends are on the end spheres
                        TraceContext ctx;
                        SpanList s;
                        capsule->spans(ray, -kInf, kInf, ctx, s);
                        REQUIRE(s.size() == 1);
                        const LD lo = 5.0L + (dz > 0 ? -1 : -2) - reach;
                        CHECK(std::fabs(s[0].in.t - lo) < 1e-12);
                    }
                }
    CHECK(counts.hits == 24);
}

TEST_CASE("Capsule::bounds hold its surface") {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-10.0, 10.0), s01(0.0, 1.0);
    for (int c = 0; c < 200; ++c) {
        const Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
        const double r = 0.01 + s01(rng) * 3.0;
        const NodePtr capsule = makeCapsule(a, b, r);
        const Bounds3 box = capsule->bounds();
        for (int i = 0; i < 50; ++i) {
            const Vec3 p = a + s01(rng) * (b - a) + r * randomUnit(rng);
            for (int k = 0; k < 3; ++k) {
                CHECK(box.lo[k] <= p[k]);
                CHECK(p[k] <= box.hi[k]);
            }
        }
        // Tight: each face is touched by an end sphere, within rounding.
        for (int k = 0; k < 3; ++k)
            CHECK(box.lo[k] >= std::min(a[k], b[k]) - r - 1e-12 * (std::fabs(a[k]) + 10));
    }
}

TEST_CASE("Capsule: the interval method finds the closed form's first hit") {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0), ur(0.1, 0.6);
    int compared = 0;
    for (int c = 0; c < 10; ++c) {
        const Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
        const double r = ur(rng);
        const NodePtr capsule = makeCapsule(a, b, r);
        for (int i = 1; i < 60; ++i) {
            if (i % 4 == 0) continue;  // grazing rays: a tangency either method may drop
            const Ray ray = randomRay(rng, a, b, r, i);
            TraceContext closed, interval;
            interval.method = TraceMethod::Interval;
            Boundary hc, hi;
            bool ec = false, ei = false;
            const bool fc = capsule->firstSurface(ray, 0.0, kInf, closed, hc, ec);
            const bool fi = capsule->firstSurface(ray, 0.0, kInf, interval, hi, ei);
            const OracleSpan o = oracle(a, b, r, ray);
            if (!o.hit || (o.tout - o.tin) * glm::length(ray.dir) < 1e-3 * r) continue;
            REQUIRE(fc);
            REQUIRE(fi);
            CHECK(std::fabs(hc.t - hi.t) <= 1e-6 * (1 + std::fabs(hc.t)));
            CHECK(ec == ei);
            ++compared;
        }
    }
    CHECK(compared > 300);
}

TEST_CASE("Capsule: the registry rows and params") {
    const NodePtr capsule = makeCapsule(Vec3(1, 2, 3), Vec3(4, 5, 6), 0.5);
    CHECK(capsule->kind() == NodeKind::Capsule);
    CHECK(std::string(nodeKindName(NodeKind::Capsule)) == "capsule");
    const KindTraits& t = kindTraits(NodeKind::Capsule);
    CHECK(t.leaf);
    CHECK_FALSE(t.rootFound);
    CHECK(t.csgOperand);
    const auto p = std::get<CapsuleParams>(capsule->params());
    CHECK(p.a == Vec3(1, 2, 3));
    CHECK(p.b == Vec3(4, 5, 6));
    CHECK(p.radius == 0.5);
    // The value is the distance to the segment minus r, from the derived evaluation.
    CHECK(capsule->value(Vec3(1, 2, 3)) == Approx(-0.5).margin(1e-15));
    CHECK(capsule->value(Vec3(1, 2, 1)) == Approx(1.5).margin(1e-15));
    CHECK(capsule->valueExtended(LVec3(4, 5, 8)) == Approx(1.5L).margin(1e-15));
}
