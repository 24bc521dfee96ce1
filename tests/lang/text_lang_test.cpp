// text { … } in the language: an extruded text's sign against the even-odd inside test of
// io/font_outline's own outline (itself tested against FreeType's rasteriser), overlapping
// glyphs joined by a union, and errors at the property at fault.
#include <catch2/catch.hpp>
#include <random>

#include "io/font_outline.h"
#include "io/outline_overlap.h"
#include "lang_test_util.h"

using namespace kerf;
using kerf::test::compileText;
using kerf::test::firstObject;
using kerf::test::requireOneError;

TEST_CASE("text: an extruded text is inside exactly where its outline is") {
    const NodePtr n = firstObject(
        "object extrude { profile text { string \"kerf é\" font \"DejaVu Sans\" size 2 halign "
        "center "
        "valign center } height 1 };");
    TextSpec spec;
    spec.text = "kerf \xC3\xA9";
    spec.size = 2;
    spec.halign = TextSpec::HAlign::Center;
    spec.valign = TextSpec::VAlign::Center;
    const TextOutline text = layoutText(spec);
    REQUIRE_FALSE(text.glyphsOverlap);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(text.ink.lo.x - 0.2, text.ink.hi.x + 0.2),
        v(text.ink.lo.y - 0.2, text.ink.hi.y + 0.2);
    int inside = 0, checked = 0;
    for (int i = 0; i < 4000; ++i) {
        const Vec2 q(u(rng), v(rng));
        const bool in = insideEvenOdd(text.shape, q);
        const double d = n->value(Vec3(q.x, 0.5, q.y));  // profiles are drawn in (x, z)
        if (std::abs(d) < 1e-9) continue;                // on the outline, within rounding
        ++checked;
        inside += in;
        INFO("u=" << q.x << " v=" << q.y << " value " << d);
        REQUIRE((d < 0) == in);
    }
    CHECK(inside > 200);
    CHECK(checked > 3900);
}

TEST_CASE("text: overlapping glyphs are joined, not cut out by the even-odd rule") {
    // Two H's 0.3 of an advance apart: the second's left stem lies on the first's crossbar.
    const NodePtr n =
        firstObject("object extrude { profile text { string \"HH\" spacing 0.3 } height 1 };");
    TextSpec spec;
    spec.text = "HH";
    spec.spacing = 0.3;
    const TextOutline text = layoutText(spec);
    REQUIRE(text.glyphsOverlap);
    REQUIRE(text.glyphs.size() == 2);
    int both = 0;
    for (double x = text.ink.lo.x; x < text.ink.hi.x; x += 0.005) {
        for (double y = text.ink.lo.y; y < text.ink.hi.y; y += 0.005) {
            const Vec2 q(x, y);
            const bool a = insideEvenOdd(text.glyphs[0], q), b = insideEvenOdd(text.glyphs[1], q);
            const double d = n->value(Vec3(x, 0.5, y));
            if (std::abs(d) < 1e-9) continue;
            INFO("u=" << x << " v=" << y << " in glyphs " << a << b << " value " << d);
            REQUIRE((d < 0) == (a || b));
            both += a && b;
        }
    }
    CHECK(both > 10);  // the overlap was sampled (the merged even-odd shape is outside there)
}

TEST_CASE("text: errors") {
    requireOneError(
        "object extrude { profile text { string \"a\" font \"Kerf No Such Font\" } height 1 };", 1,
        49, "font 'Kerf No Such Font' is not installed");
    requireOneError("object extrude { profile text { string \"a\xE4\xB8\xAD\" } height 1 };", 1, 40,
                    "has no glyph for U+4E2D");
    requireOneError("object extrude { profile text { string 3 } height 1 };", 1, 40,
                    "expects a string");
    requireOneError("object extrude { profile text { string \"a\" size 0 } height 1 };", 1, 49,
                    "text's size must be greater than 0");
    requireOneError("object extrude { profile text { string \"a\" halign middle } height 1 };", 1,
                    51, "unknown halign 'middle'");
    requireOneError("object extrude { profile text { string \" \" } height 1 };", 1, 40,
                    "has no visible glyph");
    requireOneError("object extrude { profile text { font \"DejaVu Sans\" } height 1 };", 1, 26,
                    "string");
}
