// Image textures and font layouts (io/) as assets (assets/asset_loaders.h).
#include "assets/asset_loaders.h"

#include "io/font_outline.h"
#include "io/image.h"
#include "io/texture.h"

#include <cstring>
#include <filesystem>

namespace kerf {

namespace {

TextSpec specOf(const TextRequest& r) {
    TextSpec spec;
    spec.text = r.text;
    spec.font = r.font;
    // A relative font file is relative to the model file's folder, as meshes and textures are.
    if (isFontPath(spec.font) && !std::filesystem::path(spec.font).is_absolute())
        spec.font = (std::filesystem::path(r.folder) / spec.font).lexically_normal().string();
    spec.size = r.size;
    spec.spacing = r.spacing;
    spec.halign = TextSpec::HAlign(int(r.halign));
    spec.valign = TextSpec::VAlign(int(r.valign));
    spec.acceptSubstitute = r.acceptSubstitute;
    return spec;
}

// The enumerations are mapped by value: they must list the same choices in the same order.
static_assert(int(TextSpec::HAlign::AdvanceCenter) == int(TextRequest::HAlign::AdvanceCenter));
static_assert(int(TextSpec::VAlign::Bottom) == int(TextRequest::VAlign::Bottom));

}  // namespace

Loaded<Texture> loadTextureAsset(const std::string& path) {
    Loaded<Texture> r;
    try {
        r.value = Texture::open(path);
    } catch (const TextureError& e) {
        r.error.reason = e.reason;
    } catch (const ImageSupportError& e) {
        r.error.reason = e.what();
        r.error.standalone = true;
    }
    return r;
}

FontFile fontFileOf(const TextRequest& request) {
    const TextSpec spec = specOf(request);
    FontFile font;
    try {
        const FontLocation at = findFont(spec.font, spec.acceptSubstitute);
        font.file = at.file;
        font.key = spec.font + '\0' + std::to_string(at.index) + '\0' + spec.text + '\0';
    } catch (const FontError&) {
        return {};
    }
    char bits[2 * sizeof(double) + 3];
    std::memcpy(bits, &spec.size, sizeof(double));
    std::memcpy(bits + sizeof(double), &spec.spacing, sizeof(double));
    bits[2 * sizeof(double)] = char(spec.halign);
    bits[2 * sizeof(double) + 1] = char(spec.valign);
    bits[2 * sizeof(double) + 2] = char(spec.acceptSubstitute);
    font.key.append(bits, sizeof(bits));
    return font;
}

Loaded<TextShape> layoutTextAsset(const TextRequest& request) {
    Loaded<TextShape> r;
    try {
        TextOutline outline = layoutText(specOf(request));
        auto shape = std::make_shared<TextShape>();
        shape->glyphs = std::move(outline.glyphs);
        shape->shape = std::move(outline.shape);
        shape->glyphsOverlap = outline.glyphsOverlap;
        shape->substitutedFamily = std::move(outline.substitutedFamily);
        r.value = std::move(shape);
    } catch (const FontError& e) {
        r.error.reason = e.message;
        r.error.hint = e.hint;
        if (e.subject == FontError::Subject::Text) r.error.subject = AssetError::Subject::Part;
    }
    return r;
}

}  // namespace kerf
