// Ray directions with exact +0 and −0 components: the trap of the slab test, where
// (lo − o)·(1/d) gives 0·inf = NaN or picks the wrong infinity. tests/csg/primitive_hardcases_test
// covers one box's spans along the three axes; here every one of the 26 axis and diagonal
// directions with every sign of zero, through SceneGeometry::nearestHit, on Boolean
// combinations of boxes, from cameras lying in a face plane or on an edge, and over whole
// depth images (no NaN, no speckle: every pixel equals the long-double slab test).
#include "render/camera.h"
#include "render/render.h"
#include "render/render_test_util.h"
#include "util/oracles.h"

#include <catch2/catch.hpp>

#include <vector>

using namespace kerf;
using namespace kerf::test;

namespace {

/// The 26 directions of {−1, 0, 1}³ \ {0}, each zero component in both signs (56 in all).
std::vector<Vec3> signedZeroDirections() {
    std::vector<Vec3> out;
    for (int code = 0; code < 27; ++code) {
        const int c[3] = {code % 3 - 1, code / 3 % 3 - 1, code / 9 - 1};
        if (c[0] == 0 && c[1] == 0 && c[2] == 0) continue;
        int zeros = 0;
        for (int a = 0; a < 3; ++a) zeros += c[a] == 0;
        for (int signs = 0; signs < (1 << zeros); ++signs) {
            Vec3 d;
            int z = 0;
            for (int a = 0; a < 3; ++a)
                d[a] = c[a] != 0 ? 2.0 * c[a] : ((signs >> z++) & 1 ? -0.0 : 0.0);
            out.push_back(d);
        }
    }
    return out;
}

/// The long-double slab entry and its face normal (the axis whose slab is entered last). At an
/// edge or corner several faces tie: `normal` has a component for each, and either is right.
struct BoxEntry {
    bool hit = false;
    LD t = 0;
    Vec3 normal{0.0};
    bool admits(const Vec3& n) const {
        int axis = -1;
        for (int a = 0; a < 3; ++a)
            if (n[a] != 0) axis = axis < 0 ? a : 3;
        return axis >= 0 && axis < 3 && n[axis] == normal[axis];
    }
};

BoxEntry boxEntry(const Ray& ray, const Vec3& lo, const Vec3& hi) {
    BoxEntry e;
    const auto span = boxOracle(ray, lo, hi);
    if (!span || span->first <= 0) return e;  // behind, or starting inside: not an entry
    e.hit = true;
    e.t = span->first;
    for (int a = 0; a < 3; ++a) {
        if (ray.dir[a] == 0) continue;
        const LD ta = ((ray.dir[a] > 0 ? LD(lo[a]) : LD(hi[a])) - ray.origin[a]) / ray.dir[a];
        if (ta == e.t) e.normal[a] = ray.dir[a] > 0 ? -1.0 : 1.0;
    }
    return e;
}

/// Checks nearestHit on `scene` against the entry of the box lo–hi: t exact, normal exact.
void checkEntry(const SceneGeometry& scene, const Ray& ray, const Vec3& lo, const Vec3& hi) {
    TraceContext ctx;
    const BoxEntry e = boxEntry(ray, lo, hi);
    const auto hit = scene.nearestHit(ray, 0.0, kInf, ctx);
    CAPTURE(ray.origin.x, ray.origin.y, ray.origin.z, ray.dir.x, ray.dir.y, ray.dir.z);
    CAPTURE(std::signbit(ray.dir.x), std::signbit(ray.dir.y), std::signbit(ray.dir.z));
    REQUIRE(bool(hit) == e.hit);
    if (!hit) return;
    CHECK(hit->t == double(e.t));  // every quotient here is exact in binary
    CHECK(hit->entering);
    CHECK(e.admits(hit->normal));
}

}  // namespace

