// Level sets read from .vdb files as solids, against closed forms: hits on a sphere and a torus
// lie within the trilinear interpolation error of the exact surface; rays that meet the surface
// shrunk by a voxel always hit (grazing rays included); a ray touching the interpolant's zero
// set (a double root) hits; CSG with a box; the implicit form's range holds its values; every
// error of a file that cannot be a solid.
#include "volume/grids/level_set_node.h"
#include "volume/grids/vdb_level_set.h"

#include "csg/tree/solids.h"
#include "util/level_set_files.h"
#include "util/scratch_folder.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <random>

using namespace kerf;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// The first surface along the ray, or false.
bool firstHit(const NodePtr& solid, const Ray& ray, double& t, Vec3& normal, bool& entering) {
    TraceContext ctx;
    Boundary hit;
    if (!solid->firstSurface(ray, 0.0, kInf, ctx, hit, entering)) return false;
    t = hit.t;
    normal = hit.normal;
    return true;
}

/// A ray from a random point on a sphere of radius `from` round c towards a point at distance
/// `impact` from c (perpendicular to the ray).
Ray rayPast(std::mt19937_64& rng, const Vec3& c, double from, double impact) {
    std::normal_distribution<double> n;
    Vec3 dir = glm::normalize(Vec3(n(rng), n(rng), n(rng)));
    Vec3 side = glm::cross(dir, Vec3(n(rng), n(rng), n(rng)));
    side = glm::normalize(side);
    const Vec3 target = c + impact * side;
    return {target - from * dir, dir};
}

}  // namespace

TEST_CASE("LevelSet/sphere depth within the trilinear error", "[volume]") {
    test::ScratchFolder dir;
    const double radius = 2.0, voxel = 0.1;
    const Vec3 center(0.3f, -0.2f, 0.1f);  // as floats were written
    test::writeGrids(dir.file("s.vdb"), {test::sphereGrid(radius, center, voxel)});
    const auto grid = loadLevelSet(dir.file("s.vdb"));
    CHECK(grid->info().gridName == "sphere");
    CHECK(grid->info().voxelSize.x == Approx(voxel));
    const NodePtr solid = levelSetSolid(grid);
    // Trilinear interpolation of d = |p − c| − R errs by at most (h²/8)·Σ|∂²d/∂xᵢ²| ≤ h²/(4ρ)
    // (the Hessian's trace is 2/ρ at distance ρ ≥ R − 2h from c in the cells the surface
    // crosses), plus the samples' float rounding: the zero set lies within that of the sphere.
    const double bound = voxel * voxel / (4 * (radius - 2 * voxel)) + 1e-5 * voxel;
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> impact(0.0, radius - voxel);
    double worst = 0.0;
    for (int i = 0; i < 3000; ++i) {
        const Ray ray = rayPast(rng, center, 6.0, impact(rng));
        double t;
        Vec3 normal;
        bool entering;
        REQUIRE(firstHit(solid, ray, t, normal, entering));
        CHECK(entering);
        const Vec3 p = ray.at(t);
        const double err = std::fabs(glm::length(p - center) - radius);
        worst = std::max(worst, err);
        REQUIRE(err <= bound);
        // The normal is the gradient's direction: close to the radial one.
        CHECK(glm::dot(glm::normalize(normal), glm::normalize(p - center)) > 0.999);
    }
    INFO("worst distance from the sphere " << worst / voxel << " voxel; bound " << bound / voxel);
    CHECK(worst > 0.0);
}

TEST_CASE("LevelSet/the grid's own transform places it (rotation, translation)", "[volume]") {
    test::ScratchFolder dir;
    const double radius = 1.0, voxel = 0.05;
    auto g = test::sphereGrid(radius, Vec3(0.5, 0.0, 0.0), voxel);
    // World = index·h, then turned 90° about z (x → y), then moved by (0, 0, 2).
    g.turnZ = kPi / 2;
    g.move = Vec3(0.0, 0.0, 2.0);
    test::writeGrids(dir.file("moved.vdb"), {g});
    const NodePtr solid = levelSetSolid(loadLevelSet(dir.file("moved.vdb")));
    const Vec3 center(0.0, 0.5, 2.0);
    const double bound = voxel * voxel / (4 * (radius - 2 * voxel)) + 1e-5 * voxel;
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> impact(0.0, radius - voxel);
    for (int i = 0; i < 500; ++i) {
        const Ray ray = rayPast(rng, center, 5.0, impact(rng));
        double t;
        Vec3 normal;
        bool entering;
        REQUIRE(firstHit(solid, ray, t, normal, entering));
        const Vec3 p = ray.at(t);
        REQUIRE(std::fabs(glm::length(p - center) - radius) <= bound + 1e-9);
        CHECK(glm::dot(glm::normalize(normal), glm::normalize(p - center)) > 0.999);
    }
}

