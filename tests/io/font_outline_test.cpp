// io/font_outline: glyph outlines against FreeType's own rasteriser (the oracle), kerning and
// advances against the font's tables read directly, alignment against FT_Outline_Get_BBox
// (exact Bézier bounds), and the error messages.

#include "io/font_outline.h"

#include <ft2build.h>

#include <catch2/catch.hpp>
#include FT_FREETYPE_H
#include FT_OUTLINE_H
#include FT_BBOX_H

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>

using namespace kerf;

namespace {

Vec2 pointAt(const PathSegment& s, double t) {
    double u = 1.0 - t;
    switch (s.kind) {
        case PathSegment::Kind::Line: return u * s.p[0] + t * s.p[1];
        case PathSegment::Kind::Quadratic:
            return u * u * s.p[0] + 2 * u * t * s.p[1] + t * t * s.p[2];
        case PathSegment::Kind::Cubic:
            return u * u * u * s.p[0] + 3 * u * u * t * s.p[1] + 3 * u * t * t * s.p[2] +
                   t * t * t * s.p[3];
        case PathSegment::Kind::Arc: break;
    }
    FAIL("glyph outlines have no arcs");
    return {};
}

// Parameters where y'(t) = 0 inside (0, 1), sorted, with 0 and 1: y is monotone between them.
std::vector<double> yMonotoneBreaks(const PathSegment& s) {
    std::vector<double> t{0.0, 1.0};
    auto keep = [&](double r) {
        if (r > 0.0 && r < 1.0) t.push_back(r);
    };
    if (s.kind == PathSegment::Kind::Quadratic) {
        double d = s.p[0].y - 2 * s.p[1].y + s.p[2].y;
        if (d != 0.0) keep((s.p[0].y - s.p[1].y) / d);
    } else if (s.kind == PathSegment::Kind::Cubic) {
        double p0 = s.p[0].y, p1 = s.p[1].y, p2 = s.p[2].y, p3 = s.p[3].y;
        long double a = -p0 + 3.0L * p1 - 3.0L * p2 + p3, b = 2.0L * (p0 - 2.0L * p1 + p2),
                    c = p1 - p0;
        if (a == 0) {
            if (b != 0) keep(static_cast<double>(-c / b));
        } else {
            long double disc = b * b - 4 * a * c;
            if (disc >= 0) {
                keep(static_cast<double>((-b - std::sqrt(disc)) / (2 * a)));
                keep(static_cast<double>((-b + std::sqrt(disc)) / (2 * a)));
            }
        }
    }
    std::sort(t.begin(), t.end());
    return t;
}

// Even-odd inside test by counting crossings of the ray from q towards +x: each y-monotone
// piece crosses the line y = q.y at most once (half-open in y, so a shared end counts once),
// found by bisection to the last bit.
bool oracleInside(const PathShape& shape, Vec2 q) {
    int crossings = 0;
    for (const auto& loop : shape.loops) {
        for (const auto& seg : loop.segments) {
            std::vector<double> br = yMonotoneBreaks(seg);
            for (size_t i = 0; i + 1 < br.size(); ++i) {
                double t0 = br[i], t1 = br[i + 1];
                double y0 = pointAt(seg, t0).y, y1 = pointAt(seg, t1).y;
                if (y0 == y1) continue;
                bool up = y0 < y1;
                if (!(up ? (y0 <= q.y && q.y < y1) : (y1 <= q.y && q.y < y0))) continue;
                for (int k = 0; k < 80; ++k) {
                    double tm = 0.5 * (t0 + t1);
                    if ((pointAt(seg, tm).y <= q.y) == up)
                        t0 = tm;
                    else
                        t1 = tm;
                }
                if (pointAt(seg, 0.5 * (t0 + t1)).x > q.x) ++crossings;
            }
        }
    }
    return crossings % 2 == 1;
}

// Distance from q to the outline, by dense sampling (an upper bound close to the truth).
double distanceToOutline(const PathShape& shape, Vec2 q) {
    double best = INFINITY;
    for (const auto& loop : shape.loops) {
        for (const auto& seg : loop.segments) {
            for (int i = 0; i <= 2000; ++i)
                best = std::min(best, glm::length(pointAt(seg, i / 2000.0) - q));
        }
    }
    return best;
}

struct Ft {
    FT_Library lib = nullptr;
    FT_Face face = nullptr;
    explicit Ft(const std::string& file) {
        REQUIRE(FT_Init_FreeType(&lib) == 0);
        REQUIRE(FT_New_Face(lib, file.c_str(), 0, &face) == 0);
    }
    ~Ft() {
        FT_Done_Face(face);
        FT_Done_FreeType(lib);
    }
};

const char* const kFont = "DejaVu Sans";

// Renders `utf8` (one character) with FreeType at `ppem` pixels per em, anti-aliased and
// unhinted, and compares each pixel centre with the even-odd test of our outline at the
// same size in model units = pixels. Fully covered pixels must be inside, empty ones
// outside, except within a pixel of the outline (FreeType rounds points to 1/64 pixel).
void compareWithFreeTypeRaster(const std::string& utf8, char32_t code, int ppem) {
    TextSpec spec;
    spec.text = utf8;
    spec.font = kFont;
    spec.size = ppem;
    PathShape shape = textOutline(spec);
    REQUIRE(!shape.loops.empty());

    Ft ft(findFontFile(kFont));
    REQUIRE(FT_Set_Pixel_Sizes(ft.face, 0, static_cast<FT_UInt>(ppem)) == 0);
    REQUIRE(FT_Load_Char(ft.face, code, FT_LOAD_NO_HINTING | FT_LOAD_RENDER) == 0);
    const FT_Bitmap& bm = ft.face->glyph->bitmap;
    REQUIRE(bm.pixel_mode == FT_PIXEL_MODE_GRAY);
    REQUIRE(bm.rows > 10);

    const int margin = 3;
    int checked = 0, inside = 0, mismatches = 0, far = 0;
    double worst = 0.0;
    std::string firstFar;
    for (int j = -margin; j < static_cast<int>(bm.rows) + margin; ++j) {
        for (int i = -margin; i < static_cast<int>(bm.width) + margin; ++i) {
            bool inBitmap =
                i >= 0 && j >= 0 && i < static_cast<int>(bm.width) && j < static_cast<int>(bm.rows);
            int cov = inBitmap ? bm.buffer[j * bm.pitch + i] : 0;
            if (cov != 0 && cov != 255) continue;  // the outline crosses this pixel
            Vec2 q{ft.face->glyph->bitmap_left + i + 0.5, ft.face->glyph->bitmap_top - j - 0.5};
            bool ours = oracleInside(shape, q);
            ++checked;
            inside += ours;
            if (ours != (cov == 255)) {
                ++mismatches;
                double d = distanceToOutline(shape, q);
                worst = std::max(worst, d);
                if (d >= 1.0 && far++ == 0) {
                    firstFar = "pixel (" + std::to_string(i) + ", " + std::to_string(j) +
                               ") coverage " + std::to_string(cov) + " at distance " +
                               std::to_string(d) + " from the outline";
                }
            }
        }
    }
    INFO(utf8 << ": " << checked << " pixels checked, " << inside << " inside, " << mismatches
              << " mismatches, farthest " << worst << " px from the outline");
    INFO("first mismatch farther than a pixel: " << firstFar);
    CHECK(far == 0);
    CHECK(inside > 100);
    CHECK(mismatches <= checked / 1000);
}

// Every loop is closed and continuous exactly (the implied on-points of TrueType conics
// become shared segment ends).
void checkClosed(const PathShape& shape) {
    for (const auto& loop : shape.loops) {
        REQUIRE(!loop.segments.empty());
        for (size_t i = 0; i < loop.segments.size(); ++i) {
            const auto& next = loop.segments[(i + 1) % loop.segments.size()];
            CHECK(loop.segments[i].end() == next.start());
        }
    }
}

/// layoutText's error with its subject first ("font: …" or "text: …"), or "(no error)".
std::string layoutError(const TextSpec& spec) {
    try {
        layoutText(spec);
    } catch (const FontError& e) {
        return (e.subject == FontError::Subject::Font ? "font: " : "text: ") +
               std::string(e.what());
    }
    return "(no error)";
}

}  // namespace

