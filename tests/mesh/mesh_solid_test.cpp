// A closed mesh as a solid: its spans, first surface, signed distance and interval enclosure
// against the analytic sphere it approximates (the mesh lies between two concentric spheres,
// the oracle's bounds), and an open mesh as a two-sided surface.
#include "csg/tape/tape.h"
#include "csg/tape/tree_tape.h"
#include "csg/tree/solids.h"
#include "mesh/mesh_shape.h"
#include "tests/mesh/geodesic_sphere.h"
#include "tests/mesh/mesh_files.h"

#include <catch2/catch.hpp>

#include <random>

using namespace kerf;
using namespace kerf::test;

namespace {

const Vec3 kCenter(0.25, -0.5, 1.0);
constexpr double kRadius = 2.0;

std::shared_ptr<const MeshShape> sphereShape(int levels = 4) {
    return std::make_shared<const MeshShape>(geodesicSphere(kCenter, kRadius, levels));
}

/// Where a ray enters and leaves the sphere of radius r around kCenter (false if it misses).
bool sphereCrossings(const Ray& ray, double r, double& t0, double& t1) {
    const Vec3 oc = ray.origin - kCenter;
    const double a = glm::dot(ray.dir, ray.dir), b = glm::dot(oc, ray.dir);
    const double c = glm::dot(oc, oc) - r * r, disc = b * b - a * c;
    if (disc < 0.0) return false;
    t0 = (-b - std::sqrt(disc)) / a;
    t1 = (-b + std::sqrt(disc)) / a;
    return true;
}

/// A ray from well outside towards a point within 0.7 R of the centre.
Ray randomRay(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Vec3 d;
    do d = Vec3(u(rng), u(rng), u(rng));
    while (glm::length(d) < 0.1 || glm::length(d) > 1.0);
    Vec3 aim;
    do aim = Vec3(u(rng), u(rng), u(rng));
    while (glm::length(aim) > 1.0);
    const Vec3 target = kCenter + 0.7 * kRadius * aim;
    return Ray{target - 3.0 * kRadius * glm::normalize(d) * (1.0 + u(rng) * 0.2), d};
}

}  // namespace

TEST_CASE("meshNode::spans of a geodesic sphere lie between its inner and outer spheres") {
    const auto shape = sphereShape();
    REQUIRE(shape->isSolid());
    const double inner = innerRadius(shape->mesh(), kCenter);
    REQUIRE(inner < kRadius);
    REQUIRE(inner > 0.99 * kRadius);
    const NodePtr mesh = meshNode(shape, true);
    std::mt19937_64 rng(7);
    TraceContext ctx;
    SpanList spans;
    for (int i = 0; i < 2000; ++i) {
        const Ray ray = randomRay(rng);
        mesh->spans(ray, 0.0, kInf, ctx, spans);
        double o0, o1, i0, i1;
        REQUIRE(sphereCrossings(ray, kRadius, o0, o1));
        REQUIRE(sphereCrossings(ray, inner, i0, i1));
        REQUIRE(spans.size() == 1);
        // Entering the mesh happens after entering the outer sphere and before the inner one.
        CHECK(spans[0].in.t >= o0 * (1 - 1e-12));
        CHECK(spans[0].in.t <= i0 * (1 + 1e-12));
        CHECK(spans[0].out.t >= i1 * (1 - 1e-12));
        CHECK(spans[0].out.t <= o1 * (1 + 1e-12));
        // Normals point outward.
        CHECK(glm::dot(spans[0].in.normal, ray.dir) < 0.0);
        CHECK(glm::dot(spans[0].out.normal, ray.dir) > 0.0);
        // The first surface is the span's entry, found by the closest-hit walk.
        Boundary hit;
        bool entering = false;
        REQUIRE(mesh->firstSurface(ray, 0.0, kInf, ctx, hit, entering));
        CHECK(entering);
        CHECK(hit.t == spans[0].in.t);
        // From inside the sphere's core, the ray starts inside: the span is open at the start
        // and the first surface is the exit.
        const double mid = 0.5 * (i0 + i1);
        mesh->spans(ray, mid, kInf, ctx, spans);
        REQUIRE(spans.size() == 1);
        CHECK(spans[0].in.t < mid);
        REQUIRE(mesh->firstSurface(ray, mid, kInf, ctx, hit, entering));
        CHECK_FALSE(entering);
        CHECK(hit.t == spans[0].out.t);
    }
    CHECK(ctx.stats.meshNodes > 0);
    CHECK(ctx.stats.triangleTests > 0);
}