TEST_CASE("LevelSet/grazing rays on a sphere hit where the sphere shrunk by a voxel is hit",
          "[volume]") {
    test::ScratchFolder dir;
    const double radius = 1.5, voxel = 0.05;
    test::writeGrids(dir.file("s.vdb"), {test::sphereGrid(radius, Vec3(0.0), voxel)});
    const NodePtr solid = levelSetSolid(loadLevelSet(dir.file("s.vdb")));
    std::mt19937_64 rng(11);
    // Impact parameters in the last voxel before the shrunk sphere's silhouette must hit;
    // those a voxel beyond the sphere must miss (the interpolant errs by far less than that).
    std::uniform_real_distribution<double> inner(radius - 2 * voxel, radius - voxel);
    std::uniform_real_distribution<double> outer(radius + voxel, radius + 2 * voxel);
    int misses = 0, falseHits = 0;
    for (int i = 0; i < 4000; ++i) {
        double t;
        Vec3 n;
        bool e;
        if (!firstHit(solid, rayPast(rng, Vec3(0.0), 5.0, inner(rng)), t, n, e)) ++misses;
        if (firstHit(solid, rayPast(rng, Vec3(0.0), 5.0, outer(rng)), t, n, e)) ++falseHits;
    }
    CHECK(misses == 0);
    CHECK(falseHits == 0);
}

TEST_CASE("LevelSet/torus hits and grazing rays against the analytic torus", "[volume]") {
    test::ScratchFolder dir;
    const double R = 1.0, r = 0.35, voxel = 0.025;
    test::writeGrids(dir.file("t.vdb"), {test::torusGrid(R, r, voxel)});
    const auto grid = loadLevelSet(dir.file("t.vdb"));
    const NodePtr solid = levelSetSolid(grid);
    const NodePtr shrunk = makeTorus(R, r - voxel);  // kerf's closed-form torus as the oracle
    // The torus distance's Hessian has eigenvalues of magnitude ≤ max(1/q, 1/ρ) (q from the
    // tube's core circle ≥ r − 2h, ρ from the axis ≥ R − r − 2h): the trilinear error is
    // at most (3h²/8)·max(1/q, 1/ρ), plus the samples' float rounding.
    const double bound =
        3 * voxel * voxel / 8 * std::max(1 / (r - 2 * voxel), 1 / (R - r - 2 * voxel)) +
        1e-5 * voxel;
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int shrunkHits = 0, misses = 0;
    double worst = 0.0;
    for (int i = 0; i < 20000; ++i) {
        // Rays from a sphere of radius 4 towards random points near the torus (many graze it).
        const Vec3 from = 4.0 * glm::normalize(Vec3(u(rng), u(rng), u(rng)));
        const Vec3 to(1.4 * u(rng), 0.4 * u(rng), 1.4 * u(rng));
        const Ray ray{from, glm::normalize(to - from)};
        double t, ts;
        Vec3 n;
        bool e;
        const bool hit = firstHit(solid, ray, t, n, e);
        if (hit) {
            const Vec3 p = ray.at(t);
            const double err = std::fabs(test::torusDistance(R, r, p.x, p.y, p.z));
            worst = std::max(worst, err);
            REQUIRE(err <= bound);
        }
        if (firstHit(shrunk, ray, ts, n, e)) {
            ++shrunkHits;
            if (!hit) ++misses;
        }
    }
    INFO("worst distance from the torus " << worst / voxel << " voxel; bound " << bound / voxel);
    CHECK(shrunkHits > 5000);
    CHECK(misses == 0);
}

