// Open surfaces (csg/primitives/surfaces.h) against closed forms: disc, triangle, open cylinder,
// the boundary of a sphere, a clipped disc, and the back-side marks the interior modifier fills.
#include <catch2/catch.hpp>

#include "csg/primitives/surfaces.h"
#include "csg/tape/tree_tape.h"
#include "csg/tree/solids.h"

#include <cmath>
#include <random>

using namespace kerf;

namespace {

struct Crossing {
    bool found = false;
    Boundary b;
    bool entering = false;
};

Crossing first(const NodePtr& n, const Ray& ray, double tmin = 0.0, double tmax = kInf) {
    TraceContext ctx;
    Crossing c;
    c.found = n->firstSurface(ray, tmin, tmax, ctx, c.b, c.entering);
    return c;
}

/// The normal faces the ray (two-sided) and is parallel to `geometric`.
void checkFacesRay(const Crossing& c, const Ray& ray, const Vec3& geometric) {
    CHECK(glm::dot(c.b.normal, ray.dir) < 0.0);
    const Vec3 n = glm::normalize(c.b.normal), g = glm::normalize(geometric);
    CHECK(std::fabs(std::fabs(glm::dot(n, g)) - 1.0) < 1e-14);
}

}  // namespace

TEST_CASE("surfaces: a disc is hit from both sides where the plane meets the ring") {
    const Vec3 c(0.5, 1.0, -0.25), n(0.0, 2.0, 0.0);  // normal not unit: only its direction counts
    const double r = 1.5, inner = 0.5;
    const NodePtr disc = makeDisc(c, n, r, inner);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    int hits = 0, misses = 0;
    for (int i = 0; i < 2000; ++i) {
        const bool fromAbove = i % 2 == 0;
        const Vec3 o(u(rng), fromAbove ? 3.0 : -2.0, u(rng));
        const Vec3 target(c.x + u(rng), c.y, c.z + u(rng));
        const Ray ray{o, target - o};
        // Closed form: the plane y = 1 is at t = 1 (target lies on it); hit iff inner ≤ ρ ≤ r.
        const double rho = std::hypot(target.x - c.x, target.z - c.z);
        const Crossing got = first(disc, ray);
        if (rho > r * (1 + 1e-12) || rho < inner * (1 - 1e-12)) {
            CHECK_FALSE(got.found);
            ++misses;
            continue;
        }
        if (std::fabs(rho - r) < 1e-9 || std::fabs(rho - inner) < 1e-9) continue;  // the rim
        REQUIRE(got.found);
        ++hits;
        CHECK(got.entering);
        CHECK(std::fabs(got.b.t - 1.0) <= 4e-16 * 4);
        checkFacesRay(got, ray, n);
        // From below the ray meets the back: marked for interior until a material fills it.
        CHECK(got.b.material == (fromAbove ? Boundary::kNoMaterial : Boundary::kNoMaterialBack));
    }
    CHECK(hits > 500);
    CHECK(misses > 500);
}

TEST_CASE(
    "surfaces: a triangle is hit iff the barycentric coordinates are in range, from both sides") {
    const Vec3 a(0, 0, 0), b(2, 0, 0), c(0, 1, 1);
    const NodePtr tri = makeTriangle(a, b, c);
    const Vec3 geometric = glm::cross(b - a, c - a);
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-0.4, 1.4);
    int hits = 0, misses = 0;
    for (int i = 0; i < 2000; ++i) {
        // A point of the plane by its barycentric (s, t): p = a + s(b − a) + t(c − a).
        const double s = u(rng), t = u(rng);
        const Vec3 p = a + s * (b - a) + t * (c - a);
        const double side = i % 2 == 0 ? 1.0 : -1.0;
        const Vec3 o =
            p + side * 2.0 * glm::normalize(geometric) + Vec3(0.1 * u(rng), 0.2 * u(rng), 0.0);
        const Ray ray{o, p - o};
        const Crossing got = first(tri, ray);
        const double margin = 1e-9;
        const bool inside = s > margin && t > margin && s + t < 1 - margin;
        const bool outside = s < -margin || t < -margin || s + t > 1 + margin;
        if (outside) {
            CHECK_FALSE(got.found);
            ++misses;
        } else if (inside) {
            REQUIRE(got.found);
            ++hits;
            CHECK(got.entering);
            CHECK(std::fabs(got.b.t - 1.0) < 1e-14);
            checkFacesRay(got, ray, geometric);
            CHECK(got.b.material == (side > 0 ? Boundary::kNoMaterial : Boundary::kNoMaterialBack));
        }
    }
    CHECK(hits > 300);
    CHECK(misses > 300);
}