TEST_CASE("meshNode::rays through the vertices and edges of an octahedron enter once") {
    // Axis rays through two opposite vertices, and rays through edge midpoints: every
    // coordinate is exact, so the crossings are at known t.
    const auto shape = std::make_shared<const MeshShape>(octahedronMesh());
    REQUIRE(shape->isSolid());
    const NodePtr mesh = meshNode(shape, false);
    TraceContext ctx;
    SpanList spans;
    const double r = kOctaRadius;
    const Vec3 c = kOctaCenter;
    for (int axis = 0; axis < 3; ++axis)
        for (double s : {1.0, -1.0}) {
            Vec3 d(0.0);
            d[axis] = s;
            const Ray ray{c - 4.0 * d, d};
            mesh->spans(ray, 0.0, kInf, ctx, spans);
            REQUIRE(spans.size() == 1);
            CHECK(spans[0].in.t == 4.0 - r);
            CHECK(spans[0].out.t == 4.0 + r);
        }
    // Through the midpoint of the edge from +x to +y, along the edge's outward normal.
    const Vec3 mid = c + Vec3(r / 2, r / 2, 0.0);
    const Vec3 d = glm::normalize(Vec3(-1.0, -1.0, 0.0));
    mesh->spans(Ray{mid - 3.0 * d, d}, 0.0, kInf, ctx, spans);
    REQUIRE(spans.size() == 1);
    CHECK(spans[0].in.t == Approx(3.0).epsilon(1e-14));
}

TEST_CASE("MeshShape::signed distance matches the sphere's within the tessellation") {
    const auto shape = sphereShape();
    const double inner = innerRadius(shape->mesh(), kCenter);
    const double sag = kRadius - inner;
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    for (int i = 0; i < 3000; ++i) {
        const Vec3 p = kCenter + kRadius * Vec3(u(rng), u(rng), u(rng));
        const double exact = glm::length(p - kCenter) - kRadius;
        const double v = shape->value(p);
        CHECK(v >= exact - 1e-12);
        CHECK(v <= exact + sag + 1e-12);
        if (std::fabs(exact) > sag) CHECK((v < 0.0) == (exact < 0.0));
        Vec3 g;
        CHECK(shape->valueGradient(p, g) == v);
        if (std::fabs(exact) > 0.1) CHECK(glm::length(g) == Approx(1.0).epsilon(1e-12));
    }
}

TEST_CASE("MeshShape::range encloses the signed distance over boxes") {
    const auto shape = sphereShape(3);
    const NodePtr mesh = meshNode(shape, true);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-1.5, 1.5), w(0.0, 1.0);
    int decided = 0;
    for (int i = 0; i < 300; ++i) {
        const Vec3 lo = kCenter + kRadius * Vec3(u(rng), u(rng), u(rng));
        const Vec3 size = kRadius * std::pow(w(rng), 2.0) * Vec3(w(rng), w(rng), w(rng));
        const Vec3 hi = lo + size;
        const Interval r =
            mesh->valueInterval({Interval(lo.x, hi.x), Interval(lo.y, hi.y), Interval(lo.z, hi.z)});
        if (r.classify() != Classification::Ambiguous) ++decided;
        for (int k = 0; k < 20; ++k) {
            const Vec3 p = lo + Vec3(w(rng), w(rng), w(rng)) * size;
            const double v = shape->value(p);
            CHECK(r.lo <= v);
            CHECK(v <= r.hi);
        }
    }
    CHECK(decided > 100);  // most boxes away from the surface are decided
}