TEST_CASE("font_outline::glyphs match FreeType's rasteriser") {
    compareWithFreeTypeRaster("H", U'H', 400);
    compareWithFreeTypeRaster("o", U'o', 400);
    // Non-ASCII from UTF-8: é (two bytes), a composite glyph (e + acute) in DejaVu Sans.
    compareWithFreeTypeRaster("\xC3\xA9", U'\u00E9', 400);
}

TEST_CASE("font_outline::outlines are the font's points, exactly") {
    std::string file = findFontFile(kFont);
    Ft ft(file);
    const double upem = ft.face->units_per_EM;
    TextSpec spec;
    spec.font = kFont;
    spec.size = upem;  // one model unit per font unit: no rounding at all
    SECTION("H is lines between the font's integer points") {
        spec.text = "H";
        PathShape shape = textOutline(spec);
        REQUIRE(FT_Load_Char(ft.face, 'H', FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING) == 0);
        const FT_Outline& o = ft.face->glyph->outline;
        std::set<std::pair<double, double>> fontPoints, ours;
        for (int k = 0; k < o.n_points; ++k)
            fontPoints.insert({double(o.points[k].x), double(o.points[k].y)});
        for (const auto& loop : shape.loops) {
            for (const auto& seg : loop.segments) {
                CHECK(seg.kind == PathSegment::Kind::Line);
                ours.insert({seg.p[0].x, seg.p[0].y});
            }
        }
        CHECK(shape.loops.size() == static_cast<size_t>(o.n_contours));
        CHECK(ours == fontPoints);
        checkClosed(shape);
    }
    SECTION("o is quadratics whose implied on-points are midpoints of off-curve points") {
        spec.text = "o";
        PathShape shape = textOutline(spec);
        REQUIRE(shape.loops.size() == 2);
        checkClosed(shape);
        int quadratics = 0, implied = 0;
        for (const auto& loop : shape.loops) {
            for (size_t i = 0; i < loop.segments.size(); ++i) {
                const auto& a = loop.segments[i];
                const auto& b = loop.segments[(i + 1) % loop.segments.size()];
                if (a.kind != PathSegment::Kind::Quadratic) continue;
                ++quadratics;
                if (b.kind == PathSegment::Kind::Quadratic && a.p[2] == 0.5 * (a.p[1] + b.p[1])) {
                    ++implied;
                }
            }
        }
        CHECK(quadratics >= 8);
        CHECK(implied > 0);
    }
}