TEST_CASE("LevelSet/a ray touching the zero set (a double root) hits", "[volume]") {
    // One cell whose corners make the interpolant (u − ½)² along the diagonal u = v (constant
    // in z): 0.25 at (0,0) and (1,1), −0.25 at (1,0) and (0,1); the background (1) elsewhere.
    test::ScratchFolder dir;
    test::Grid g;
    g.name = "saddle";
    g.background = 1.f;
    for (int z = 0; z <= 1; ++z) {
        g.values.push_back({{0, 0, z}, 0.25f});
        g.values.push_back({{1, 1, z}, 0.25f});
        g.values.push_back({{1, 0, z}, -0.25f});
        g.values.push_back({{0, 1, z}, -0.25f});
    }
    test::writeGrids(dir.file("saddle.vdb"), {g});
    const auto grid = loadLevelSet(dir.file("saddle.vdb"));
    const NodePtr leaf = levelSetLeaf(grid);  // index space = world space here
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> u(0.1, 3.0), z(0.05, 0.95);
    std::vector<LevelSetCrossing> xs;
    for (int i = 0; i < 200; ++i) {
        // Rays along (1, 1, 0)·s through the touching point (½, ½, z), from various distances.
        const double s = u(rng), back = u(rng);
        const Vec3 touch(0.5, 0.5, z(rng));
        const Ray ray{touch - back * Vec3(s, s, 0.0), Vec3(s, s, 0.0)};
        grid->walk(ray, 0.0, kInf, false, xs);
        REQUIRE(xs.size() >= 2);
        CHECK(xs.size() % 2 == 0);
        CHECK(xs.front().entering);
        CHECK(std::fabs(xs.front().t - back) <= 1e-6 * back);
        double t;
        Vec3 n;
        bool e;
        CHECK(firstHit(leaf, ray, t, n, e));
    }
    // The zero set is the two lines u = ½ and v = ½ (f = (u − ½)(v − ½)): a ray beside the
    // diagonal, v = u + 0.01, crosses them at u = 0.49 and u = 0.5.
    const Ray beside{Vec3(-1.0, -0.99, 0.5), Vec3(1.0, 1.0, 0.0)};
    grid->walk(beside, 0.0, kInf, false, xs);
    REQUIRE(xs.size() == 2);
    CHECK(xs[0].entering);
    CHECK(xs[0].t == Approx(1.49).epsilon(1e-12));
    CHECK(xs[1].t == Approx(1.5).epsilon(1e-12));
}

TEST_CASE("LevelSet/difference with a box", "[volume]") {
    test::ScratchFolder dir;
    const double radius = 1.0, voxel = 0.05;
    test::writeGrids(dir.file("s.vdb"), {test::sphereGrid(radius, Vec3(0.0), voxel)});
    const NodePtr sphere = levelSetSolid(loadLevelSet(dir.file("s.vdb")));
    // The upper half (z > 0.2) cut away.
    const NodePtr cut =
        makeBoolean(BoolOp::Difference, {sphere, makeBox(Vec3(-2, -2, 0.2), Vec3(2, 2, 2))});
    const double bound = voxel * voxel / (4 * (radius - 2 * voxel)) + 1e-5 * voxel;
    TraceContext ctx;
    SpanList spans;
    // Down the z axis from above, at x = y = 0.3: the box's face at z = 0.2 is the first surface.
    cut->spans(Ray{Vec3(0.3, 0.3, 3.0), Vec3(0, 0, -1)}, 0.0, kInf, ctx, spans);
    REQUIRE(spans.size() == 1);
    CHECK(spans[0].in.t == Approx(2.8).epsilon(1e-12));
    CHECK(spans[0].in.normal.z > 0.0);  // the cutter's normal, flipped
    const double zExit = -std::sqrt(radius * radius - 0.18);
    CHECK(std::fabs((3.0 - spans[0].out.t) - zExit) <=
          bound / std::cos(std::asin(std::sqrt(0.18))) + 1e-9);
    // Below the cut the sphere is whole: a horizontal ray at z = −0.5 crosses it twice.
    cut->spans(Ray{Vec3(-3.0, 0.0, -0.5), Vec3(1, 0, 0)}, 0.0, kInf, ctx, spans);
    REQUIRE(spans.size() == 1);
    const double half = std::sqrt(radius * radius - 0.25);
    CHECK(std::fabs(spans[0].in.t - (3.0 - half)) <= 2 * bound);
    CHECK(std::fabs(spans[0].out.t - (3.0 + half)) <= 2 * bound);
}

TEST_CASE("LevelSet/rays that start inside leave once; spans agree with firstSurface", "[volume]") {
    test::ScratchFolder dir;
    const double radius = 1.0, voxel = 0.05;
    test::writeGrids(dir.file("s.vdb"), {test::sphereGrid(radius, Vec3(0.0), voxel)});
    const NodePtr solid = levelSetSolid(loadLevelSet(dir.file("s.vdb")));
    const double bound = voxel * voxel / (4 * (radius - 2 * voxel)) + 1e-5 * voxel;
    std::mt19937_64 rng(4);
    std::normal_distribution<double> n;
    TraceContext ctx;
    SpanList spans;
    for (int i = 0; i < 500; ++i) {
        // From a point inside (|p| ≤ 0.5) in a random direction: inside at t = 0, one exit.
        const Vec3 p = 0.5 * std::cbrt(std::uniform_real_distribution<double>(0, 1)(rng)) *
                       glm::normalize(Vec3(n(rng), n(rng), n(rng)));
        const Ray ray{p, glm::normalize(Vec3(n(rng), n(rng), n(rng)))};
        solid->spans(ray, 0.0, kInf, ctx, spans);
        REQUIRE(spans.size() == 1);
        CHECK_FALSE(spans[0].in.isSurface());  // the clip at t = 0
        CHECK(spans[0].in.t == 0.0);
        CHECK(std::fabs(glm::length(ray.at(spans[0].out.t)) - radius) <= bound);
        Boundary hit;
        bool entering = true;
        REQUIRE(solid->firstSurface(ray, 0.0, kInf, ctx, hit, entering));
        CHECK_FALSE(entering);
        CHECK(hit.t == spans[0].out.t);
        CHECK(glm::dot(hit.normal, ray.dir) > 0.0);  // outward, along the leaving ray
    }
}

