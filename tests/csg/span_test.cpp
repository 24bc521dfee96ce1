// The span algebra against its definition: a point is inside a op b iff op(inside a, inside b).
#include "csg/tree/span.h"

#include <catch2/catch.hpp>

#include <random>

using namespace kerf;

namespace {

Boundary bd(double t, uint32_t prim, Vec3 n = Vec3(1, 0, 0)) {
    Boundary b;
    b.t = t;
    b.primitive = prim;
    b.normal = n;
    return b;
}

SpanList spansOf(std::initializer_list<std::pair<double, double>> ranges, uint32_t prim) {
    SpanList s;
    for (auto [a, b] : ranges)
        s.push_back({bd(a, prim, Vec3(-1, 0, 0)), bd(b, prim, Vec3(1, 0, 0))});
    return s;
}

bool inside(const SpanList& s, double t) {
    for (const Span& x : s)
        if (x.in.t < t && t < x.out.t) return true;
    return false;
}

bool expected(BoolOp op, bool a, bool b) {
    switch (op) {
        case BoolOp::Union: return a || b;
        case BoolOp::Intersection: return a && b;
        case BoolOp::Difference: return a && !b;
        case BoolOp::Xor: return a != b;
    }
    return false;
}

SpanList randomSpans(std::mt19937_64& rng, uint32_t prim) {
    std::uniform_int_distribution<int> count(0, 6);
    std::uniform_int_distribution<int> grid(0, 40);  // a coarse grid makes coincident ends common
    std::vector<double> ts;
    const int n = 2 * count(rng);
    for (int i = 0; i < n; ++i) ts.push_back(grid(rng) * 0.25);
    std::sort(ts.begin(), ts.end());
    ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
    if (ts.size() % 2) ts.pop_back();
    SpanList s;
    for (size_t i = 0; i + 1 < ts.size(); i += 2)
        s.push_back({bd(ts[i], prim, Vec3(-1, 0, 0)), bd(ts[i + 1], prim, Vec3(1, 0, 0))});
    return s;
}

}  // namespace

TEST_CASE("combineSpans matches the point-wise definition", "[span]") {
    std::mt19937_64 rng(42);
    const BoolOp ops[] = {BoolOp::Union, BoolOp::Intersection, BoolOp::Difference, BoolOp::Xor};
    for (int trial = 0; trial < 2000; ++trial) {
        const SpanList a = randomSpans(rng, 1), b = randomSpans(rng, 2);
        for (BoolOp op : ops) {
            SpanList r;
            combineSpans(op, a, b, 1e-12, r);
            // Sorted, disjoint, non-degenerate.
            for (int i = 0; i < r.size(); ++i) {
                REQUIRE(r[i].in.t < r[i].out.t);
                if (i > 0) REQUIRE(r[i - 1].out.t < r[i].in.t);
            }
            // Sample between the grid points, where membership is unambiguous.
            for (double t = -0.125; t < 10.5; t += 0.25) {
                INFO("op " << int(op) << " trial " << trial << " t " << t);
                REQUIRE(inside(r, t) == expected(op, inside(a, t), inside(b, t)));
            }
        }
    }
}

TEST_CASE("combineSpans: coincident boundaries leave neither sliver nor seam", "[span]") {
    SECTION("difference whose cutter shares the body's entry face") {
        SpanList r;
        combineSpans(BoolOp::Difference, spansOf({{1, 5}}, 1), spansOf({{1, 3}}, 2), 1e-12, r);
        REQUIRE(r.size() == 1);
        CHECK(r[0].in.t == 3);
        CHECK(r[0].in.primitive == 2);
        CHECK(r[0].in.normal.x == -1);  // the cutter's exit normal (+x), flipped
        CHECK(r[0].out.primitive == 1);
    }
    SECTION("difference with the cutter equal to the body is empty") {
        SpanList r;
        combineSpans(BoolOp::Difference, spansOf({{1, 5}}, 1), spansOf({{1, 5}}, 2), 1e-12, r);
        CHECK(r.empty());
    }
    SECTION("union of abutting spans is one span") {
        SpanList r;
        combineSpans(BoolOp::Union, spansOf({{1, 2}}, 1), spansOf({{2, 3}}, 2), 1e-12, r);
        REQUIRE(r.size() == 1);
        CHECK(r[0].in.t == 1);
        CHECK(r[0].out.t == 3);
    }
    SECTION("union of spans abutting within rounding error is one span") {
        SpanList r;
        const double t = 2.0;
        combineSpans(BoolOp::Union, spansOf({{1, t}}, 1), spansOf({{std::nextafter(t, 3.0), 3}}, 2),
                     1e-12, r);
        REQUIRE(r.size() == 1);
    }
    SECTION("intersection of identical spans is that span") {
        SpanList r;
        combineSpans(BoolOp::Intersection, spansOf({{1, 2}, {4, 6}}, 1),
                     spansOf({{1, 2}, {4, 6}}, 2), 1e-12, r);
        REQUIRE(r.size() == 2);
        CHECK(r[0].in.t == 1);
        CHECK(r[1].out.t == 6);
    }
    SECTION("a cutter ending a few ulps inside the body leaves no sliver") {
        SpanList r;
        combineSpans(BoolOp::Difference, spansOf({{1, 5}}, 1),
                     spansOf({{std::nextafter(1.0, 2.0) + 1e-15, 3}}, 2), 1e-12, r);
        REQUIRE(r.size() == 1);
        CHECK(r[0].in.t == 3);
    }
}