TEST_CASE("meshNode::CSG with a mesh agrees with the same CSG of the analytic sphere") {
    const auto shape = sphereShape();
    const double inner = innerRadius(shape->mesh(), kCenter);
    const double sag = kRadius - inner;
    const NodePtr cut = makeBox(kCenter + Vec3(-3.0, 0.3, -3.0), kCenter + Vec3(3.0, 3.0, 3.0));
    const NodePtr meshed = makeBoolean(BoolOp::Difference, {meshNode(shape, true), cut});
    const NodePtr exact = makeBoolean(BoolOp::Difference, {makeSphere(kCenter, kRadius), cut});
    std::mt19937_64 rng(5);
    TraceContext ctx;
    SpanList a, b;
    int compared = 0;
    for (int i = 0; i < 2000; ++i) {
        const Ray ray = randomRay(rng);
        meshed->spans(ray, 0.0, kInf, ctx, a);
        exact->spans(ray, 0.0, kInf, ctx, b);
        if (a.size() != b.size() || a.empty()) continue;  // rays near the cut's rim may differ
        ++compared;
        for (int k = 0; k < a.size(); ++k) {
            // Along a unit direction the depth moves by at most the sagitta over the cosine of
            // incidence; the box faces are shared exactly.
            const double len = glm::length(ray.dir);
            CHECK(std::fabs(a[k].in.t - b[k].in.t) * len <= 20.0 * sag);
            CHECK(std::fabs(a[k].out.t - b[k].out.t) * len <= 20.0 * sag);
        }
    }
    CHECK(compared > 1500);
}

TEST_CASE("meshNode::an open mesh is a two-sided surface") {
    TriangleMesh m = octahedronMesh();
    m.triangles.pop_back();  // a hole: boundary edges
    const auto shape = std::make_shared<const MeshShape>(std::move(m));
    REQUIRE_FALSE(shape->isSolid());
    REQUIRE(shape->report().boundaryEdges == 3);
    const NodePtr mesh = meshNode(shape, false);
    TraceContext ctx;
    const Vec3 c = kOctaCenter;
    for (double s : {1.0, -1.0}) {
        const Vec3 d(0.0, 0.0, s);
        Boundary hit;
        bool entering = false;
        const Ray ray{c - 4.0 * d + Vec3(0.1, 0.05, 0.0), d};
        REQUIRE(mesh->firstSurface(ray, 0.0, kInf, ctx, hit, entering));
        CHECK(entering);
        CHECK(glm::dot(hit.normal, d) < 0.0);  // faces the ray from either side
        // Behind the first face, the second is met too, still facing the ray.
        REQUIRE(mesh->firstSurface(ray, hit.t, kInf, ctx, hit, entering));
        CHECK(glm::dot(hit.normal, d) < 0.0);
    }
    // Its field is the unsigned distance: never negative.
    CHECK(shape->value(c) > 0.0);
}

TEST_CASE("meshNode::the tree's tape calls the mesh's field") {
    const auto shape = sphereShape(2);
    const NodePtr tree = makeTransform(meshNode(shape, true), Affine::translate(Vec3(1, 2, 3)));
    const auto tape = treeTape(*tree);
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> u(-4.0, 4.0);
    for (int i = 0; i < 200; ++i) {
        const Vec3 p = Vec3(1, 2, 3) + kCenter + Vec3(u(rng), u(rng), u(rng));
        CHECK(tape->eval(p) == tree->value(p));
    }
}

