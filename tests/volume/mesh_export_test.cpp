// kerf mesh against closed forms: every edge of every mesh is shared by exactly two triangles
// running it in opposite directions (watertight, manifold, consistently wound); vertices lie
// on a sphere; the enclosed volume converges as h²; a box's edges and corners are kept; the
// measured distance to the surface equals the exact one where that is known.
#include "volume/export/mesh_export.h"
#include "volume/export/mesh_unpinch.h"

#include "util/compiled_scene.h"

#include <tbb/global_control.h>
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <string>

using namespace kerf;

namespace {

constexpr double kPi = 3.14159265358979323846;

WatertightMesh meshOf(const std::string& model, double voxel, MeshExportStats& stats,
                      double adaptivity = 0.0) {
    const Scene scene = test::compiledScene(model, "mesh_export_test.kerf");
    MeshExportOptions options;
    options.voxel = voxel;
    options.adaptivity = adaptivity;
    options.measure = true;
    return exportMesh(scene.objects, options, stats);
}

/// Counts every directed edge: a closed, manifold, consistently wound mesh has each directed
/// edge once and its reverse once. Returns how many undirected edges break that.
size_t badEdges(const WatertightMesh& mesh) {
    std::map<std::pair<uint32_t, uint32_t>, int> directed;
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) ++directed[{t[size_t(k)], t[size_t((k + 1) % 3)]}];
    size_t bad = 0;
    for (const auto& [edge, count] : directed) {
        const auto reverse = directed.find({edge.second, edge.first});
        if (count != 1 || reverse == directed.end() || reverse->second != 1) ++bad;
    }
    return bad;
}

void requireWatertight(const WatertightMesh& mesh) {
    REQUIRE(mesh.triangles.size() > 100);
    CHECK(badEdges(mesh) == 0);
    size_t malformed = 0;  // a repeated corner or an index past the vertices
    for (const auto& t : mesh.triangles)
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] ||
            std::max({t[0], t[1], t[2]}) >= mesh.vertices.size())
            ++malformed;
    CHECK(malformed == 0);
}

const char* kSphere = "object sphere { center <0.1, 0.2, 0.3> radius 1 };";

}  // namespace

