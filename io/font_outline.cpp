// Glyph outlines from FreeType (the only file that includes its headers), laid out along one
// line. Glyphs are loaded unscaled (FT_LOAD_NO_SCALE: integer font units, no hinting), so the
// only rounding is the one multiplication by size / units_per_EM per coordinate; with
// size = units_per_EM the outline is the font's own integers. FT_Outline_Decompose turns
// TrueType's implied on-curve points (the midpoint between two consecutive off-curve
// points) into explicit quadratic segments; CFF fonts give cubics.

#include "io/font_outline.h"

#include <ft2build.h>

#include "io/number_text.h"
#include "io/outline_overlap.h"
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace kerf {
namespace {

std::string codepointName(char32_t c) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "U+%04X", static_cast<unsigned>(c));
    return buf;
}

// Strict UTF-8: no overlong forms, no surrogates, nothing above U+10FFFF.
std::u32string decodeUtf8(const std::string& s) {
    std::u32string out;
    size_t i = 0;
    auto bad = [&](size_t at) {
        return FontError(FontError::Subject::Text,
                         "text is not valid UTF-8 (byte " + std::to_string(at + 1) + ")");
    };
    while (i < s.size()) {
        unsigned char b = static_cast<unsigned char>(s[i]);
        int n = b < 0x80           ? 0
                : (b >> 5) == 0x6  ? 1
                : (b >> 4) == 0xE  ? 2
                : (b >> 3) == 0x1E ? 3
                                   : -1;
        if (n < 0) throw bad(i);
        char32_t c = n == 0 ? b : n == 1 ? (b & 0x1F) : n == 2 ? (b & 0x0F) : (b & 0x07);
        for (int k = 1; k <= n; ++k) {
            if (i + k >= s.size()) throw bad(i);
            unsigned char t = static_cast<unsigned char>(s[i + k]);
            if ((t >> 6) != 0x2) throw bad(i + k);
            c = (c << 6) | (t & 0x3F);
        }
        static const char32_t minimum[] = {0, 0x80, 0x800, 0x10000};
        if (c < minimum[n] || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) throw bad(i);
        out.push_back(c);
        i += static_cast<size_t>(n) + 1;
    }
    return out;
}

// FreeType objects released in reverse order of creation whatever throws.
struct FreeTypeFace {
    FT_Library library = nullptr;
    FT_Face face = nullptr;
    ~FreeTypeFace() {
        if (face) FT_Done_Face(face);
        if (library) FT_Done_FreeType(library);
    }
};

// Collects one glyph's contours, placed at the pen position, in model units.
struct OutlineSink {
    PathShape shape;
    Vec2 pen{0.0, 0.0};  // in font units (integers and kerning sums, exact in double)
    double scale = 1.0;  // size / units_per_EM
    Vec2 start{}, last{};

    Vec2 map(const FT_Vector* v) const {
        return {(pen.x + static_cast<double>(v->x)) * scale,
                (pen.y + static_cast<double>(v->y)) * scale};
    }
    void add(PathSegment::Kind kind, std::initializer_list<Vec2> points) {
        PathSegment seg;
        seg.kind = kind;
        size_t i = 0;
        for (Vec2 p : points) seg.p[i++] = p;
        last = seg.end();
        shape.loops.back().segments.push_back(seg);
    }
    void closeLoop() {
        if (shape.loops.empty()) return;
        auto& segs = shape.loops.back().segments;
        if (!segs.empty() && last != start) add(PathSegment::Kind::Line, {last, start});
        if (segs.empty()) shape.loops.pop_back();
    }
};

int moveTo(const FT_Vector* to, void* user) {
    auto* s = static_cast<OutlineSink*>(user);
    s->closeLoop();
    s->shape.loops.emplace_back();
    s->start = s->last = s->map(to);
    return 0;
}
int lineTo(const FT_Vector* to, void* user) {
    auto* s = static_cast<OutlineSink*>(user);
    Vec2 p = s->map(to);
    if (p != s->last) s->add(PathSegment::Kind::Line, {s->last, p});  // no zero-length lines
    return 0;
}
int conicTo(const FT_Vector* control, const FT_Vector* to, void* user) {
    auto* s = static_cast<OutlineSink*>(user);
    s->add(PathSegment::Kind::Quadratic, {s->last, s->map(control), s->map(to)});
    return 0;
}
int cubicTo(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
    auto* s = static_cast<OutlineSink*>(user);
    s->add(PathSegment::Kind::Cubic, {s->last, s->map(c1), s->map(c2), s->map(to)});
    return 0;
}

