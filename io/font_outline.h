/// @file io/font_outline.h
/// @brief Text as a 2-D outline: a line of UTF-8 text laid out with a font file's advance
/// widths and kerning, each glyph kept as the exact line / quadratic / cubic Bézier segments
/// the font stores (never flattened), scaled from font units to model units.
///
/// Fonts are files that are not models, so this lives in io/; FreeType and fontconfig are
/// used only by font_outline.cpp. The result is a csg PathShape (a header-only value type;
/// io links nothing of csg).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "csg/profiles/profile_path.h"

namespace kerf {

/// Thrown for a font that cannot be found or read, or a text it cannot draw. `message` names
/// the font (and the character, when one is missing); `hint` says what to do, if anything
/// (how to list the installed fonts). what() is both.
struct FontError : std::runtime_error {
    /// What is wrong: the font (lookup, file) or the text (its bytes, a missing glyph, size).
    enum class Subject { Font, Text };
    FontError(Subject subject, const std::string& message, const std::string& hint = {})
        : std::runtime_error(hint.empty() ? message : message + " (" + hint + ")"),
          subject(subject),
          message(message),
          hint(hint) {}
    Subject subject;
    std::string message;
    std::string hint;
};

/// The most characters one text may have (docs/robustness.md, "Limits"): each glyph costs
/// about 8 kB of outline and overlap tests, so the 1 MB string the language allows took 35 s
/// and 8.3 GB; 10,000 is several pages of one line, 80 MB and a fraction of a second.
constexpr size_t kMaxTextCharacters = 10000;

struct TextSpec {
    enum class HAlign { Left, Center, Right, AdvanceCenter };
    enum class VAlign { Baseline, Top, Center, Bottom };

    std::string text;                  ///< one line of UTF-8 (a newline is an error)
    std::string font = "DejaVu Sans";  ///< fontconfig pattern ("DejaVu Sans:bold") or a file path
    double size = 1.0;                 ///< the em height in model units (finite, > 0)
    /// Left: the pen starts at x = 0. Right: the pen ends at x = 0 (the kerned advance).
    /// Center: the ink bounds' centre at x = 0. AdvanceCenter: the middle of the kerned
    /// advance at x = 0 (OpenSCAD's `halign = "center"`).
    HAlign halign = HAlign::Left;
    /// Baseline: the baseline at y = 0. Top / Center / Bottom: the ink bounds' top, centre or
    /// bottom at y = 0.
    VAlign valign = VAlign::Baseline;
    double spacing = 1.0;  ///< multiplies every advance (and kerning): 1 sets the font as drawn
    /// Take the family fontconfig substitutes for one that is not installed (as OpenSCAD
    /// does) instead of refusing it; TextOutline::substitutedFamily then names it.
    bool acceptSubstitute = false;
};

/// Axis-aligned bounds in the plane; empty (lo > hi) when there is no ink.
struct InkBounds {
    Vec2 lo{1.0, 1.0}, hi{-1.0, -1.0};
    bool empty() const { return lo.x > hi.x; }
};

/// The laid-out text, placed by the alignment.
struct TextOutline {
    /// One PathShape per glyph with ink, in text order. Glyphs of one font never overlap
    /// their own contours, but neighbours can overlap once kerned (italics, tight pairs):
    /// see `glyphsOverlap`.
    std::vector<PathShape> glyphs;
    /// All glyphs' loops in one even-odd shape: the text exactly when !glyphsOverlap.
    PathShape shape;
    InkBounds ink;          ///< exact bounds of the curves (not of their control points)
    double penStart = 0.0;  ///< x where the pen starts (0 for Left)
    double advance = 0.0;   ///< the kerned, spaced advance of the whole line
    /// Whether two glyphs may share a point (io/outline_overlap.h: their outlines cross or
    /// touch, or one holds the other): then the even-odd `shape` would show the overlap as a
    /// hole, and a caller should take the union of `glyphs` instead.
    bool glyphsOverlap = false;
    std::string fontFile;           ///< the file the font came from
    std::string substitutedFamily;  ///< the family used instead of the one asked for, if any
    bool fontHasKerning = false;    ///< the font has a 'kern' table FreeType reads
};

/// Lays out `spec`. Throws FontError: a font fontconfig does not know or silently replaces
/// by another family (the message names both and says how to list fonts: `fc-list`), an
/// unreadable or non-scalable font file, invalid UTF-8, a newline, a character the font has
/// no glyph for, a size or spacing that is not finite and positive.
///
/// Kerning comes from the font's 'kern' table through FT_Get_Kerning (DejaVu Sans and
/// DejaVu Serif and most TrueType fonts have one); pairs that exist only in an OpenType GPOS
/// table are not applied (that needs a shaper such as HarfBuzz).
TextOutline layoutText(const TextSpec& spec);

/// `layoutText(spec).shape`.
PathShape textOutline(const TextSpec& spec);

/// A font face: a file, and the face's index within it (a collection, .ttc, holds several).
struct FontLocation {
    std::string file;
    int index = 0;
    std::string substitutedFamily;  ///< set when a substitute was accepted
};

/// The face fontconfig picks for `pattern` (or face 0 of `pattern` itself when it names a
/// file), the lookup layoutText does. Throws FontError as layoutText does, also for a style
/// the family lacks ("DejaVu Serif:light": fontconfig would give the Book face).
/// With `acceptSubstitute`, another family fontconfig picks is taken (and named in the
/// result) instead of being an error.
FontLocation findFont(const std::string& pattern, bool acceptSubstitute = false);
/// `findFont(pattern).file`.
std::string findFontFile(const std::string& pattern);

/// Whether `font` is taken as a file path rather than a fontconfig pattern: it has a '/' or
/// ends with a font file's extension (.ttf, .otf, .ttc, .pfb).
bool isFontPath(const std::string& font);

/// Exact bounds of a segment's curve (its ends and the extrema of its Bézier).
InkBounds segmentBounds(const PathSegment& segment);

}  // namespace kerf
