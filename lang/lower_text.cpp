// Lowering: `text { string "kerf" font "DejaVu Sans" size 1 halign center valign baseline
// spacing 1 }`, a 2-D profile whose outline is the font's glyphs (io/font_outline.h). The
// font is looked up now, so a missing font or character is an error at its property.
#include <filesystem>

#include "csg/profiles/profile.h"
#include "lang/lower.h"

namespace kerf {

std::optional<TextOutline> Lowering::lowerText(const Solid& s) {
    const PropertyBlock b(s.properties,
                          {{"string", PropertyType::Word, true},
                           {"font", PropertyType::Word},
                           {"size", PropertyType::Number},
                           {"halign", PropertyType::Word},
                           {"valign", PropertyType::Word},
                           {"spacing", PropertyType::Number}},
                          "text", s.loc, mSink);
    bool ok = b.ok();
    TextSpec spec;
    // A string property: its value must be a string (written in quotes or computed).
    auto readString = [&](const char* name, std::string& out) {
        const Property* p = b.find(name);
        if (!p) return true;
        if (p->solid || !p->expr) {
            error(p->loc, std::string("text's ") + name + " must be a string in quotes");
            return false;
        }
        const auto v = evaluate(*p->expr, nullptr);
        if (!v) return false;
        if (v->type != Value::Type::String) {
            error(p->valueLoc(),
                  std::string("text's ") + name + " expects a string, got " + typeName(v->type),
                  std::string("write e.g. '") + name + " \"kerf\"'");
            return false;
        }
        out = v->string();
        return true;
    };
    ok &= readString("string", spec.text);
    ok &= readString("font", spec.font);
    ok &= readNumber(b, "size", spec.size);
    ok &= readNumber(b, "spacing", spec.spacing);
    std::string halign = "left", valign = "baseline";
    ok &= readWord(b, "halign", {"left", "center", "right"}, halign);
    ok &= readWord(b, "valign", {"baseline", "top", "center", "bottom"}, valign);
    if (!ok) return std::nullopt;
    for (const char* name : {"size", "spacing"}) {
        const double v = std::string(name) == "size" ? spec.size : spec.spacing;
        if (!(v > 0.0)) {
            error(b.find(name)->valueLoc(),
                  std::string("text's ") + name + " must be greater than 0");
            return std::nullopt;
        }
    }
    spec.halign = halign == "center"  ? TextSpec::HAlign::Center
                  : halign == "right" ? TextSpec::HAlign::Right
                                      : TextSpec::HAlign::Left;
    spec.valign = valign == "top"      ? TextSpec::VAlign::Top
                  : valign == "center" ? TextSpec::VAlign::Center
                  : valign == "bottom" ? TextSpec::VAlign::Bottom
                                       : TextSpec::VAlign::Baseline;

    // A font file is relative to the model file's folder, as meshes and textures are.
    const Property* fontProp = b.find("font");
    const SourcePos fontAt = fontProp ? fontProp->valueLoc() : s.loc;
    if (isFontPath(spec.font) && !std::filesystem::path(spec.font).is_absolute()) {
        const std::filesystem::path model = *mSink.locate(fontAt).file;
        spec.font = (model.parent_path() / spec.font).lexically_normal().string();
    }
    try {
        TextOutline text = layoutText(spec);
        if (text.shape.loops.empty()) {
            error(b.find("string")->valueLoc(), "text '" + spec.text + "' has no visible glyph");
            return std::nullopt;
        }
        return text;
    } catch (const FontError& e) {
        // Font lookups are errors at the font; bad characters and UTF-8 at the string.
        error(e.subject == FontError::Subject::Font ? fontAt : b.find("string")->valueLoc(),
              e.message, e.hint);
        return std::nullopt;
    }
}

std::optional<Profile> Lowering::textProfile(const Solid& s) {
    std::optional<TextOutline> text = lowerText(s);
    if (!text) return std::nullopt;
    // One even-odd path is the text exactly when no two glyphs share a point; else the
    // overlap would be a hole, so the glyphs are joined by a union.
    if (!text->glyphsOverlap) return profilePath(std::move(text->shape));
    std::vector<Profile> parts;
    for (PathShape& glyph : text->glyphs) parts.push_back(profilePath(std::move(glyph)));
    return profileUnion(std::move(parts));
}

}  // namespace kerf