void include(InkBounds& b, Vec2 p) {
    if (b.empty()) {
        b.lo = b.hi = p;
    } else {
        b.lo = glm::min(b.lo, p);
        b.hi = glm::max(b.hi, p);
    }
}
void include(InkBounds& b, const InkBounds& o) {
    if (o.empty()) return;
    include(b, o.lo);
    include(b, o.hi);
}

Vec2 quadraticAt(const PathSegment& s, double t) {
    double u = 1.0 - t;
    return u * u * s.p[0] + 2.0 * u * t * s.p[1] + t * t * s.p[2];
}
Vec2 cubicAt(const PathSegment& s, double t) {
    double u = 1.0 - t;
    return u * u * u * s.p[0] + 3.0 * u * u * t * s.p[1] + 3.0 * u * t * t * s.p[2] +
           t * t * t * s.p[3];
}

void translate(PathShape& shape, Vec2 d) {
    for (auto& loop : shape.loops) {
        for (auto& seg : loop.segments) {
            for (auto& p : seg.p) p += d;
        }
    }
}

}  // namespace

InkBounds segmentBounds(const PathSegment& s) {
    InkBounds b;
    include(b, s.start());
    include(b, s.end());
    switch (s.kind) {
        case PathSegment::Kind::Line: break;
        case PathSegment::Kind::Quadratic:
            // Per axis the derivative 2[(1-t)(p1-p0) + t(p2-p1)] vanishes once.
            for (int a = 0; a < 2; ++a) {
                double d = s.p[0][a] - 2.0 * s.p[1][a] + s.p[2][a];
                if (d != 0.0) {
                    double t = (s.p[0][a] - s.p[1][a]) / d;
                    if (t > 0.0 && t < 1.0) include(b, quadraticAt(s, t));
                }
            }
            break;
        case PathSegment::Kind::Cubic:
            // Per axis the derivative is the quadratic a t² + b t + c (up to the factor 3).
            for (int ax = 0; ax < 2; ++ax) {
                double p0 = s.p[0][ax], p1 = s.p[1][ax], p2 = s.p[2][ax], p3 = s.p[3][ax];
                double a = -p0 + 3.0 * p1 - 3.0 * p2 + p3, bb = 2.0 * (p0 - 2.0 * p1 + p2),
                       c = p1 - p0;
                double roots[2];
                int n = 0;
                if (a == 0.0) {
                    if (bb != 0.0) roots[n++] = -c / bb;
                } else {
                    double disc = bb * bb - 4.0 * a * c;
                    if (disc >= 0.0) {
                        double q = -0.5 * (bb + std::copysign(std::sqrt(disc), bb));
                        roots[n++] = q / a;
                        if (q != 0.0) roots[n++] = c / q;
                    }
                }
                for (int i = 0; i < n; ++i) {
                    if (roots[i] > 0.0 && roots[i] < 1.0) include(b, cubicAt(s, roots[i]));
                }
            }
            break;
        case PathSegment::Kind::Arc: {
            // The ends and the axis points of the circle that lie within the sweep.
            Vec2 c = s.p[2];
            double r = glm::length(s.p[0] - c);
            double a0 = std::atan2(s.p[0].y - c.y, s.p[0].x - c.x);
            double a1 = std::atan2(s.p[1].y - c.y, s.p[1].x - c.x);
            if (!s.ccw) std::swap(a0, a1);
            const double twoPi = 2.0 * M_PI;
            double sweep = std::fmod(a1 - a0 + 2.0 * twoPi, twoPi);
            if (sweep == 0.0) sweep = twoPi;  // same ends: a full turn
            for (int k = 0; k < 4; ++k) {
                double ang = k * 0.5 * M_PI;
                if (std::fmod(ang - a0 + 2.0 * twoPi, twoPi) <= sweep) {
                    include(b, c + r * Vec2(std::cos(ang), std::sin(ang)));
                }
            }
            break;
        }
    }
    return b;
}

