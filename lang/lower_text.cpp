// Lowering: `text { string "kerf" font "DejaVu Sans" size 1 halign center valign baseline
// spacing 1 }`, a 2-D profile whose outline is the font's glyphs, laid out by the asset
// provider (scene/assets.h). The font is looked up now, so a missing font or character is an
// error at its property.
#include "csg/profiles/profile.h"
#include "lang/lower.h"

#include <filesystem>

namespace kerf {

std::optional<TextShape> Lowering::lowerText(const Solid& s) {
    const PropertyBlock b(s.properties,
                          {{"string", PropertyType::Word, true},
                           {"font", PropertyType::Word},
                           {"size", PropertyType::Number},
                           {"halign", PropertyType::Word},
                           {"valign", PropertyType::Word},
                           {"spacing", PropertyType::Number}},
                          "text", s.loc, mSink);
    bool ok = b.ok();
    TextRequest spec;
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
    spec.halign = halign == "center"  ? TextRequest::HAlign::Center
                  : halign == "right" ? TextRequest::HAlign::Right
                                      : TextRequest::HAlign::Left;
    spec.valign = valign == "top"      ? TextRequest::VAlign::Top
                  : valign == "center" ? TextRequest::VAlign::Center
                  : valign == "bottom" ? TextRequest::VAlign::Bottom
                                       : TextRequest::VAlign::Baseline;

    // A font file is relative to the model file's folder, as meshes and textures are.
    const Property* fontProp = b.find("font");
    const SourcePos fontAt = fontProp ? fontProp->valueLoc() : s.loc;
    spec.folder = std::filesystem::path(*mSink.locate(fontAt).file).parent_path().string();
    Loaded<TextShape> text = mAssets.text(spec);
    if (!text) {
        if (text.error.skipped) return std::nullopt;
        // Font lookups are errors at the font; bad characters and UTF-8 at the string.
        error(
            text.error.subject == AssetError::Subject::File ? fontAt : b.find("string")->valueLoc(),
            text.error.reason, text.error.hint);
        return std::nullopt;
    }
    if (text.value->shape.loops.empty()) {
        error(b.find("string")->valueLoc(), "text '" + spec.text + "' has no visible glyph");
        return std::nullopt;
    }
    return *text.value;
}

std::optional<Profile> Lowering::textProfile(const Solid& s) {
    std::optional<TextShape> text = lowerText(s);
    if (!text) return std::nullopt;
    // One even-odd path is the text exactly when no two glyphs share a point; else the
    // overlap would be a hole, so the glyphs are joined by a union.
    if (!text->glyphsOverlap) return profilePath(std::move(text->shape));
    std::vector<Profile> parts;
    for (PathShape& glyph : text->glyphs) parts.push_back(profilePath(std::move(glyph)));
    return profileUnion(std::move(parts));
}

}  // namespace kerf