TEST_CASE("mesh_export/sphere: watertight, vertices on the sphere, volume error O(h^2)") {
    const Vec3 c(0.1, 0.2, 0.3);
    const double exact = 4.0 / 3.0 * kPi;
    double previousError = 0.0;
    for (const double h : {0.1, 0.05}) {
        INFO("voxel " << h);
        MeshExportStats stats;
        const WatertightMesh mesh = meshOf(kSphere, h, stats);
        requireWatertight(mesh);
        // Every vertex on the sphere after placement (a root found along the radius).
        double worstVertex = 0.0;
        for (const Vec3& v : mesh.vertices)
            worstVertex = std::max(worstVertex, std::fabs(glm::length(v - c) - 1.0));
        CHECK(worstVertex <= 1e-6 * h);
        CHECK(stats.placement.kept == 0);
        // The measured distance is the exact distance to the sphere at the sample points: at
        // least the largest at the centroids (and no more than the chord sag allows).
        double worstCentroid = 0.0;
        for (const auto& t : mesh.triangles) {
            const Vec3 m = (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0;
            worstCentroid = std::max(worstCentroid, std::fabs(glm::length(m - c) - 1.0));
        }
        CHECK(stats.distance.hausdorff >= worstCentroid * (1.0 - 1e-9));
        CHECK(stats.distance.hausdorff <= 0.1 * h);
        CHECK(stats.distance.firstOrder == 0);
        // An inscribed polyhedron: its volume is below the ball's, by O(h²). Measured here
        // 1.58·h² at h = 0.1 and 1.55·h² at 0.05; the bound 2·h² leaves room for the
        // lattice's phase.
        CHECK(stats.meshVolume == Approx(enclosedVolume(mesh.vertices, mesh.triangles)));
        const double error = exact - stats.meshVolume;
        INFO("volume " << stats.meshVolume << " error " << error);
        CHECK(error > 0.0);
        CHECK(error <= 2.0 * h * h);
        if (previousError > 0.0) CHECK(error <= previousError / 3.0);  // order 2 → about /4
        previousError = error;
        // The interval bounds of the model's volume hold the exact one.
        CHECK(stats.modelVolume.lo <= exact);
        CHECK(stats.modelVolume.hi >= exact);
    }
}

TEST_CASE("mesh_export/box minus sphere keeps the box's edges and corner") {
    // Faces off the lattice (widths not multiples of h) and on it (h divides the widths, and
    // the lattice starts two voxels below the bounds): both must keep the creases.
    struct Case {
        const char* name;
        Vec3 lo, hi;
        double h;
    };
    const Case cases[] = {{"off the lattice", {-0.93, -0.91, -0.97}, {0.971, 0.953, 0.936}, 0.1},
                          {"on the lattice", {-0.93, -0.91, -0.97}, {0.97, 0.95, 0.93}, 0.1},
                          {"finer", {-0.93, -0.91, -0.97}, {0.971, 0.953, 0.936}, 0.04}};
    for (const Case& k : cases) {
        INFO(k.name);
        // The sphere takes a bite out of the corner at hi, so the edges there end on it.
        char model[512];
        std::snprintf(
            model, sizeof model,
            "object difference { box { min <%.17g, %.17g, %.17g> max <%.17g, %.17g, %.17g> } "
            "sphere { center <%.17g, %.17g, %.17g> radius 0.7 } };",
            k.lo.x, k.lo.y, k.lo.z, k.hi.x, k.hi.y, k.hi.z, k.hi.x, k.hi.y, k.hi.z);
        MeshExportStats stats;
        const WatertightMesh mesh = meshOf(model, k.h, stats);
        requireWatertight(mesh);
        const double tol = 1e-6 * k.h;
        // Distance from v to the box edge along `axis` at the corners' other two coordinates.
        const Vec3 corner[2] = {k.lo, k.hi};
        int onEdges = 0;
        bool cornerFound = false;
        for (const Vec3& v : mesh.vertices) {
            if (glm::length(v - k.hi) < 0.7 + 2.0 * k.h) continue;  // near the bite
            if (glm::length(v - k.lo) <= tol) cornerFound = true;
            for (int axis = 0; axis < 3; ++axis)
                for (int s = 0; s < 4; ++s) {
                    const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
                    const double u = corner[s & 1][a1], w = corner[s >> 1][a2];
                    const double d = std::hypot(v[a1] - u, v[a2] - w);
                    // A vertex within a fifth of a voxel of an edge is on it.
                    if (d < 0.2 * k.h) {
                        INFO("vertex " << v.x << " " << v.y << " " << v.z << " is " << d
                                       << " from the edge");
                        CHECK(d <= tol);
                        ++onEdges;
                    }
                }
        }
        CHECK(cornerFound);
        // The nine edges away from the bite, about 1.9 long: a vertex per voxel along each.
        CHECK(onEdges >= int(9 * 1.0 / k.h));
        // Flat faces and sharp edges: the error is the chord sag on the spherical bite and
        // the triangles that cut its circular crease where it runs diagonally across the
        // lattice (measured 0.16 h).
        CHECK(stats.distance.hausdorff <= 0.25 * k.h);
        const Vec3 size = k.hi - k.lo;
        const double exact = size.x * size.y * size.z - 4.0 / 3.0 * kPi * 0.343 / 8.0;
        CHECK(std::fabs(stats.meshVolume - exact) <= 0.2 * k.h * k.h);
    }
}

TEST_CASE("mesh_export/torus: watertight, volume 2 pi^2 R r^2 within O(h^2)") {
    MeshExportStats stats;
    const WatertightMesh mesh =
        meshOf("object torus { major 1 minor 0.3 } rotate <20, 10, 0> translate <0.05, 0.1, 0>;",
               0.05, stats);
    requireWatertight(mesh);
    const double exact = 2.0 * kPi * kPi * 1.0 * 0.09;
    INFO("volume " << stats.meshVolume << " exact " << exact);
    // Measured 1.9·h² (the tube's radius 0.3 is its tighter curvature).
    CHECK(std::fabs(stats.meshVolume - exact) <= 2.5 * 0.05 * 0.05);
    CHECK(stats.distance.hausdorff <= 0.1 * 0.05);
}

TEST_CASE("mesh_export/gyroid ball model: watertight, volume within the model's bounds") {
    const Scene scene =
        test::compiledSceneFile(std::string(KERF_SOURCE_DIR) + "/models/gyroid_sphere.kerf");
    for (const double adaptivity : {0.0, 0.5}) {
        INFO("adaptivity " << adaptivity);
        MeshExportOptions options;
        options.voxel = 0.05;
        options.adaptivity = adaptivity;
        options.measure = true;
        MeshExportStats stats;
        const WatertightMesh mesh = exportMesh(scene.objects, options, stats);
        CHECK(stats.unboundedSkipped == 1);  // the floor
        requireWatertight(mesh);
        // Once equal positions are joined, as a reader of the file does, no edge has four
        // faces (37 before crease points were unpinched, at adaptivity 0).
        CHECK(crowdedEdges(mesh.vertices, mesh.triangles) == 0);
        CHECK(stats.crowdedEdges == 0);
        CHECK(stats.meshVolume > stats.modelVolume.lo);
        CHECK(stats.meshVolume < stats.modelVolume.hi);
        // Thin sheets meet the sphere at grazing angles: the worst is still within two voxels.
        CHECK(stats.distance.hausdorff <= 2.0 * options.voxel);
    }
}

// cup.kerf at voxel 0.08: two vertices 2^-55 apart in y (and off the float grid in x) were
// left unjoined by a GCC 12.2 -O2 miscompile of the float rounding, so an edge of four faces
// in the written file went uncounted and unfixed.
TEST_CASE("mesh_export/crowded edges are counted on positions as floats") {
    const double x = 2.6094427190999907, z0 = -0.6747877654413359, z1 = -0.61622697442571095;
    const std::vector<Vec3> points = {{x, 0.19999999999999998, z0},
                                      {x, 0.19999999999999993, z1},  // the edge, sheet 1
                                      {x, 0.19999999999999996, z0},
                                      {x, 0.19999999999999991, z1},  // the same as floats
                                      {2.5, 0.2, -0.65},
                                      {2.7, 0.2, -0.65},  // sheet 1's other corners
                                      {2.5, 0.25, -0.65},
                                      {2.7, 0.25, -0.65}};  // sheet 2's
    const std::vector<std::array<uint32_t, 3>> triangles = {
        {0, 1, 4}, {1, 0, 5}, {2, 3, 6}, {3, 2, 7}};
    CHECK(crowdedEdges(points, triangles) == 1);
    // Apart by more than a float's spacing, the sheets share no edge.
    std::vector<Vec3> apart = points;
    apart[2].y = apart[3].y = 0.2 + 1e-6;
    CHECK(crowdedEdges(apart, triangles) == 0);
}

TEST_CASE("mesh_export/bad voxel sizes are refused") {
    const Scene scene = test::compiledScene(kSphere);
    MeshExportStats stats;
    for (const double h : {0.0, -0.1, std::nan(""), HUGE_VAL, 1e-9, 1e-4}) {
        INFO("voxel " << h);
        MeshExportOptions options;
        options.voxel = h;
        CHECK_THROWS_AS(exportMesh(scene.objects, options, stats), MeshInputError);
    }
    MeshExportOptions options;
    options.voxel = 0.1;
    const Scene floorOnly = test::compiledScene("object halfspace { normal <0, 1, 0> };");
    CHECK_THROWS_WITH(exportMesh(floorOnly.objects, options, stats),
                      Catch::Contains("no bounded object"));
}

TEST_CASE("mesh_export/the same mesh whatever the thread count") {
    const Scene scene =
        test::compiledSceneFile(std::string(KERF_SOURCE_DIR) + "/models/gyroid_sphere.kerf");
    MeshExportOptions options;
    options.voxel = 0.08;
    options.adaptivity = 0.2;
    MeshExportStats stats;
    const WatertightMesh many = exportMesh(scene.objects, options, stats);
    WatertightMesh one;
    {
        tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
        one = exportMesh(scene.objects, options, stats);
    }
    REQUIRE(one.vertices.size() == many.vertices.size());
    CHECK(one.vertices == many.vertices);
    CHECK(one.triangles == many.triangles);
}

TEST_CASE("mesh_export/a model scaled by 1e-6 or 1e6 meshes alike at a scaled voxel") {
    // No tolerance depends on the model's scale: every one is a fraction of the voxel.
    double relativeError[3], relativeDistance[3];
    size_t triangles[3];
    const double scales[3] = {1.0, 1e-6, 1e6};
    for (int i = 0; i < 3; ++i) {
        const double s = scales[i];
        char model[160];
        // The lattice starts 2 voxels below the bounds, so with a voxel that divides the
        // radius the poles are lattice points, whose side comes from rounding (which differs
        // between scales): 0.093 does not divide 1.
        std::snprintf(model, sizeof model,
                      "object sphere { center <%.17g, %.17g, %.17g> radius %.17g };", 0.1 * s,
                      0.2 * s, 0.3 * s, s);
        MeshExportStats stats;
        const WatertightMesh mesh = meshOf(model, 0.093 * s, stats);
        requireWatertight(mesh);
        triangles[i] = mesh.triangles.size();
        relativeError[i] = (4.0 / 3.0 * kPi * s * s * s - stats.meshVolume) / (s * s * s);
        relativeDistance[i] = stats.distance.hausdorff / s;
    }
    for (int i = 1; i < 3; ++i) {
        INFO("scale " << scales[i]);
        CHECK(triangles[i] == triangles[0]);
        CHECK(relativeError[i] == Approx(relativeError[0]).epsilon(1e-6));
        CHECK(relativeDistance[i] == Approx(relativeDistance[0]).epsilon(1e-6));
    }
}