namespace {

/// The text's code points, after checking the size, the spacing and that it is one line.
std::u32string checkedText(const TextSpec& spec) {
    if (!(std::isfinite(spec.size) && spec.size > 0.0)) {
        throw FontError(FontError::Subject::Text, "text size must be finite and greater than 0");
    }
    if (!(std::isfinite(spec.spacing) && spec.spacing > 0.0)) {
        throw FontError(FontError::Subject::Text, "text spacing must be finite and greater than 0");
    }
    std::u32string chars = decodeUtf8(spec.text);
    if (chars.size() > kMaxTextCharacters)
        throw FontError(FontError::Subject::Text, "text has " + std::to_string(chars.size()) +
                                                      " characters; one text may have at most " +
                                                      std::to_string(kMaxTextCharacters));
    for (char32_t c : chars) {
        if (c == U'\n' || c == U'\r')
            throw FontError(FontError::Subject::Text,
                            "text must be one line (it has a line break)");
    }
    return chars;
}

/// Opens the font's face with FreeType; it must have scalable outlines.
void openFace(FreeTypeFace& ft, const FontLocation& location, const TextSpec& spec) {
    if (FT_Init_FreeType(&ft.library) != 0)
        throw FontError(FontError::Subject::Font, "cannot initialise FreeType");
    if (FT_New_Face(ft.library, location.file.c_str(), location.index, &ft.face) != 0) {
        throw FontError(FontError::Subject::Font, "cannot read font file '" + location.file +
                                                      "' (for font '" + spec.font + "')");
    }
    if (!FT_IS_SCALABLE(ft.face) || ft.face->units_per_EM == 0) {
        throw FontError(FontError::Subject::Font, "font '" + spec.font + "' (" + location.file +
                                                      ") has no outlines (a bitmap font)");
    }
}

/// Refuses a layout whose pen or ink left the double range (size or spacing 1e308 drew part
/// of the text, the rest at infinity).
void checkFinite(const TextSpec& spec, const TextOutline& out) {
    const bool finite =
        std::isfinite(out.advance) &&
        (out.ink.empty() || (std::isfinite(out.ink.lo.x) && std::isfinite(out.ink.lo.y) &&
                             std::isfinite(out.ink.hi.x) && std::isfinite(out.ink.hi.y)));
    if (!finite)
        throw FontError(FontError::Subject::Text,
                        "text size " + exactNumber(spec.size) + " with spacing " +
                            exactNumber(spec.spacing) +
                            " is too large: the outline's coordinates would overflow");
}

/// Lays the glyphs out along the baseline, kerned and spaced; returns each inked glyph's bounds.
std::vector<InkBounds> layOutGlyphs(FT_Face face, const TextSpec& spec, const std::u32string& chars,
                                    TextOutline& out) {
    FT_Outline_Funcs funcs{};
    funcs.move_to = moveTo;
    funcs.line_to = lineTo;
    funcs.conic_to = conicTo;
    funcs.cubic_to = cubicTo;

    OutlineSink sink;
    sink.scale = spec.size / static_cast<double>(face->units_per_EM);
    // Coordinates are font units (integers) times the scale: below the smallest normal double
    // they would lose their precision, then vanish (size 1e-308 drew nothing).
    if (sink.scale < std::numeric_limits<double>::min())
        throw FontError(FontError::Subject::Text,
                        "text size " + exactNumber(spec.size) +
                            " is too small: the outline's coordinates would underflow");
    std::vector<InkBounds> glyphInk;
    FT_UInt previous = 0;
    for (char32_t c : chars) {
        FT_UInt index = FT_Get_Char_Index(face, c);
        if (index == 0) {
            throw FontError(FontError::Subject::Text, "font '" + spec.font + "' (" + out.fontFile +
                                                          ") has no glyph for " + codepointName(c));
        }
        if (previous != 0 && out.fontHasKerning) {
            FT_Vector kern{0, 0};
            if (FT_Get_Kerning(face, previous, index, FT_KERNING_UNSCALED, &kern) == 0) {
                sink.pen.x += spec.spacing * static_cast<double>(kern.x);
            }
        }
        if (FT_Load_Glyph(face, index, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) !=
                0 ||
            face->glyph->format != FT_GLYPH_FORMAT_OUTLINE) {
            throw FontError(FontError::Subject::Font, "font '" + spec.font + "' (" + out.fontFile +
                                                          "): cannot load the outline of " +
                                                          codepointName(c));
        }
        sink.shape.loops.clear();
        if (FT_Outline_Decompose(&face->glyph->outline, &funcs, &sink) != 0) {
            throw FontError(FontError::Subject::Font, "font '" + spec.font + "' (" + out.fontFile +
                                                          "): cannot read the outline of " +
                                                          codepointName(c));
        }
        sink.closeLoop();
        if (!sink.shape.loops.empty()) {
            InkBounds ink;
            for (const auto& loop : sink.shape.loops) {
                for (const auto& seg : loop.segments) include(ink, segmentBounds(seg));
            }
            glyphInk.push_back(ink);
            include(out.ink, ink);
            out.glyphs.push_back(std::move(sink.shape));
            sink.shape = PathShape{};
        }
        // With FT_LOAD_NO_SCALE the advance is in font units.
        sink.pen.x += spec.spacing * static_cast<double>(face->glyph->advance.x);
        previous = index;
    }
    out.advance = sink.pen.x * sink.scale;
    checkFinite(spec, out);
    return glyphInk;
}

/// Whether any two glyphs' outlines may overlap.
bool anyGlyphsOverlap(const std::vector<InkBounds>& glyphInk,
                      const std::vector<PathShape>& glyphs) {
    // Pairs whose ink bounds meet, by a sweep in x (a long line is not quadratic in its
    // length), then the exact test of their outlines.
    std::vector<size_t> order(glyphInk.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return glyphInk[a].lo.x < glyphInk[b].lo.x; });
    for (size_t k = 0; k < order.size(); ++k) {
        const InkBounds& a = glyphInk[order[k]];
        for (size_t m = k + 1; m < order.size() && glyphInk[order[m]].lo.x <= a.hi.x; ++m) {
            const InkBounds& b = glyphInk[order[m]];
            if (a.lo.y <= b.hi.y && b.lo.y <= a.hi.y &&
                outlinesMayOverlap(glyphs[order[k]], glyphs[order[m]]))
                return true;
        }
    }
    return false;
}

