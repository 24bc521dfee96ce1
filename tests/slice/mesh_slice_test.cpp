// Sections of closed meshes, alone and in CSG, against the areas of the polyhedra they cut:
// an octahedron's section at height h is a square of area 2(r − |h|)².
#include "csg/tree/solids.h"
#include "mesh/mesh_shape.h"
#include "slice/slice.h"
#include "tests/mesh/mesh_files.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace kerf;
using namespace kerf::test;

namespace {

SliceResult sliceAt(const NodePtr& object, double z, double& tolerance) {
    Scene scene;
    scene.objects.push_back(object);
    SliceOptions o;
    o.tolerance = 1e-8;
    SceneSlicer slicer(scene, SlicePlane::axisAligned(2, z), o);
    tolerance = slicer.absoluteTolerance();
    return slicer.slice(SlicePlane::axisAligned(2, z).w);
}

}  // namespace

TEST_CASE("slice::a closed mesh's section is the polyhedron's") {
    const NodePtr octa = meshNode(std::make_shared<const MeshShape>(octahedronMesh()), false);
    const double r = kOctaRadius;
    for (double h : {0.0, 0.3, -0.71, 1.1}) {
        double tol = 0.0;
        const SliceResult s = sliceAt(octa, kOctaCenter.z + h, tol);
        const double exact = 2.0 * (r - std::fabs(h)) * (r - std::fabs(h));
        INFO("h " << h << " area " << s.stats.area << " exact " << exact);
        REQUIRE(s.stats.contours == 1);
        CHECK(std::fabs(s.stats.area - exact) <= 2.0 * tol * s.stats.perimeter);
        CHECK(s.stats.perimeter ==
              Approx(4.0 * std::sqrt(2.0) * (r - std::fabs(h))).epsilon(1e-13));
    }
}

TEST_CASE("slice::a mesh minus a sphere leaves the square minus the disc") {
    const NodePtr octa = meshNode(std::make_shared<const MeshShape>(octahedronMesh()), true);
    const double r = kOctaRadius, s = 0.4, h = 0.1;
    const NodePtr cut = makeBoolean(BoolOp::Difference, {octa, makeSphere(kOctaCenter, s)});
    double tol = 0.0;
    const SliceResult res = sliceAt(cut, kOctaCenter.z + h, tol);
    const double pi = 3.14159265358979323846;
    const double exact = 2.0 * (r - h) * (r - h) - pi * (s * s - h * h);
    INFO("area " << res.stats.area << " exact " << exact);
    REQUIRE(res.stats.contours == 2);
    CHECK(res.stats.holes == 1);
    CHECK(std::fabs(res.stats.area - exact) <= 2.0 * tol * res.stats.perimeter);
}

TEST_CASE("slice::an open mesh is left out of the section with a note") {
    TriangleMesh m = octahedronMesh();
    m.triangles.pop_back();
    Scene scene;
    scene.objects.push_back(meshNode(std::make_shared<const MeshShape>(std::move(m)), false));
    SceneSlicer slicer(scene, SlicePlane::axisAligned(2, kOctaCenter.z), SliceOptions{});
    CHECK(slicer.slice(kOctaCenter.z).stats.contours == 0);
    REQUIRE(slicer.notes().size() == 1);
    CHECK(slicer.notes()[0].find("open mesh") != std::string::npos);
}

TEST_CASE("slice::a moved mesh is cut where it was moved to") {
    // Scaled by 2 and shifted: the section at the new centre's height is the square of side
    // 2·√2·r.
    const NodePtr octa =
        makeTransform(meshNode(std::make_shared<const MeshShape>(octahedronMesh()), false),
                      Affine::translate(Vec3(0.0, 0.0, 5.0)).after(Affine::scale(Vec3(2.0))));
    double tol = 0.0;
    const SliceResult s = sliceAt(octa, 2.0 * kOctaCenter.z + 5.0, tol);
    const double r = 2.0 * kOctaRadius;
    CHECK(s.stats.area == Approx(2.0 * r * r).epsilon(1e-14));
}