TEST_CASE("surfaces: an open cylinder seen through its open end is hit on the inside wall") {
    // Axis along z from 0 to 4, radius 1. A ray from the axis outside the end, slanting.
    const NodePtr tube = makeOpenCone(Vec3(0, 0, 0), Vec3(0, 0, 4), 1.0, 1.0);
    const Ray ray{Vec3(0, 0, -1), Vec3(0.25, 0, 1)};
    // x = 0.25 (z + 1) reaches 1 at z = 3: t = 4, inside the tube's length; the cap plane at
    // z = 0 (t = 1) is open, so nothing is met there.
    const Crossing got = first(tube, ray);
    REQUIRE(got.found);
    CHECK(got.entering);
    CHECK(std::fabs(got.b.t - 4.0) < 1e-14);
    // The wall is seen from inside: against its outward normal (1, 0, 0), so the back.
    CHECK(got.b.material == Boundary::kNoMaterialBack);
    checkFacesRay(got, ray, Vec3(1, 0, 0));
    CHECK(got.b.normal.x < 0.0);
    // Straight along the axis: no wall, no caps.
    CHECK_FALSE(first(tube, Ray{Vec3(0, 0, -1), Vec3(0, 0, 1)}).found);
    // From outside across the middle: both walls, the near one from the front.
    TraceContext ctx;
    SpanList s;
    tube->spans(Ray{Vec3(-3, 0, 2), Vec3(1, 0, 0)}, 0.0, kInf, ctx, s);
    REQUIRE(s.size() == 2);
    CHECK(s[0].in.t == 2.0);
    CHECK(s[1].in.t == 4.0);
    CHECK(s[0].in.material == Boundary::kNoMaterial);
    CHECK(s[1].in.material == Boundary::kNoMaterialBack);
}

TEST_CASE("surfaces: an open cone's side matches its closed form, without the caps") {
    // Radius 0.5 at z = 0 to 1.5 at z = 2 (slope 0.5). A ray along x at height z meets it at
    // x = ±(0.5 + 0.5 z).
    const NodePtr cone = makeOpenCone(Vec3(0, 0, 0), Vec3(0, 0, 2), 0.5, 1.5);
    for (double z : {0.25, 1.0, 1.75}) {
        const Crossing got = first(cone, Ray{Vec3(-5, 0, z), Vec3(1, 0, 0)});
        REQUIRE(got.found);
        CHECK(std::fabs(got.b.t - (5 - (0.5 + 0.5 * z))) < 1e-13);
        CHECK(got.b.material == Boundary::kNoMaterial);
    }
    // Past the ends: nothing (the capped cone would be met on its caps here).
    CHECK_FALSE(first(cone, Ray{Vec3(-5, 0, 2.1), Vec3(1, 0, 0)}).found);
    CHECK_FALSE(first(cone, Ray{Vec3(0.2, 0, -3), Vec3(0, 0, 1)}).found);
}

TEST_CASE("surfaces: surface sphere is crossed at the sphere's depth twice along a ray") {
    const Vec3 c(1, 2, 3);
    const double r = 0.75;
    const NodePtr sheet = makeSurfaceOf(makeSphere(c, r));
    const Ray ray{Vec3(1, 2, -2), Vec3(0, 0, 1)};  // through the centre: at z = 3 ∓ r
    const Crossing near = first(sheet, ray);
    REQUIRE(near.found);
    CHECK(near.entering);
    CHECK(near.b.t == 5.0 - r);
    CHECK(near.b.material == Boundary::kNoMaterial);
    CHECK(near.b.normal.z < 0.0);
    const Crossing far = first(sheet, ray, near.b.t);
    REQUIRE(far.found);
    CHECK(far.entering);  // a surface is met, never entered or left
    CHECK(far.b.t == 5.0 + r);
    CHECK(far.b.normal.z < 0.0);                         // turned to face the ray
    CHECK(far.b.material == Boundary::kNoMaterialBack);  // the inside of the sphere
    CHECK_FALSE(first(sheet, ray, far.b.t).found);
    // The spans list both crossings as zero-width spans.
    TraceContext ctx;
    SpanList s;
    sheet->spans(ray, 0.0, kInf, ctx, s);
    REQUIRE(s.size() == 2);
    CHECK(s[0].in.t == s[0].out.t);
    CHECK(s[1].in.t == 5.0 + r);
}

