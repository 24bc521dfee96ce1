// Lowering, part 6: solid textures (`pattern KIND { a … b … } transforms` in a material),
// and image textures (`pattern image { file "…" mapping … } transforms`), whose file is
// opened now (by the asset provider, scene/assets.h) so a bad one is an error at its `file`
// property before anything renders.
#include "lang/lower.h"

#include "lang/names.h"

#include <cmath>

namespace kerf {

namespace {

const std::vector<std::pair<std::string, Pattern::Kind>>& patternKinds() {
    static const std::vector<std::pair<std::string, Pattern::Kind>> kinds = {
        {"checker", Pattern::Kind::Checker}, {"stripes", Pattern::Kind::Stripes},
        {"rings", Pattern::Kind::Rings},     {"gradient", Pattern::Kind::Gradient},
        {"noise", Pattern::Kind::Noise},     {"turbulence", Pattern::Kind::Turbulence},
        {"image", Pattern::Kind::Image}};
    return kinds;
}

const std::vector<std::pair<std::string, ImageMap::Mapping>>& mappings() {
    static const std::vector<std::pair<std::string, ImageMap::Mapping>> m = {
        {"planar", ImageMap::Mapping::Planar},
        {"spherical", ImageMap::Mapping::Spherical},
        {"cylindrical", ImageMap::Mapping::Cylindrical},
        {"box", ImageMap::Mapping::Box}};
    return m;
}

}  // namespace

std::shared_ptr<const Pattern> Lowering::lowerPattern(const Solid& s) {
    if (!enter(s.loc)) return nullptr;
    struct Leave {
        int& depth;
        ~Leave() { --depth; }
    } leave{mDepth};
    auto pattern = std::make_shared<Pattern>();
    std::vector<std::string> names;
    bool known = false;
    for (const auto& [name, kind] : patternKinds()) {
        names.push_back(name);
        if (s.name == name) pattern->kind = kind, known = true;
    }
    if (s.kind != Solid::Kind::Primitive || !known) {
        const std::string hint = didYouMean(s.name, names);
        error(s.loc, "unknown pattern '" + s.name + "'",
              hint.empty() ? "the patterns are " + joinNames(names) : hint);
        return nullptr;
    }
    const bool noisy =
        pattern->kind == Pattern::Kind::Noise || pattern->kind == Pattern::Kind::Turbulence;
    const bool image = pattern->kind == Pattern::Kind::Image;
    std::vector<PropertySpec> specs;
    if (image) {  // the file's value is a string, checked by lowerImage (Word only names it)
        specs = {{"file", PropertyType::Word, true}, {"mapping", PropertyType::Word}};
    } else {
        specs = {{"a", PropertyType::Vector}, {"b", PropertyType::Vector}};
    }
    if (noisy) specs.push_back({"seed", PropertyType::Number});
    if (pattern->kind == Pattern::Kind::Turbulence)
        specs.push_back({"octaves", PropertyType::Number});
    const PropertyBlock b(s.properties, specs, s.name + " pattern", s.loc, mSink);
    bool ok = b.ok();
    pattern->b.color = Vec3(1.0);  // black to white unless told
    if (image) ok = ok && lowerImage(b, *pattern);
    for (Pattern::Entry* entry : {&pattern->a, &pattern->b}) {
        if (image) break;
        const char* name = entry == &pattern->a ? "a" : "b";
        const Property* p = b.find(name);
        if (p && p->solid) {
            entry->pattern = lowerPattern(*p->solid);
            ok &= entry->pattern != nullptr;
        } else if (readVector(b, name, entry->color)) {
            if (p && !(entry->color.x >= 0 && entry->color.y >= 0 && entry->color.z >= 0)) {
                error(p->valueLoc(), "pattern colour " + std::string(name) +
                                         " must not have negative components, got " +
                                         formatVector(entry->color));
                ok = false;
            }
        } else {
            ok = false;
        }
    }
    int seed = 0;
    ok &= readInteger(b, "seed", 0, 1 << 30, seed);
    pattern->seed = uint64_t(seed);
    ok &= readInteger(b, "octaves", 1, 16, pattern->octaves);
    Affine map;
    for (const Modifier& m : s.modifiers) {
        if (m.kind == Modifier::Kind::Material) {
            error(m.loc, "a pattern takes no material", "the pattern is the material's colour");
            ok = false;
            continue;
        }
        if (m.kind == Modifier::Kind::Move || m.kind == Modifier::Kind::Spin ||
            m.kind == Modifier::Kind::Displace) {
            error(m.loc, "a pattern takes only translate, rotate, scale and matrix");
            ok = false;
            continue;
        }
        const auto t = modifierTransform(m);
        if (!t) {
            ok = false;
            continue;
        }
        map = t->after(map);
        if (!checkFolded(map, m)) ok = false;
    }
    if (!ok) return nullptr;
    pattern->toPattern = map.inverse();
    return pattern;
}

bool Lowering::lowerImage(const PropertyBlock& b, Pattern& pattern) {
    auto map = std::make_shared<ImageMap>();
    std::vector<std::string> names;
    for (const auto& [name, mapping] : mappings()) names.push_back(name);
    std::string mappingName = "planar";
    if (!readWord(b, "mapping", names, mappingName)) return false;
    for (const auto& [name, mapping] : mappings())
        if (name == mappingName) map->mapping = mapping;

    const Property* p = b.find("file");
    if (p == nullptr) return false;  // reported by the block
    const SourcePos at = p->valueLoc();
    std::optional<Value> v;
    if (p->expr)
        v = evaluate(*p->expr, nullptr);
    else
        error(at, "property 'file' of image pattern expects a file name in quotes, got a block");
    if (!v) return false;
    if (v->type != Value::Type::String) {
        error(at,
              "property 'file' of image pattern expects a file name in quotes, got " +
                  typeName(v->type),
              "write e.g. 'file \"wood.png\"'");
        return false;
    }
    const std::string& written = v->string();
    if (written.empty()) {
        error(at, "the image pattern's file name is empty");
        return false;
    }
    // Relative to the folder of the model file the property is written in, as includes are.
    const std::string path = resolvedPath(written, at);
    Loaded<Texture> texture = mAssets.texture(path);
    if (!texture) {
        if (texture.error.skipped) return false;  // the compile failed before: nothing opened
        if (texture.error.standalone)
            error(at, texture.error.reason);
        else
            error(
                at, "cannot read texture '" + written + "': " + texture.error.reason,
                path == written
                    ? std::string()
                    : "texture files are relative to the model file's folder; looked for " + path);
        return false;
    }
    map->texture = std::move(texture.value);
    map->path = path;
    pattern.image = std::move(map);
    return true;
}

}  // namespace kerf
