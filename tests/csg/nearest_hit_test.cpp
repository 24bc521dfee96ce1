// SceneGeometry::nearestHit where two separate objects' faces coincide: the choice is fixed
// (not by ulps of t or the search order) and rays leaving the chosen hit start past both.
#include "csg/bvh/scene_geometry.h"
#include "csg/tree/solids.h"
#include "util/oracles.h"

#include <catch2/catch.hpp>

using namespace kerf;
using namespace kerf::test;

namespace {

/// A block with its top at y = 0.3 and a slab resting on it, placed by a transform so its
/// bottom is 0.1 + 0.2 (not 0.3): the two faces differ by rounding, either way per ray.
NodePtr block() { return makeBox({-2, -1, -2}, {2, 0.3, 2}); }
NodePtr slabOnBlock() {
    return makeTransform(makeBox({-1, 0.1, -1}, {1, 0.6, 1}), Affine::translate({0, 0.2, 0}));
}
/// A box overlapping the block whose top face lies in the block's top face, placed by a scale
/// (3 × 0.1 is not 0.3): per ray its top comes out an ulp nearer or farther or the same.
NodePtr flushWithBlock() {
    return makeTransform(makeBox({-1.0 / 3, -0.5, -1.0 / 3}, {1.0 / 3, 0.1, 1.0 / 3}),
                         Affine::scale({3, 3, 3}));
}

/// A ray from a random point at a height in [y0, y1] over the slab's footprint, heading up or
/// down steeply enough to stay within it (|x|, |z| < 1) between y = −1 and y = 2.
Ray verticalish(Random& rnd, double y0, double y1, bool up) {
    const Vec3 o(rnd.uniform(-0.4, 0.4), rnd.uniform(y0, y1), rnd.uniform(-0.4, 0.4));
    const Vec3 d(rnd.uniform(-0.15, 0.15), up ? 1.0 : -1.0, rnd.uniform(-0.15, 0.15));
    return {o, d};
}

/// The origin of a ray leaving h on the side `side` points to, as the renderer places it.
Vec3 leaving(const Ray& ray, const Hit& h, const Vec3& side) {
    const Vec3 p = ray.at(h.t);
    return p + hitErrorBound(ray, h.t, p, h.relError) * side;
}

}  // namespace

TEST_CASE("nearestHit: passing from one object into a touching one meets the one entered") {
    for (bool slabFirst : {true, false}) {
        const std::vector<NodePtr> objects = slabFirst
                                                 ? std::vector<NodePtr>{slabOnBlock(), block()}
                                                 : std::vector<NodePtr>{block(), slabOnBlock()};
        const int slab = slabFirst ? 0 : 1, blk = 1 - slab;
        const SceneGeometry geometry(objects);
        TraceContext ctx;
        Random rnd(5);
        int wrongObject = 0, wrongBack = 0, wrongOn = 0;
        for (int k = 0; k < 2000; ++k) {
            // Down from inside the slab (leaving it, entering the block), or up from inside
            // the block (leaving it, entering the slab).
            const bool down = k % 2 == 0;
            const Ray ray =
                down ? verticalish(rnd, 0.35, 0.55, false) : verticalish(rnd, -0.9, 0.25, true);
            const std::optional<Hit> h = geometry.nearestHit(ray, 0.0, kInf, ctx);
            REQUIRE(h);
            const int entered = down ? blk : slab, left = down ? slab : blk;
            CHECK(std::abs(h->t - (0.3 - ray.origin.y) / ray.dir.y) <= 1e-14);
            if (h->object != entered || !h->entering) ++wrongObject;
            // Back the way it came: inside the object it left, it meets that object's far
            // face, not the contact again.
            const Vec3 back = down ? Vec3(0, 1, 0) : Vec3(0, -1, 0);
            const Ray r1{leaving(ray, *h, back), -ray.dir};
            const std::optional<Hit> h1 = geometry.nearestHit(r1, 0.0, kInf, ctx);
            if (!h1 || h1->object != left || h1->entering || h1->t < 0.1) ++wrongBack;
            // On into the object entered: it meets that object's far face, not the contact.
            const Ray r2{leaving(ray, *h, -back), ray.dir};
            const std::optional<Hit> h2 = geometry.nearestHit(r2, 0.0, kInf, ctx);
            if (!h2 || h2->object != entered || h2->entering || h2->t < 0.1) ++wrongOn;
        }
        INFO("slab listed " << (slabFirst ? "first" : "second"));
        CHECK(wrongObject == 0);
        CHECK(wrongBack == 0);
        CHECK(wrongOn == 0);
    }
}

TEST_CASE("nearestHit: two objects entered through one face give the one listed first") {
    for (bool blockFirst : {true, false}) {
        const std::vector<NodePtr> objects = blockFirst
                                                 ? std::vector<NodePtr>{block(), flushWithBlock()}
                                                 : std::vector<NodePtr>{flushWithBlock(), block()};
        const SceneGeometry geometry(objects);
        TraceContext ctx;
        Random rnd(9);
        int notFirst = 0;
        for (int k = 0; k < 2000; ++k) {
            const Ray ray = verticalish(rnd, 1.5, 2.0, false);
            const std::optional<Hit> h = geometry.nearestHit(ray, 0.0, kInf, ctx);
            REQUIRE(h);
            CHECK(h->entering);
            CHECK(std::abs(h->t - (0.3 - ray.origin.y) / ray.dir.y) <= 1e-14);
            notFirst += h->object != 0;
        }
        INFO("block listed " << (blockFirst ? "first" : "second"));
        CHECK(notFirst == 0);
    }
}