TEST_CASE("meshNode::hard cases: -0 directions, huge and tiny scales, grazing rays") {
    TraceContext ctx;
    SpanList spans;
    // Directions with negative zeros through the octahedron's vertices: the same exact depths.
    const auto octa = std::make_shared<const MeshShape>(octahedronMesh());
    const NodePtr o = meshNode(octa, false);
    for (const Vec3& d : {Vec3(-0.0, -0.0, 1.0), Vec3(0.0, -0.0, -1.0), Vec3(-1.0, -0.0, 0.0)}) {
        o->spans(Ray{kOctaCenter - 2.0 * d, d}, 0.0, kInf, ctx, spans);
        REQUIRE(spans.size() == 1);
        CHECK(spans[0].in.t == 2.0 - kOctaRadius);
        CHECK(spans[0].out.t == 2.0 + kOctaRadius);
    }
    // The geodesic sphere at 1e-7 and 1e7: the relative bounds of the first test hold.
    for (double scale : {1e-7, 1e7}) {
        const TriangleMesh m = geodesicSphere(kCenter * scale, kRadius * scale, 3);
        const double inner = innerRadius(m, kCenter * scale);
        const NodePtr mesh = meshNode(std::make_shared<const MeshShape>(m), true);
        std::mt19937_64 rng(17);
        for (int i = 0; i < 300; ++i) {
            Ray ray = randomRay(rng);
            ray.origin *= scale;
            mesh->spans(ray, 0.0, kInf, ctx, spans);
            REQUIRE(spans.size() == 1);
            const Vec3 oc = ray.origin - kCenter * scale;
            const double a = glm::dot(ray.dir, ray.dir), b = glm::dot(oc, ray.dir);
            const double outer0 =
                (-b - std::sqrt(b * b - a * (glm::dot(oc, oc) - std::pow(kRadius * scale, 2)))) / a;
            const double inner0 =
                (-b - std::sqrt(b * b - a * (glm::dot(oc, oc) - inner * inner))) / a;
            CHECK(spans[0].in.t >= outer0 * (1 - 1e-11));
            CHECK(spans[0].in.t <= inner0 * (1 + 1e-11));
        }
    }
    // Rays grazing the octahedron's faces (in a face's plane) and along an edge: a ray in a
    // face's plane meets the solid at most at the face's edges, never in a span of positive
    // length outside the solid; a ray along the z axis line through two vertices still enters
    // exactly once.
    const Vec3 c = kOctaCenter;
    const double r = kOctaRadius;
    // The face (+x, +y, +z) lies in the plane x + y + z = r around c; a ray in that plane
    // outside the face (through the edge's line beyond it) must miss.
    const Vec3 inPlane = glm::normalize(Vec3(1.0, -1.0, 0.0));
    o->spans(Ray{c + Vec3(r, 0.0, 0.0) + Vec3(0.0, 0.0, 0.0) - 3.0 * inPlane + Vec3(0.0, 0.0, 0.0),
                 inPlane},
             0.0, kInf, ctx, spans);
    for (const Span& s : spans) CHECK(s.out.t - s.in.t <= 1e-12);
}

TEST_CASE("meshNode::anySurface answers as firstSurface does, through transforms") {
    const auto shape = sphereShape(3);
    const NodePtr tree = makeMaterial(
        makeTransform(meshNode(shape, true), Affine::rotateDegrees(Vec3(10, 20, 30))), 1);
    std::mt19937_64 rng(23);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    TraceContext ctx;
    int blocked = 0;
    for (int i = 0; i < 3000; ++i) {
        const Ray ray = randomRay(rng);
        const double tmin = 6.0 * u(rng), tmax = tmin + 4.0 * u(rng);
        Boundary hit;
        bool entering = false;
        const bool first = tree->firstSurface(ray, tmin, tmax, ctx, hit, entering);
        CHECK(tree->anySurface(ray, tmin, tmax, ctx) == first);
        blocked += first;
    }
    CHECK(blocked > 500);
    CHECK(blocked < 2500);
}