TEST_CASE("combineSpans: xor flips the normals of boundaries inside the other operand", "[span]") {
    SpanList r;
    combineSpans(BoolOp::Xor, spansOf({{0, 4}}, 1), spansOf({{2, 6}}, 2), 1e-12, r);
    REQUIRE(r.size() == 2);
    CHECK(r[0].in.t == 0);
    CHECK(r[0].out.t == 2);
    CHECK(r[0].out.normal.x == 1);  // B's entry normal (-1) flipped: A ∖ B is left here
    CHECK(r[1].in.t == 4);
    CHECK(r[1].in.normal.x == -1);  // A's exit normal (+1) flipped
    CHECK(r[1].out.t == 6);
}

TEST_CASE("dropThinSpans: a span vanishes only within its boundaries' own error", "[span]") {
    auto rootFound = [](SpanList s, float relError) {
        for (Span& x : s) x.in.relError = x.out.relError = relError;
        return s;
    };
    for (double scale : {1e-6, 1.0, 1e6}) {
        // Root-found boundaries: thinner than the tolerance they carry (capped by the
        // caller's) vanishes, relative to |t| at every scale.
        SpanList s =
            rootFound(spansOf({{1 * scale, 1.000001 * scale}, {2 * scale, 3 * scale}}, 1), 1e-5f);
        dropThinSpans(s, 1e-5);
        REQUIRE(s.size() == 1);
        CHECK(s[0].in.t == 2 * scale);
        SpanList capped = rootFound(spansOf({{1 * scale, 1.000001 * scale}}, 1), 1e-5f);
        dropThinSpans(capped, 1e-7);
        CHECK(capped.size() == 1);
        // Closed-form boundaries (relError 0): a sheet 1e-9 thick survives any tolerance.
        SpanList sheet = spansOf({{1 * scale, (1 + 1e-9) * scale}}, 1);
        dropThinSpans(sheet, 1e-2);
        CHECK(sheet.size() == 1);
        // ... but not rounding noise.
        SpanList noise = spansOf({{1 * scale, (1 + 1e-15) * scale}}, 1);
        dropThinSpans(noise, 1e-2);
        CHECK(noise.empty());
    }
    SECTION("unbounded spans never vanish") {
        SpanList s;
        s.push_back({bd(-kInf, 1), bd(-1e300, 1)});
        dropThinSpans(s, 1e-3);
        CHECK(s.size() == 1);
    }
}

TEST_CASE("SpanList grows past its inline storage and copies deeply", "[span]") {
    SpanList s;
    for (int i = 0; i < 100; ++i) s.push_back({bd(2 * i, 1), bd(2 * i + 1, 1)});
    SpanList copy = s;
    s[0].in.t = -5;
    CHECK(copy.size() == 100);
    CHECK(copy[0].in.t == 0);
    CHECK(copy[99].out.t == 199);
    SpanList moved = std::move(copy);
    CHECK(moved.size() == 100);
    CHECK(copy.size() == 0);
}

TEST_CASE("fillMaterial: the innermost material wins", "[span]") {
    SpanList s = spansOf({{0, 1}}, 1);
    fillMaterial(s, 3);
    fillMaterial(s, 7);
    CHECK(s[0].in.material == 3);
    CHECK(s[0].out.material == 3);
}

TEST_CASE("combineSpans: a tie is decided by the boundaries, whichever operand comes first",
          "[span]") {
    // A clip (primitive 0) stands for a surface beyond the range it ends: where a surface
    // decides the result at the same t, the surface is kept.
    SpanList body = spansOf({{1, 4}}, 1), clipped = spansOf({{1, 3}}, 2);
    clipped[0].in = bd(1, 0, Vec3(0.0));
    SpanList r;
    for (bool swap : {false, true}) {
        INFO("swapped " << swap);
        combineSpans(BoolOp::Intersection, swap ? clipped : body, swap ? body : clipped, 1e-12, r);
        REQUIRE(r.size() == 1);
        CHECK(r[0].in.primitive == 1);  // the body's entry face, not the clip
        CHECK(r[0].out.primitive == 2);
        combineSpans(BoolOp::Union, swap ? clipped : body, swap ? body : clipped, 1e-12, r);
        REQUIRE(r.size() == 1);
        CHECK(r[0].in.primitive == 0);  // the clipped operand may reach before 1: still a clip
        CHECK(r[0].out.primitive == 1);
        // Two surfaces at the same t: the lower primitive id, in either order.
        combineSpans(BoolOp::Union, swap ? spansOf({{1, 3}}, 7) : spansOf({{1, 2}}, 5),
                     swap ? spansOf({{1, 2}}, 5) : spansOf({{1, 3}}, 7), 1e-12, r);
        REQUIRE(r.size() == 1);
        CHECK(r[0].in.primitive == 5);
    }
}
