// io/outline_overlap: closed-form cases (squares that are apart, touch, cross or nest; a
// circle of cubics) and glyph pairs against FreeType's rasteriser: a pixel fully covered by
// both glyphs means they overlap, no pixel touched by both means they do not.

#include "io/outline_overlap.h"

#include <ft2build.h>

#include <catch2/catch.hpp>

#include "io/font_outline.h"
#include FT_FREETYPE_H

#include <cmath>

using namespace kerf;

namespace {

PathShape square(Vec2 lo, double side) {
    PathLoop loop;
    const Vec2 c[4] = {lo, lo + Vec2(side, 0), lo + Vec2(side, side), lo + Vec2(0, side)};
    for (int i = 0; i < 4; ++i) {
        PathSegment s;
        s.kind = PathSegment::Kind::Line;
        s.p[0] = c[i];
        s.p[1] = c[(i + 1) % 4];
        loop.segments.push_back(s);
    }
    return PathShape{{loop}};
}

// A circle of four cubics (the usual 0.5523 handles): within 3e-4·r of the true circle.
PathShape circle(Vec2 centre, double r) {
    const double k = 0.5522847498 * r;
    PathLoop loop;
    const Vec2 d[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    for (int i = 0; i < 4; ++i) {
        const Vec2 a = d[i], b = d[(i + 1) % 4];
        PathSegment s;
        s.kind = PathSegment::Kind::Cubic;
        s.p = {centre + r * a, centre + r * a + k * b, centre + r * b + k * a, centre + r * b};
        loop.segments.push_back(s);
    }
    return PathShape{{loop}};
}

}  // namespace

TEST_CASE("outline_overlap::closed forms") {
    const PathShape unit = square({0, 0}, 1);
    CHECK_FALSE(outlinesMayOverlap(unit, square({1.5, 0}, 1)));  // apart
    CHECK(outlinesMayOverlap(unit, square({1.0, 0.2}, 1)));      // sharing part of an edge
    CHECK(outlinesMayOverlap(unit, square({0.5, 0.5}, 1)));      // crossing
    CHECK(outlinesMayOverlap(unit, square({0.25, 0.25}, 0.5)));  // nested: no edges meet
    CHECK(outlinesMayOverlap(square({0.25, 0.25}, 0.5), unit));
    // A circle of radius 1 at distance d from the square's corner (1, 1) along the diagonal:
    // they meet when d < 1 (the cubic circle is within 3e-4 of the true one).
    const Vec2 diag = glm::normalize(Vec2(1, 1));
    CHECK_FALSE(outlinesMayOverlap(unit, circle(Vec2(1, 1) + 1.01 * diag, 1.0)));
    CHECK(outlinesMayOverlap(unit, circle(Vec2(1, 1) + 0.99 * diag, 1.0)));
    // The scale does not matter.
    for (double s : {1e-6, 1e6}) {
        CHECK_FALSE(
            outlinesMayOverlap(square({0, 0}, s), circle(s * (Vec2(1, 1) + 1.01 * diag), s)));
        CHECK(outlinesMayOverlap(square({0, 0}, s), circle(s * (Vec2(1, 1) + 0.99 * diag), s)));
    }
    CHECK(insideEvenOdd(unit, {0.5, 0.5}));
    CHECK_FALSE(insideEvenOdd(unit, {1.5, 0.5}));
    CHECK(insideEvenOdd(circle({0, 0}, 1), {0.7, 0.7}));
    CHECK_FALSE(insideEvenOdd(circle({0, 0}, 1), {0.71, 0.71}));
}

TEST_CASE("outline_overlap::glyph pairs against FreeType") {
    struct Case {
        const char* font;
        char32_t a, b;
        double spacing;
    };
    const Case cases[] = {
        {"DejaVu Sans", U'A', U'V', 1.0},         {"DejaVu Sans", U'H', U'H', 0.3},
        {"DejaVu Sans", U'k', U'e', 1.0},         {"DejaVu Serif:italic", U'f', U'f', 1.0},
        {"DejaVu Serif:italic", U'f', U'j', 1.0}, {"DejaVu Sans", U'o', U'o', 0.5},
        {"DejaVu Sans", U'T', U'y', 1.0},         {"DejaVu Serif:italic", U'W', U'A', 1.0}};
    const int ppem = 300;
    int decisiveYes = 0, decisiveNo = 0;
    for (const Case& c : cases) {
        FT_Library lib;
        REQUIRE(FT_Init_FreeType(&lib) == 0);
        FT_Face face;
        REQUIRE(FT_New_Face(lib, findFontFile(c.font).c_str(), 0, &face) == 0);
        REQUIRE(FT_Set_Pixel_Sizes(face, 0, ppem) == 0);
        const FT_UInt ga = FT_Get_Char_Index(face, c.a), gb = FT_Get_Char_Index(face, c.b);
        FT_Vector kern{0, 0};
        FT_Get_Kerning(face, ga, gb, FT_KERNING_UNSCALED, &kern);
        REQUIRE(FT_Load_Glyph(face, ga, FT_LOAD_NO_SCALE) == 0);
        const double pen = c.spacing * double(face->glyph->advance.x + kern.x) * ppem /
                           face->units_per_EM;  // pixels

        // Coverage of each glyph on a common grid, the second shifted by the pen (26.6).
        const int W = 3 * ppem, H = 2 * ppem, ox = ppem / 2, oy = 3 * ppem / 2;
        std::vector<unsigned char> cover[2] = {std::vector<unsigned char>(W * H, 0),
                                               std::vector<unsigned char>(W * H, 0)};
        for (int k = 0; k < 2; ++k) {
            FT_Vector delta{k == 0 ? 0 : FT_Pos(std::lround(pen * 64)), 0};
            FT_Set_Transform(face, nullptr, &delta);
            REQUIRE(FT_Load_Glyph(face, k == 0 ? ga : gb, FT_LOAD_NO_HINTING | FT_LOAD_RENDER) ==
                    0);
            const FT_GlyphSlot g = face->glyph;
            bool onGrid = true;
            for (unsigned j = 0; j < g->bitmap.rows; ++j) {
                for (unsigned i = 0; i < g->bitmap.width; ++i) {
                    const int x = ox + g->bitmap_left + int(i), y = oy - g->bitmap_top + int(j);
                    if (x < 0 || x >= W || y < 0 || y >= H) {
                        onGrid = false;
                        continue;
                    }
                    cover[k][y * W + x] = g->bitmap.buffer[j * g->bitmap.pitch + i];
                }
            }
            REQUIRE(onGrid);
        }
        bool bothFull = false, bothAny = false;
        for (int i = 0; i < W * H; ++i) {
            bothFull |= cover[0][i] == 255 && cover[1][i] == 255;
            bothAny |= cover[0][i] > 0 && cover[1][i] > 0;
        }
        FT_Done_Face(face);
        FT_Done_FreeType(lib);

        TextSpec spec;
        spec.font = c.font;
        spec.spacing = c.spacing;
        spec.text = std::string(1, char(c.a)) + char(c.b);
        const bool ours = layoutText(spec).glyphsOverlap;
        INFO(c.font << " '" << char(c.a) << char(c.b) << "' spacing " << c.spacing
                    << ": FreeType pixels covered fully by both " << bothFull << ", partly by both "
                    << bothAny << "; ours " << ours);
        if (bothFull) {
            CHECK(ours);
            ++decisiveYes;
        } else if (!bothAny) {
            CHECK_FALSE(ours);
            ++decisiveNo;
        }
    }
    // The oracle decided both ways at least once (the cases are not all borderline).
    CHECK(decisiveYes >= 2);
    CHECK(decisiveNo >= 2);
}