TEST_CASE("surfaces: clip of a disc by a box keeps the hits inside both") {
    // The unit disc in the plane y = 0, clipped by the box x ≤ 0.3 (and |z| ≤ 0.6).
    const NodePtr disc = makeDisc(Vec3(0.0), Vec3(0, 1, 0), 1.0);
    const NodePtr box = makeBox(Vec3(-2, -1, -0.6), Vec3(0.3, 1, 0.6));
    const NodePtr clipped = makeClip(disc, box);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-1.2, 1.2);
    int hits = 0, misses = 0;
    for (int i = 0; i < 3000; ++i) {
        const Vec3 target(u(rng), 0.0, u(rng));
        const Vec3 o = target + Vec3(0.3 * u(rng), i % 2 ? 2.0 : -2.0, 0.3 * u(rng));
        const Ray ray{o, target - o};
        const double rho = std::hypot(target.x, target.z);
        const double edge = std::min({std::fabs(rho - 1.0), std::fabs(target.x - 0.3),
                                      std::fabs(std::fabs(target.z) - 0.6)});
        if (edge < 1e-9) continue;
        const bool expected = rho < 1.0 && target.x < 0.3 && std::fabs(target.z) < 0.6;
        const Crossing got = first(clipped, ray);
        CHECK(got.found == expected);
        if (got.found) {
            CHECK(std::fabs(got.b.t - 1.0) < 1e-14);
            ++hits;
        } else {
            ++misses;
        }
        // The spans agree with the first surface.
        TraceContext ctx;
        SpanList s;
        clipped->spans(ray, 0.0, kInf, ctx, s);
        CHECK(s.size() == (expected ? 1 : 0));
    }
    CHECK(hits > 500);
    CHECK(misses > 500);
    // The clip's bounds are within both operands'.
    CHECK(clipped->bounds().hi.x <= 0.3);
}

TEST_CASE("surfaces: clip skips crossings outside the solid to find a later one inside") {
    // surface of a sphere of radius 1 clipped by the half-space z ≥ 0.5: along +z through the
    // centre the near crossing (z = −1) is outside, the far one (z = 1) inside.
    const NodePtr clipped =
        makeClip(makeSurfaceOf(makeSphere(Vec3(0.0), 1.0)), makeHalfSpace(Vec3(0, 0, -1), -0.5));
    const Crossing got = first(clipped, Ray{Vec3(0, 0, -3), Vec3(0, 0, 1)});
    REQUIRE(got.found);
    CHECK(got.b.t == 4.0);
    CHECK(got.b.material == Boundary::kNoMaterialBack);
}

TEST_CASE("surfaces: interior fills back sides and the boundaries where a ray leaves a solid") {
    constexpr int32_t kFront = 3, kBack = 5;
    // A disc seen from above and from below, under material(interior(disc)).
    const NodePtr disc =
        makeMaterial(makeInterior(makeDisc(Vec3(0.0), Vec3(0, 1, 0), 1.0), kBack), kFront);
    CHECK(first(disc, Ray{Vec3(0, 1, 0), Vec3(0, -1, 0)}).b.material == kFront);
    CHECK(first(disc, Ray{Vec3(0, -1, 0), Vec3(0, 1, 0)}).b.material == kBack);
    // A sphere: entering shows the material, leaving (a ray from inside) the interior.
    const NodePtr ball = makeMaterial(makeInterior(makeSphere(Vec3(0.0), 1.0), kBack), kFront);
    CHECK(first(ball, Ray{Vec3(0, 0, -3), Vec3(0, 0, 1)}).b.material == kFront);
    const Crossing inside = first(ball, Ray{Vec3(0.0), Vec3(0, 0, 1)});
    CHECK_FALSE(inside.entering);
    CHECK(inside.b.material == kBack);
    TraceContext ctx;
    SpanList s;
    ball->spans(Ray{Vec3(0, 0, -3), Vec3(0, 0, 1)}, 0.0, kInf, ctx, s);
    REQUIRE(s.size() == 1);
    CHECK(s[0].in.material == kFront);
    CHECK(s[0].out.material == kBack);
    // Without interior, a back side takes the material like any boundary.
    const NodePtr plain = makeMaterial(makeDisc(Vec3(0.0), Vec3(0, 1, 0), 1.0), kFront);
    CHECK(first(plain, Ray{Vec3(0, -1, 0), Vec3(0, 1, 0)}).b.material == kFront);
}

TEST_CASE("surfaces: isSurfaceTree sees through transforms, materials and interiors") {
    const NodePtr disc = makeDisc(Vec3(0.0), Vec3(0, 1, 0), 1.0);
    CHECK(isSurfaceTree(*makeMaterial(makeInterior(makeTransform(disc, Affine{}), 2), 1)));
    CHECK_FALSE(isSurfaceTree(*makeMaterial(makeSphere(Vec3(0.0), 1.0), 1)));
    CHECK(isSurfaceKind(NodeKind::Clip));
    CHECK_FALSE(isSurfaceKind(NodeKind::Interior));
    CHECK(isLeaf(NodeKind::Disc));
    CHECK_FALSE(isLeaf(NodeKind::SurfaceOf));
}

TEST_CASE(
    "surfaces: the tree's implicit form has no inside for a surface, and interior keeps its "
    "solid's") {
    // treeTape is what mesh export and slicing compile; `surface sphere` must not mesh as a ball.
    const auto sheet = treeTape(*makeSurfaceOf(makeSphere(Vec3(0.0), 1.0)));
    CHECK(sheet->eval(Vec3(0.0)) > 0.0);
    const auto ball = treeTape(*makeInterior(makeSphere(Vec3(0.0), 1.0), 2));
    CHECK(ball->eval(Vec3(0.0)) == -1.0);
    CHECK(ball->eval(Vec3(2.0, 0.0, 0.0)) == 1.0);
}