TEST_CASE("font_outline::advances and kerning") {
    std::string file = findFontFile(kFont);
    Ft ft(file);
    const double upem = ft.face->units_per_EM;
    REQUIRE(FT_HAS_KERNING(ft.face));
    FT_UInt a = FT_Get_Char_Index(ft.face, 'A'), v = FT_Get_Char_Index(ft.face, 'V');
    FT_Vector kern{};
    REQUIRE(FT_Get_Kerning(ft.face, a, v, FT_KERNING_UNSCALED, &kern) == 0);
    REQUIRE(kern.x < 0);  // DejaVu Sans kerns A-V
    REQUIRE(FT_Load_Glyph(ft.face, a, FT_LOAD_NO_SCALE) == 0);
    double advA = ft.face->glyph->advance.x;
    REQUIRE(FT_Load_Glyph(ft.face, v, FT_LOAD_NO_SCALE) == 0);
    double advV = ft.face->glyph->advance.x;

    TextSpec spec;
    spec.font = kFont;
    spec.size = 3.0;
    spec.text = "AV";
    TextOutline av = layoutText(spec);
    CHECK(av.fontHasKerning);
    CHECK(av.advance == Approx((advA + advV + kern.x) * 3.0 / upem).epsilon(1e-15));
    CHECK(av.advance < (advA + advV) * 3.0 / upem);
    REQUIRE(av.glyphs.size() == 2);

    // The V is placed at A's advance plus the kerning: its leftmost point moves by exactly that.
    spec.text = "V";
    TextOutline vAlone = layoutText(spec);
    InkBounds vInAv;
    for (const auto& loop : av.glyphs[1].loops) {
        for (const auto& seg : loop.segments) {
            InkBounds b = segmentBounds(seg);
            if (vInAv.empty()) vInAv = b;
            vInAv.lo = glm::min(vInAv.lo, b.lo);
            vInAv.hi = glm::max(vInAv.hi, b.hi);
        }
    }
    CHECK(vInAv.lo.x - vAlone.ink.lo.x == Approx((advA + kern.x) * 3.0 / upem).epsilon(1e-12));

    // spacing scales advances and kerning alike; a space is pure advance.
    spec.text = "AV";
    spec.spacing = 1.5;
    CHECK(layoutText(spec).advance == Approx(1.5 * av.advance).epsilon(1e-15));
    spec.spacing = 1.0;
    spec.text = "A A";
    FT_Load_Char(ft.face, ' ', FT_LOAD_NO_SCALE);
    double advSpace = ft.face->glyph->advance.x;
    FT_Vector k1{}, k2{};
    FT_UInt sp = FT_Get_Char_Index(ft.face, ' ');
    FT_Get_Kerning(ft.face, a, sp, FT_KERNING_UNSCALED, &k1);
    FT_Get_Kerning(ft.face, sp, a, FT_KERNING_UNSCALED, &k2);
    TextOutline aa = layoutText(spec);
    CHECK(aa.glyphs.size() == 2);
    CHECK(aa.advance == Approx((2 * advA + advSpace + k1.x + k2.x) * 3.0 / upem).epsilon(1e-15));
}