/// Moves the laid-out text so the anchor the alignment names is at the origin; returns the shift.
Vec2 alignText(const TextSpec& spec, TextOutline& out) {
    // Alignment: one translation of everything.
    Vec2 shift{0.0, 0.0};
    bool ink = !out.ink.empty();
    switch (spec.halign) {
        case TextSpec::HAlign::Left: break;
        case TextSpec::HAlign::Right: shift.x = -out.advance; break;
        case TextSpec::HAlign::Center:
            if (ink) shift.x = -0.5 * (out.ink.lo.x + out.ink.hi.x);
            break;
        case TextSpec::HAlign::AdvanceCenter: shift.x = -0.5 * out.advance; break;
    }
    switch (spec.valign) {
        case TextSpec::VAlign::Baseline: break;
        case TextSpec::VAlign::Top:
            if (ink) shift.y = -out.ink.hi.y;
            break;
        case TextSpec::VAlign::Bottom:
            if (ink) shift.y = -out.ink.lo.y;
            break;
        case TextSpec::VAlign::Center:
            if (ink) shift.y = -0.5 * (out.ink.lo.y + out.ink.hi.y);
            break;
    }
    if (shift != Vec2(0.0, 0.0)) {
        for (auto& g : out.glyphs) translate(g, shift);
        if (ink) {
            out.ink.lo += shift;
            out.ink.hi += shift;
        }
    }
    return shift;
}

}  // namespace

TextOutline layoutText(const TextSpec& spec) {
    const std::u32string chars = checkedText(spec);
    TextOutline out;
    const FontLocation location = findFont(spec.font, spec.acceptSubstitute);
    out.fontFile = location.file;
    out.substitutedFamily = location.substitutedFamily;
    FreeTypeFace ft;
    openFace(ft, location, spec);
    out.fontHasKerning = FT_HAS_KERNING(ft.face);
    const std::vector<InkBounds> glyphInk = layOutGlyphs(ft.face, spec, chars, out);
    out.glyphsOverlap = anyGlyphsOverlap(glyphInk, out.glyphs);
    out.penStart = alignText(spec, out).x;
    for (const auto& g : out.glyphs) {
        out.shape.loops.insert(out.shape.loops.end(), g.loops.begin(), g.loops.end());
    }
    return out;
}

PathShape textOutline(const TextSpec& spec) { return layoutText(spec).shape; }

}  // namespace kerf