TEST_CASE("SceneGeometry::nearestHit on boxes along the 26 directions with signed zeros") {
    const Vec3 lo(-1.0), hi(1.0);
    // Distinct coordinates, so that every entry is through one face, not an edge.
    const Vec3 inside(0.25, -0.125, 0.375);
    const std::vector<Vec3> dirs = signedZeroDirections();
    REQUIRE(dirs.size() == 56);  // 6 axes ×4 zero signs, 12 face diagonals ×2, 8 corners ×1

    // The same box as a primitive, as two abutting halves in a union, as a difference whose
    // cutter lies outside it (touching a face), and as an intersection with a larger box.
    const NodePtr box = makeBox(lo, hi);
    const std::vector<std::pair<const char*, NodePtr>> solids{
        {"box", box},
        {"difference touching a face",
         makeBoolean(BoolOp::Difference, {box, makeBox(Vec3(1.0, -2.0, -2.0), Vec3(3.0))})},
        {"intersection",
         makeBoolean(BoolOp::Intersection, {box, makeBox(Vec3(-1.0, -1.0, -1.0), Vec3(4.0))})},
        {"translated",
         makeTransform(makeBox(lo - Vec3(8.0), hi - Vec3(8.0)), Affine::translate(Vec3(8.0)))},
    };
    for (const auto& [name, solid] : solids) {
        const SceneGeometry scene({solid});
        for (const Vec3& d : dirs) {
            INFO(name);
            // Aimed at the inside point from 5 units back: exact arithmetic throughout.
            checkEntry(scene, Ray{inside - 2.5 * d, d}, lo, hi);
            // Offset so that it runs past the box (misses whenever d has a zero component
            // along which the origin is outside).
            checkEntry(scene, Ray{Vec3(1.5, -0.5, 0.5) - 2.5 * d, d}, lo, hi);
        }
    }
}

// A ray that enters exactly on the seam line of two abutting boxes (e.g. origin
// (−3.5, −0.5, −4.5), direction (2, ±0, 2): it meets x = 0 and z = −1 together at t = 1.75)
// must carry the outer face's normal (0, 0, −1), not the seam's (−1, 0, 0): the box reports
// its edge touch as a zero-width span, so the union sees both halves at the tie.
TEST_CASE("SceneGeometry::nearestHit on a union of abutting boxes along the 26 directions",
          "[zero-direction]") {
    const Vec3 lo(-1.0), hi(1.0);
    const SceneGeometry scene({makeBoolean(
        BoolOp::Union, {makeBox(lo, Vec3(0.0, 1.0, 1.0)), makeBox(Vec3(0.0, -1.0, -1.0), hi)})});
    for (const Vec3& d : signedZeroDirections()) {
        checkEntry(scene, Ray{Vec3(0.25, -0.125, 0.375) - 2.5 * d, d}, lo, hi);
        checkEntry(scene, Ray{Vec3(1.5, -0.5, 0.5) - 2.5 * d, d}, lo, hi);
    }
}

TEST_CASE("SceneGeometry::nearestHit from cameras in a face plane and along edges") {
    const Vec3 lo(-1.0), hi(1.0);
    const SceneGeometry scene({makeBoolean(
        BoolOp::Union, {makeBox(lo, Vec3(1.0, 0.0, 1.0)), makeBox(Vec3(-1.0, 0.0, -1.0), hi)})});
    TraceContext ctx;
    SECTION("a ray lying in the top face plane enters the closed box") {
        for (double zx : {0.0, -0.0})
            for (double zy : {0.0, -0.0}) {
                const auto hit =
                    scene.nearestHit(Ray{Vec3(zx, 1.0, -5.0), Vec3(zx, zy, 1.0)}, 0.0, kInf, ctx);
                REQUIRE(hit);
                CHECK(hit->t == 4.0);
                CHECK(hit->normal == Vec3(0, 0, -1));
            }
        // One ulp above the plane: a miss.
        CHECK_FALSE(scene.nearestHit(
            Ray{Vec3(0.0, std::nextafter(1.0, 2.0), -5.0), Vec3(-0.0, 0.0, 1.0)}, 0.0, kInf, ctx));
    }
    SECTION("along an edge of the box, and along the shared face's edge") {
        for (const Vec3& o : {Vec3(1.0, 1.0, -5.0), Vec3(-1.0, -1.0, -5.0), Vec3(1.0, 0.0, -5.0)}) {
            const auto hit = scene.nearestHit(Ray{o, Vec3(-0.0, 0.0, 0.5)}, 0.0, kInf, ctx);
            INFO(o.x << "," << o.y);
            REQUIRE(hit);
            CHECK(hit->t == 8.0);
            CHECK(hit->normal == Vec3(0, 0, -1));
        }
    }
    SECTION("from a point on a face, looking in: the hit is the way out, exactly") {
        for (double zx : {0.0, -0.0}) {
            const auto hit =
                scene.nearestHit(Ray{Vec3(0.5, -1.0, 0.25), Vec3(zx, 1.0, -0.0)}, 0.0, kInf, ctx);
            REQUIRE(hit);
            CHECK_FALSE(hit->entering);
            CHECK(hit->t == 2.0);
            CHECK(hit->normal == Vec3(0, 1, 0));
        }
    }
}

