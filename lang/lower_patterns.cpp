// Lowering, part 6: solid textures (`pattern KIND { a … b … } transforms` in a material).
#include "lang/lower.h"

#include "lang/names.h"

#include <cmath>

namespace kerf {

namespace {

const std::vector<std::pair<std::string, Pattern::Kind>>& patternKinds() {
    static const std::vector<std::pair<std::string, Pattern::Kind>> kinds = {
        {"checker", Pattern::Kind::Checker},   {"stripes", Pattern::Kind::Stripes},
        {"rings", Pattern::Kind::Rings},       {"gradient", Pattern::Kind::Gradient},
        {"noise", Pattern::Kind::Noise},       {"turbulence", Pattern::Kind::Turbulence}};
    return kinds;
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
    const bool noisy = pattern->kind == Pattern::Kind::Noise || pattern->kind == Pattern::Kind::Turbulence;
    std::vector<PropertySpec> specs{{"a", PropertyType::Vector}, {"b", PropertyType::Vector}};
    if (noisy) specs.push_back({"seed", PropertyType::Number});
    if (pattern->kind == Pattern::Kind::Turbulence) specs.push_back({"octaves", PropertyType::Number});
    const PropertyBlock b(s.properties, specs, s.name + " pattern", s.loc, mSink);
    bool ok = b.ok();
    pattern->b.color = Vec3(1.0);  // black to white unless told
    for (Pattern::Entry* entry : {&pattern->a, &pattern->b}) {
        const char* name = entry == &pattern->a ? "a" : "b";
        const Property* p = b.find(name);
        if (p && p->solid) {
            entry->pattern = lowerPattern(*p->solid);
            ok &= entry->pattern != nullptr;
        } else if (readVector(b, name, entry->color)) {
            if (p && !(entry->color.x >= 0 && entry->color.y >= 0 && entry->color.z >= 0)) {
                error(p->valueLoc(), "pattern colour " + std::string(name) +
                                         " must not have negative components, got " + formatVector(entry->color));
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
        if (m.kind == Modifier::Kind::Move || m.kind == Modifier::Kind::Spin || m.kind == Modifier::Kind::Displace) {
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

}  // namespace kerf