TEST_CASE("font_outline::alignment") {
    std::string file = findFontFile(kFont);
    Ft ft(file);
    const double upem = ft.face->units_per_EM;
    REQUIRE(FT_Load_Char(ft.face, 'o', FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING) == 0);
    FT_BBox box;  // exact bounds of the Bézier outline, in font units
    REQUIRE(FT_Outline_Get_BBox(&ft.face->glyph->outline, &box) == 0);

    TextSpec spec;
    spec.font = kFont;
    spec.text = "o";
    spec.size = 2.0;
    const double s = spec.size / upem;
    TextOutline left = layoutText(spec);
    CHECK(left.ink.lo.x == Approx(box.xMin * s).epsilon(1e-12));
    CHECK(left.ink.hi.x == Approx(box.xMax * s).epsilon(1e-12));
    CHECK(left.ink.lo.y == Approx(box.yMin * s).epsilon(1e-12));
    CHECK(left.ink.hi.y == Approx(box.yMax * s).epsilon(1e-12));

    spec.halign = TextSpec::HAlign::Center;
    spec.valign = TextSpec::VAlign::Center;
    TextOutline c = layoutText(spec);
    CHECK(std::abs(c.ink.lo.x + c.ink.hi.x) <= 1e-12 * spec.size);
    CHECK(std::abs(c.ink.lo.y + c.ink.hi.y) <= 1e-12 * spec.size);
    // The shape moved with the bounds: its sampled extent is centred at 0 too.
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& loop : c.shape.loops) {
        for (const auto& seg : loop.segments) {
            for (int i = 0; i <= 200; ++i) {
                lo = std::min(lo, pointAt(seg, i / 200.0).x);
                hi = std::max(hi, pointAt(seg, i / 200.0).x);
            }
        }
    }
    CHECK(lo == Approx(c.ink.lo.x).margin(1e-6 * spec.size));
    CHECK(hi == Approx(c.ink.hi.x).margin(1e-6 * spec.size));

    spec.halign = TextSpec::HAlign::Right;
    spec.valign = TextSpec::VAlign::Top;
    TextOutline r = layoutText(spec);
    CHECK(r.penStart + r.advance == Approx(0.0).margin(1e-15));
    CHECK(r.ink.hi.y == Approx(0.0).margin(1e-15));
    spec.valign = TextSpec::VAlign::Bottom;
    CHECK(layoutText(spec).ink.lo.y == Approx(0.0).margin(1e-15));
}