TEST_CASE("render: depth of an axis-aligned box seen straight on has no speckle") {
    // 64×64 as asked, and 63×63, whose middle row and column have exactly zero (signed)
    // direction components. Also a camera lying in the box's top face plane.
    struct View {
        int size;
        Vec3 eye;
        Vec3 lookAt;
    };
    const Vec3 lo(-1.0, -1.0, -1.0), hi(1.0, 1.0, 1.0);
    for (const View& view :
         {View{64, Vec3(0, 0, -5), Vec3(0, 0, 0)}, View{63, Vec3(0, 0, -5), Vec3(0, 0, 0)},
          View{63, Vec3(0, 1, -5), Vec3(0, 1, 0)}, View{64, Vec3(0, 1, -5), Vec3(0, 1, 0)}}) {
        Scene scene;
        // Two boxes abutting at z = 0 as one union: the seam faces the camera edge-on.
        addObject(
            scene,
            makeBoolean(BoolOp::Union, {makeBox(lo, Vec3(1, 1, 0)), makeBox(Vec3(-1, -1, 0), hi)}),
            0);
        scene.camera.eye = view.eye;
        scene.camera.lookAt = view.lookAt;
        scene.camera.fovDegrees = 40;
        RenderOptions options = smallImage(view.size, view.size);
        options.wantDepth = true;
        options.wantNormal = true;
        const RenderResult r = render(scene, options);
        const Camera camera(scene.camera, view.size, view.size);
        int mismatches = 0, hits = 0, zeroComponents = 0;
        for (int j = 0; j < view.size; ++j)
            for (int i = 0; i < view.size; ++i) {
                const Ray ray = camera.rayThrough(i + 0.5, j + 0.5);
                zeroComponents += (ray.dir.x == 0) + (ray.dir.y == 0);
                const BoxEntry e = boxEntry(ray, lo, hi);
                const float depth = r.depth.at(i, j, 0);
                const float expected = e.hit ? float(e.t * glm::length(ld(ray.dir))) : INFINITY;
                const bool nanFree = !std::isnan(depth) && !std::isnan(r.normal.at(i, j, 0)) &&
                                     !std::isnan(r.color.at(i, j, 0));
                const bool same = depth == expected ||
                                  (e.hit && std::fabs(depth - expected) <=
                                                std::nextafter(expected, INFINITY) - expected);
                hits += e.hit;
                if (!nanFree || !same || (e.hit && !e.admits(pixel(r.normal, i, j)))) {
                    ++mismatches;
                    FAIL_CHECK("pixel " << i << "," << j << " depth " << depth << " expected "
                                        << expected);
                }
            }
        INFO("view size " << view.size << " eye y " << view.eye.y);
        CHECK(mismatches == 0);
        CHECK(hits > view.size * view.size / 8);
        if (view.size == 63) CHECK(zeroComponents >= 63);
    }
}
