// Degenerate and extreme values at the csg level, where the language's checks do not protect:
// zero-thickness boxes, cones with both radii 0, and coordinates of 1e±300. Nothing may crash
// or produce NaN; hits are within 1e-12 relative of the long-double value or a clean miss.
#include "render/render.h"
#include "render/render_test_util.h"
#include "util/oracles.h"

#include <catch2/catch.hpp>

using namespace kerf;
using namespace kerf::test;

namespace {

void checkFinite(const SpanList& spans) {
    for (const Span& s : spans) {
        CHECK_FALSE(std::isnan(s.in.t));
        CHECK_FALSE(std::isnan(s.out.t));
        for (int a = 0; a < 3; ++a) {
            CHECK(std::isfinite(s.in.normal[a]));
            CHECK(std::isfinite(s.out.normal[a]));
        }
    }
}

}  // namespace

TEST_CASE("Box with min == max on one axis") {
    Random rng(701);
    const NodePtr sheet = makeBox(Vec3(-1.0, 0.5, -1.0), Vec3(1.0, 0.5, 1.0));
    TraceContext ctx;
    SECTION("a ray that crosses the plane meets no span of any width, and no hit") {
        // At most a zero-width touch (the box reports touches so Boolean parents see them at
        // ties; they vanish in any combination and are never a hit).
        const SceneGeometry alone({sheet});
        for (int i = 0; i < 2000; ++i) {
            const Vec3 o = rng.unitVector() * 5.0;
            const Ray ray{o, rng.inBall() - o};
            if (ray.dir.y == 0) continue;
            SpanList s;
            sheet->spans(ray, 0.0, kInf, ctx, s);
            CAPTURE(i);
            for (const Span& x : s) CHECK(x.in.t == x.out.t);
            CHECK_FALSE(alone.nearestHit(ray, 0.0, kInf, ctx));
        }
    }
    SECTION("a ray lying in the plane: the closed box holds the segment, exactly") {
        // The same convention as a ray in a face plane of a proper box.
        for (double zy : {0.0, -0.0}) {
            SpanList s;
            sheet->spans(Ray{Vec3(-3.0, 0.5, 0.25), Vec3(2.0, zy, 0.0)}, 0.0, kInf, ctx, s);
            checkFinite(s);
            REQUIRE(s.size() == 1);
            CHECK(s[0].in.t == 1.0);
            CHECK(s[0].out.t == 2.0);
            CHECK(s[0].in.normal == Vec3(-1, 0, 0));
        }
    }
    SECTION("rendered tilted, it is invisible: every pixel a miss, no NaN") {
        Scene scene;
        addObject(scene, sheet, 0);
        scene.background = Vec3(0.25);
        scene.camera.eye = Vec3(0.3, 3.0, -4.0);
        RenderOptions options = smallImage(32, 24);
        options.wantDepth = true;
        const RenderResult r = render(scene, options);
        for (float d : r.depth.pixels) CHECK(std::isinf(d));
        for (float c : r.color.pixels) CHECK(c == 0.25f);
    }
}

TEST_CASE("Cone with both radii 0") {
    Random rng(702);
    const NodePtr needle = makeCone(Vec3(0.0, -1.0, 0.0), Vec3(0.0, 1.0, 0.0), 0.0, 0.0);
    TraceContext ctx;
    for (int i = 0; i < 2000; ++i) {
        const Vec3 o = rng.unitVector() * 5.0;
        Ray ray{o, rng.inBall() - o};
        if (i % 4 == 0)
            ray.dir = Vec3(0.0, i % 8 ? 1.0 : -1.0, 0.0);  // parallel to the axis, off it
        if (i % 4 == 0 && ray.origin.x == 0 && ray.origin.z == 0) continue;
        SpanList s;
        needle->spans(ray, 0.0, kInf, ctx, s);
        CAPTURE(i);
        checkFinite(s);
        CHECK(s.empty());
    }
    // Exactly along the axis the closed segment is inside: a span no wider than the segment,
    // finite, or none.
    SpanList s;
    needle->spans(Ray{Vec3(0.0, -5.0, 0.0), Vec3(-0.0, 1.0, 0.0)}, 0.0, kInf, ctx, s);
    checkFinite(s);
    for (const Span& sp : s) {
        CHECK(sp.in.t >= 4.0);
        CHECK(sp.out.t <= 6.0);
    }
}

namespace {

/// Rays at a sphere of radius s centred at s·(1, 0.5, −0.25), from distance 6s, with
/// unit-sized directions (t of order 1). Counts agreement with the long-double oracle.
struct ExtremeTally {
    int hits = 0, misses = 0, missedHits = 0, falseHits = 0;
};

ExtremeTally traceExtreme(double s, uint64_t seed) {
    Random rng(seed);
    const Vec3 c = s * Vec3(1.0, 0.5, -0.25);
    const SceneGeometry scene({makeSphere(c, s)});
    TraceContext ctx;
    ExtremeTally tally;
    for (int i = 0; i < 500; ++i) {
        const Vec3 o = c + s * 6.0 * rng.unitVector();
        const Ray ray{o, (c + s * 1.3 * rng.inBall() - o) / s};
        const SphereOracle ref = sphereOracle(ray, ld(c), s);
        const auto hit = scene.nearestHit(ray, 0.0, kInf, ctx);
        CAPTURE(s, i, double(ref.margin));
        if (hit) {
            // Never a NaN or infinite distance, nor a non-finite normal, for a hit.
            REQUIRE(std::isfinite(hit->t));
            CHECK(std::isfinite(glm::dot(hit->normal, hit->normal)));
        }
        if (std::fabs(ref.margin) < 1e-9) continue;  // grazing: not the point here
        if (hit && ref.hit()) {
            ++tally.hits;
            CHECK(relativeError(hit->t, ref.tIn()) <= 1e-12L);
        } else if (hit) {
            ++tally.falseHits;
        } else if (ref.hit()) {
            ++tally.missedHits;
        } else {
            ++tally.misses;
        }
    }
    return tally;
}

}  // namespace

TEST_CASE("Spheres at 1e±300: accurate hits or clean misses, never NaN") {
    // As the issue words it: a hit within 1e-12 relative, or a clean miss. At 1e150 and
    // 1e-150 every ray must also agree with the oracle.
    for (double s : {1e300, 1e-300, 1e150, 1e-150}) {
        const ExtremeTally t = traceExtreme(s, 703);
        INFO("scale " << s << ": " << t.hits << " hits, " << t.misses << " misses, " << t.missedHits
                      << " hits missed, " << t.falseHits << " false hits");
        CHECK(t.falseHits == 0);
        if (std::fabs(std::log10(s)) < 200) {
            CHECK(t.missedHits == 0);
            CHECK(t.hits > 100);
        }
    }
}

// Squaring coordinates of 1e±300 overflows or underflows; the sphere rescales such rays by
// powers of two (exact) first. A regression test: every hit was once missed at these scales.
TEST_CASE("Spheres at 1e±300: every hit found", "[extremes]") {
    for (double s : {1e300, 1e-300}) {
        const ExtremeTally t = traceExtreme(s, 704);
        INFO("scale " << s << ": " << t.hits << " hits, " << t.missedHits << " hits missed");
        CHECK(t.missedHits == 0);
        CHECK(t.hits > 100);
    }
}