TEST_CASE("LevelSet/implicit form: range holds the values, inside by sign", "[volume]") {
    test::ScratchFolder dir;
    test::writeGrids(dir.file("t.vdb"), {test::torusGrid(1.0, 0.3, 0.05)});
    const auto grid = loadLevelSet(dir.file("t.vdb"));
    const NodePtr solid = levelSetSolid(grid);
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> u(-1.6, 1.6), w(0.0, 0.4);
    for (int i = 0; i < 2000; ++i) {
        const Vec3 lo(u(rng), u(rng) * 0.3, u(rng));
        const Vec3 hi = lo + Vec3(w(rng), w(rng), w(rng));
        const Interval range = solid->valueInterval(
            {Interval(lo.x, hi.x), Interval(lo.y, hi.y), Interval(lo.z, hi.z)});
        for (int k = 0; k < 20; ++k) {
            const Vec3 p =
                lo + Vec3((hi.x - lo.x) * (k % 3) / 2.0, (hi.y - lo.y) * ((k / 3) % 3) / 2.0,
                          (hi.z - lo.z) * std::fmod(k * 0.37, 1.0));
            const double v = solid->value(p);
            REQUIRE(range.contains(v));
            // Inside by the sign, where the exact torus says so beyond the interpolation error.
            const double d = test::torusDistance(1.0, 0.3, p.x, p.y, p.z);
            if (d < -0.01) CHECK(v <= 0.0);
            if (d > 0.01) CHECK(v > 0.0);
        }
    }
}

TEST_CASE("LevelSet/errors name what is wrong", "[volume]") {
    test::ScratchFolder dir;
    const auto message = [](const std::string& path, const std::string& grid) -> std::string {
        try {
            loadLevelSet(path, grid);
        } catch (const VdbError& e) {
            return e.what();
        }
        return "";
    };
    CHECK(message(dir.file("none.vdb"), "") == "no such file");
    { std::ofstream(dir.file("text.vdb")) << "not a vdb"; }
    // Checked by kerf before OpenVDB reads it (volume/grids/checked_vdb_layout.h).
    CHECK(message(dir.file("text.vdb"), "") ==
          "not a .vdb file: its first 8 bytes are not OpenVDB's magic number");
    test::writeGrids(dir.file("many.vdb"),
                     {test::fogGrid(), test::vectorGrid(), test::sphereGrid(1.0, Vec3(0.0), 0.1)});
    CHECK(message(dir.file("many.vdb"), "missing") ==
          "it has no grid named 'missing'; its grids: 'density' (float, fog volume), 'sphere' "
          "(float, "
          "level set), 'vel' (vec3s, unknown class)");
    CHECK_THAT(message(dir.file("many.vdb"), "density"),
               Catch::StartsWith("grid 'density' is a fog volume"));
    CHECK(message(dir.file("many.vdb"), "vel") ==
          "grid 'vel' holds vec3s values; a solid needs a float level set");
    CHECK(message(dir.file("many.vdb"), "").empty());  // the level set is found by its class
    test::writeGrids(dir.file("fog.vdb"), {test::fogGrid()});
    CHECK_THAT(message(dir.file("fog.vdb"), ""),
               Catch::StartsWith("grid 'density' is a fog volume"));
    // A fog volume without its class: no value ≤ 0 (all densities are ≥ 0 and the background 0
    // is refused first as no outside).
    auto unclassed = test::fogGrid("d2");
    unclassed.kind = test::Grid::Kind::Unclassed;
    unclassed.background = 0.5f;
    test::writeGrids(dir.file("unclassed.vdb"), {unclassed});
    CHECK_THAT(message(dir.file("unclassed.vdb"), ""), Catch::Contains("has no value ≤ 0"));
}