TEST_CASE("font_outline::errors") {
    TextSpec spec;
    spec.text = "kerf";
    auto message = [&] { return layoutError(spec); };
    SECTION("a family fontconfig does not have is not silently substituted") {
        spec.font = "Kerf No Such Font";
        std::string m = message();
        CHECK_THAT(m, Catch::StartsWith("font: font 'Kerf No Such Font' is not installed"));
        CHECK_THAT(m, Catch::Contains("would substitute 'DejaVu"));
        CHECK_THAT(m, Catch::Contains("fc-list"));
    }
    SECTION("a font file that does not exist") {
        spec.font = "/nonexistent/kerf.ttf";
        CHECK_THAT(message(), Catch::Contains("'/nonexistent/kerf.ttf' does not exist"));
    }
    SECTION("a file that is not a font") {
        spec.font = KERF_SOURCE_DIR "/io/font_outline.h";
        CHECK_THAT(message(), Catch::StartsWith("font: cannot read font file"));
    }
    SECTION("a character the font has no glyph for") {
        spec.font = kFont;
        spec.text = "a\xE4\xB8\xAD";  // U+4E2D, a CJK ideograph DejaVu does not cover
        CHECK_THAT(message(),
                   Catch::StartsWith("text: ") && Catch::Contains("has no glyph for U+4E2D"));
    }
    SECTION("invalid UTF-8, line breaks, sizes") {
        spec.font = kFont;
        spec.text = "a\xC3";
        CHECK_THAT(message(), Catch::Contains("not valid UTF-8"));
        spec.text = "\xC0\xAF";  // an overlong '/'
        CHECK_THAT(message(), Catch::Contains("not valid UTF-8"));
        spec.text = "a\nb";
        CHECK_THAT(message(), Catch::Contains("one line"));
        spec.text = "a";
        spec.size = 0.0;
        CHECK_THAT(message(), Catch::Contains("size must be finite"));
        spec.size = 1.0;
        spec.spacing = NAN;
        CHECK_THAT(message(), Catch::Contains("spacing must be finite"));
    }
    SECTION("a style of an installed family is found; a style it lacks is an error") {
        CHECK_THAT(findFontFile("DejaVu Sans:bold"), Catch::Contains("Bold"));
        CHECK_THAT(findFontFile("DejaVu Sans:italic"), Catch::Contains("Oblique"));
        CHECK_THAT(findFontFile("DejaVu Sans:light"), Catch::Contains("ExtraLight"));
        spec.font = "DejaVu Serif:light";  // DejaVu Serif has no light face
        CHECK_THAT(message(),
                   Catch::StartsWith("font: font 'DejaVu Serif:light' has no such style"));
        spec.font = "DejaVu Sans Mono:light";
        CHECK_THAT(message(), Catch::Contains("has no such style"));
    }
}

TEST_CASE("font_outline::limits on the characters and on the size's range") {
    TextSpec spec;
    spec.font = kFont;
    auto message = [&] { return layoutError(spec); };
    SECTION("at most kMaxTextCharacters characters (a 1 MB string took 35 s and 8.3 GB)") {
        spec.text = std::string(kMaxTextCharacters, '.');
        CHECK(message() == "(no error)");
        spec.text += '.';
        CHECK(message() == "text: text has 10001 characters; one text may have at most 10000");
    }
    SECTION("a size or spacing whose outline leaves the double range") {
        spec.text = "kerf kerf";
        spec.size = 1e308;
        CHECK_THAT(message(), Catch::StartsWith("text: text size 1e+308 with spacing 1 is too "
                                                "large: the outline's coordinates would overflow"));
        spec.size = 1.0;
        spec.spacing = 1e308;
        CHECK_THAT(message(), Catch::Contains("is too large"));
        spec.spacing = 1.0;
        spec.size = 1e-308;
        CHECK_THAT(message(), Catch::StartsWith("text: text size 1e-308 is too small"));
    }
    SECTION("large and small sizes that stay in range are drawn, scaled exactly") {
        spec.text = "kerf";
        for (const double size : {1e300, 1e-300}) {
            spec.size = size;
            const TextOutline out = layoutText(spec);
            CHECK(std::isfinite(out.advance));
            CHECK(out.advance > 0.0);
            CHECK(out.glyphs.size() == 4);
        }
    }
}
