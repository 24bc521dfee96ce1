// Lowering, part 4b: `mist { … }`. Without a density it is the homogeneous mist (scene/scene.h
// Mist: colour and distance, the cheap special case). With `density EXPR` (in x, y, z) or
// `density volume "file.vdb" [grid "name"]` it is a heterogeneous medium (scene/medium.h):
// bounds, extinction, albedo, emission, g, method and step, samples, and `bake N` to trace an
// expression's density from bricked storage. The bake is only requested here (Medium::bake):
// render/ makes it when it prepares the medium, so `kerf check` bakes nothing.
#include "lang/lower.h"

#include "csg/tape/tape.h"

#include <cmath>

namespace kerf {
namespace {

/// A density written as an expression, compiled to a tape. The medium calls it from render
/// threads, never from inside a tape, so evaluating a tape here is safe (csg/tape/scalar_field.h).
class TapeDensity final : public ScalarField {
public:
    explicit TapeDensity(std::shared_ptr<const Tape> tape) : mTape(std::move(tape)) {}
    double value(const Vec3& p) const override { return mTape->eval(p); }
    long double valueExtended(const glm::tvec3<long double>& p) const override {
        return mTape->evalExtended(p);
    }
    double valueGradient(const Vec3& p, Vec3& gradient) const override {
        return mTape->evalGradient(p, gradient);
    }
    Interval range(const Interval& x, const Interval& y, const Interval& z) const override {
        return mTape->evalInterval(x, y, z);
    }
    double lipschitz() const override { return kInf; }

private:
    std::shared_ptr<const Tape> mTape;
};

/// A sub-box of `box` where the field's interval bound proves it negative, searched by
/// bisecting the boxes whose bound straddles 0 (at most `budget` range calls).
std::optional<Bounds3> provedNegative(const ScalarField& f, const Bounds3& box, int level,
                                      int& budget) {
    if (budget-- <= 0) return std::nullopt;
    const Interval r = f.range(Interval(box.lo.x, box.hi.x), Interval(box.lo.y, box.hi.y),
                               Interval(box.lo.z, box.hi.z));
    if (r.hi < 0.0) return box;
    if (!(r.lo < 0.0) || level >= 5) return std::nullopt;
    const Vec3 mid = box.center();
    for (int c = 0; c < 8; ++c) {
        Bounds3 sub;
        for (int a = 0; a < 3; ++a) {
            sub.lo[a] = (c >> a) & 1 ? mid[a] : box.lo[a];
            sub.hi[a] = (c >> a) & 1 ? box.hi[a] : mid[a];
        }
        if (auto found = provedNegative(f, sub, level + 1, budget)) return found;
    }
    return std::nullopt;
}

/// Range calls spent looking for negative density.
constexpr int kNegativeSearchBudget = 4096;

}  // namespace

void Lowering::lowerMist(const Statement& s, Scene& scene) {
    const PropertyBlock b(s.properties,
                          {{"color", PropertyType::Vector},
                           {"distance", PropertyType::Number},
                           {"density", PropertyType::Function},
                           {"bounds", PropertyType::Solid},
                           {"min", PropertyType::Vector},
                           {"max", PropertyType::Vector},
                           {"extinction", PropertyType::Number},
                           {"albedo", PropertyType::Vector},
                           {"emission", PropertyType::Vector},
                           {"g", PropertyType::Number},
                           {"method", PropertyType::Word},
                           {"step", PropertyType::Number},
                           {"samples", PropertyType::Number},
                           {"bake", PropertyType::Number}},
                          "mist", s.loc, mSink);
    if (!b.ok()) return;
    const Property* density = b.find("density");
    if (!density) return lowerUniformMist(b, s, scene);
    for (const char* name : {"distance", "color"})
        if (const Property* p = b.find(name)) {
            error(p->loc,
                  std::string("mist ") + name +
                      " is for uniform mist; a mist with a density takes " +
                      (name[0] == 'd' ? "extinction" : "albedo"),
                  "extinction scales the density into the extinction coefficient; albedo is the "
                  "colour scattered");
            return;
        }
    Medium medium;
    std::optional<Bounds3> bounds;
    if (!lowerMediumProperties(b, medium) || !lowerMistBounds(b, s, bounds)) return;
    const bool ok = density->solid ? lowerFogDensity(b, s, bounds, medium)
                                   : lowerExprDensity(b, bounds, medium);
    // A baked density is clamped at 0 and stored as finite floats: nothing left to check.
    if (!ok || (!medium.bake && !checkDensity(*density, medium))) return;
    scene.medium = std::move(medium);
}

void Lowering::lowerUniformMist(const PropertyBlock& b, const Statement& s, Scene& scene) {
    static const char* const kMediumOnly[] = {"bounds", "min",      "max", "extinction",
                                              "albedo", "emission", "g",   "method",
                                              "step",   "samples",  "bake"};
    Mist& mist = scene.mist;
    for (const char* name : kMediumOnly)
        if (const Property* p = b.find(name)) {
            error(p->loc, std::string("mist ") + name + " needs a density",
                  "write density EXPR bounds box { min … max … }, or use color and distance "
                  "for uniform mist");
            return;
        }
    if (!b.find("distance")) {
        error(s.loc, "mist needs a distance (uniform mist) or a density (a medium)",
              "write e.g. mist { color <0.8, 0.85, 0.9> distance 30 }");
        return;
    }
    bool ok = readVector(b, "color", mist.color);
    ok &= readNumber(b, "distance", mist.distance);
    if (!ok) return;
    if (!allNonNegative(mist.color))
        error(b.find("color")->valueLoc(),
              "mist color must not have negative components, got " + formatVector(mist.color));
    if (!(mist.distance > 0))
        error(b.find("distance")->valueLoc(),
              "mist distance must be positive, got " + formatNumber(mist.distance));
    mist.enabled = true;
}

bool Lowering::lowerMediumProperties(const PropertyBlock& b, Medium& medium) {
    bool ok = readNumber(b, "extinction", medium.extinction);
    ok &= readVector(b, "albedo", medium.albedo);
    ok &= readVector(b, "emission", medium.emission);
    ok &= readNumber(b, "g", medium.g);
    ok &= readNumber(b, "step", medium.step);
    ok &= readInteger(b, "samples", 1, 64, medium.samples);
    std::string method;
    ok &= readWord(b, "method", {"ratio", "delta", "march"}, method);
    if (!ok) return false;
    const auto at = [&](const char* name) { return b.find(name)->valueLoc(); };
    const auto fail = [&](SourcePos where, std::string message, std::string hint = {}) {
        error(where, std::move(message), std::move(hint));
        return false;
    };
    if (b.find("extinction") && !(medium.extinction >= 0 && std::isfinite(medium.extinction)))
        return fail(at("extinction"),
                    "mist extinction must be 0 or more, got " + formatNumber(medium.extinction),
                    "extinction per unit density per unit length");
    if (b.find("albedo") && !(allNonNegative(medium.albedo) && medium.albedo.x <= 1 &&
                              medium.albedo.y <= 1 && medium.albedo.z <= 1))
        return fail(at("albedo"),
                    "mist albedo must be within 0 to 1, got " + formatVector(medium.albedo),
                    "albedo is the fraction of extinguished light scattered, per channel");
    if (b.find("emission") &&
        !(allNonNegative(medium.emission) && std::isfinite(medium.emission.x) &&
          std::isfinite(medium.emission.y) && std::isfinite(medium.emission.z)))
        return fail(at("emission"), "mist emission must be finite and not negative, got " +
                                        formatVector(medium.emission));
    if (b.find("g") && !(medium.g > -1 && medium.g < 1))
        return fail(at("g"),
                    "mist g must be between -1 and 1 (exclusive), got " + formatNumber(medium.g),
                    "g is the Henyey-Greenstein asymmetry: 0 scatters evenly, > 0 forward");
    if (!method.empty())
        medium.method = method == "ratio"   ? MediumMethod::Ratio
                        : method == "delta" ? MediumMethod::Delta
                                            : MediumMethod::March;
    if (b.find("step") && !(medium.step > 0 && std::isfinite(medium.step)))
        return fail(at("step"), "mist step must be positive, got " + formatNumber(medium.step));
    if (b.find("step") && medium.method != MediumMethod::March)
        return fail(b.find("step")->loc, "mist step is the march method's step",
                    "write method march step " + formatNumber(medium.step));
    return true;
}

bool Lowering::lowerMistBounds(const PropertyBlock& b, const Statement& s,
                               std::optional<Bounds3>& bounds) {
    const auto fail = [&](SourcePos where, std::string message) {
        error(where, std::move(message));
        return false;
    };
    if (const Property* p = b.find("bounds")) {
        if (b.find("min") || b.find("max"))
            return fail(p->loc, "mist takes bounds or min and max, not both");
        if (!p->solid || p->solid->kind != Solid::Kind::Primitive || p->solid->name != "box")
            return fail(p->valueLoc(), "property 'bounds' of mist expects box { min … max … }");
        bounds = boxBounds(*p->solid, "bounds");
        if (!bounds) return false;
    } else if (b.find("min") || b.find("max")) {
        if (!b.find("min") || !b.find("max"))
            return fail((b.find("min") ? b.find("min") : b.find("max"))->loc,
                        "mist needs both min and max");
        Bounds3 box{Vec3(0.0), Vec3(0.0)};
        if (!readVector(b, "min", box.lo) || !readVector(b, "max", box.hi)) return false;
        if (!(box.lo.x < box.hi.x && box.lo.y < box.hi.y && box.lo.z < box.hi.z))
            return fail(b.find("max")->valueLoc(),
                        "empty mist bounds: min " + formatVector(box.lo) +
                            " must be less than max " + formatVector(box.hi) + " on every axis");
        bounds = box;
    }
    if (bounds && !bounds->finite()) return fail(s.loc, "mist bounds must be finite");
    return true;
}

bool Lowering::lowerFogDensity(const PropertyBlock& b, const Statement& s,
                               const std::optional<Bounds3>& bounds, Medium& medium) {
    const Solid& fog = *b.find("density")->solid;
    const Property* file = nullptr;
    const Property* grid = nullptr;
    for (const Property& p : fog.properties) (p.name == "file" ? file : grid) = &p;
    if (fog.name != "volume" || !file) {
        error(fog.loc,
              "property 'density' of mist expects an expression in x, y, z or volume "
              "\"file.vdb\"");
        return false;
    }
    if (const Property* bake = b.find("bake")) {
        error(bake->loc, "mist bake is for a density written as an expression",
              "a fog volume is already a grid");
        return false;
    }
    const auto fileValue = evaluate(*file->expr, nullptr);
    if (!fileValue) return false;
    std::string gridName;
    if (grid) {
        const auto g = evaluate(*grid->expr, nullptr);
        if (!g) return false;
        gridName = *g->text;
    }
    const std::string written = *fileValue->text;
    const std::string path = resolvedPath(written, file->valueLoc());
    const Loaded<FogAsset> v = mAssets.fogVolume(path, gridName);
    if (!v) {
        if (!v.error.skipped)
            error(
                grid && v.error.subject == AssetError::Subject::Part ? grid->loc : file->valueLoc(),
                "cannot read fog volume '" + written + "': " + v.error.reason,
                path == written
                    ? std::string()
                    : "volume files are relative to the model file's folder; looked for " + path);
        return false;
    }
    medium.density = v.value->density;
    medium.bounds = bounds ? Bounds3::overlap(*bounds, v.value->bounds) : v.value->bounds;
    if (medium.bounds.empty()) {
        error(b.find("bounds") ? b.find("bounds")->loc : s.loc,
              "mist bounds do not overlap the fog volume");
        return false;
    }
    return true;
}

bool Lowering::lowerExprDensity(const PropertyBlock& b, const std::optional<Bounds3>& bounds,
                                Medium& medium) {
    const Property& density = *b.find("density");
    if (!bounds) {
        error(density.loc, "a mist density needs bounds",
              "write bounds box { min <x, y, z> max <x, y, z> } around where the density is "
              "nonzero");
        return false;
    }
    ExprGraph graph;
    const auto v = evaluate(*density.expr, &graph);
    if (!v) return false;
    if (v->type != Value::Type::Field && v->type != Value::Type::Number) {
        error(density.expr->start,
              "property 'density' of mist expects a function of x, y, z, got " + typeName(v->type));
        return false;
    }
    const ExprId root = v->type == Value::Type::Field ? v->field : graph.constant(v->number);
    medium.bounds = *bounds;
    medium.density = std::make_shared<TapeDensity>(Tape::compile(graph, root));
    if (const Property* bake = b.find("bake")) {
        // `bake N`: render/ samples the density at N points along the box's longest side into
        // bricked storage and traces its trilinear interpolant (scene/medium.h MediumBake).
        MediumBake request;
        if (!readInteger(b, "bake", 2, 4096, request.resolution)) return false;
        const SourceLoc at = mSink.locate(bake->valueLoc());
        request.where = *at.file + ":" + std::to_string(at.line) + ":" + std::to_string(at.col);
        medium.bake = std::move(request);
    }
    return true;
}

bool Lowering::checkDensity(const Property& density, const Medium& medium) {
    // The majorant needs a finite bound; negative density the bound can prove is an error,
    // anywhere else a negative value is read as 0.
    const Bounds3& box = medium.bounds;
    const Interval r = medium.density->range(
        Interval(box.lo.x, box.hi.x), Interval(box.lo.y, box.hi.y), Interval(box.lo.z, box.hi.z));
    if (!(std::isfinite(r.lo) && std::isfinite(r.hi))) {
        error(density.valueLoc(),
              "the mist density has no finite bound over its bounds (got [" + formatNumber(r.lo) +
                  ", " + formatNumber(r.hi) + "])",
              "the renderer needs a majorant: write a density bounded over the box");
        return false;
    }
    int budget = kNegativeSearchBudget;
    if (const auto neg = provedNegative(*medium.density, box, 0, budget)) {
        error(density.valueLoc(),
              "the mist density is negative in the box from " + formatVector(neg->lo) + " to " +
                  formatVector(neg->hi),
              "density must be 0 or more; e.g. max(0, …) clamps it");
        return false;
    }
    return true;
}

}  // namespace kerf
