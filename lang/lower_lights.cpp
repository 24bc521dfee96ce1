// Lowering, part 5: lights (point, directional, area, sphere, with their falloff and shadow
// controls) and the background (a colour or a gradient sky).
#include "lang/lower.h"

#include "lang/names.h"

#include <cmath>

namespace kerf {

std::optional<Light> Lowering::lowerLight(const Statement& s) {
    Light light;
    std::vector<PropertySpec> specs{{"color", PropertyType::Vector}};
    if (!lightKind(s, light, specs)) return std::nullopt;
    specs.push_back({"shadows", PropertyType::Bool});
    const PropertyBlock b(s.properties, specs, s.name + " light", s.loc, mSink);
    bool ok = b.ok();
    ok &= readLight(b, light);
    if (!ok) return std::nullopt;
    return checkLight(b, light) ? std::optional<Light>(light) : std::nullopt;
}

bool Lowering::lightKind(const Statement& s, Light& light, std::vector<PropertySpec>& specs) {
    const bool positioned = s.name == "point" || s.name == "area" || s.name == "sphere";
    if (s.name == "point") {
        light.kind = Light::Kind::Point;
        specs.push_back({"at", PropertyType::Vector, true});
    } else if (s.name == "directional") {
        light.kind = Light::Kind::Directional;
        specs.push_back({"direction", PropertyType::Vector, true});
    } else if (s.name == "area") {
        light.kind = Light::Kind::Area;
        specs.push_back({"corner", PropertyType::Vector, true});
        specs.push_back({"edge1", PropertyType::Vector, true});
        specs.push_back({"edge2", PropertyType::Vector, true});
        specs.push_back({"samples", PropertyType::Number});
    } else if (s.name == "sphere") {
        light.kind = Light::Kind::Sphere;
        specs.push_back({"at", PropertyType::Vector, true});
        specs.push_back({"radius", PropertyType::Number, true});
        specs.push_back({"samples", PropertyType::Number});
    } else {
        std::string hint = didYouMean(s.name, {"point", "directional", "area", "sphere"});
        error(s.nameLoc, "unknown light kind '" + s.name + "'",
              hint.empty() ? "lights are point, directional, area or sphere" : hint);
        return false;
    }
    if (positioned) {
        specs.push_back({"power", PropertyType::Number});
        specs.push_back({"falloff", PropertyType::Word});
        specs.push_back({"fade_distance", PropertyType::Number});
    }
    return true;
}

bool Lowering::readLight(const PropertyBlock& b, Light& light) {
    bool ok = true;
    ok &= readVector(b, "color", light.color);
    ok &= readBool(b, "shadows", light.shadows);
    ok &= readInteger(b, "samples", 1, 4096, light.samples);
    if (light.kind == Light::Kind::Directional) {
        ok &= readVector(b, "direction", light.direction);
    } else {
        ok &= readVector(b, light.kind == Light::Kind::Area ? "corner" : "at", light.position);
        ok &= readNumber(b, "power", light.power);
        ok &= readNumber(b, "fade_distance", light.fadeDistance);
        std::string falloff;
        ok &= readWord(b, "falloff", {"inverse_square", "linear", "none"}, falloff);
        if (falloff == "linear") light.falloff = Falloff::Linear;
        if (falloff == "none") light.falloff = Falloff::None;
    }
    if (light.kind == Light::Kind::Area) {
        ok &= readVector(b, "edge1", light.edgeU);
        ok &= readVector(b, "edge2", light.edgeV);
    }
    if (light.kind == Light::Kind::Sphere) ok &= readNumber(b, "radius", light.radius);
    return ok;
}

bool Lowering::checkLight(const PropertyBlock& b, const Light& light) {
    bool ok = true;
    if (!allNonNegative(light.color)) {
        error(b.find("color")->valueLoc(),
              "light color must not have negative components, got " + formatVector(light.color));
        ok = false;
    }
    if (light.power < 0) {
        error(b.find("power")->valueLoc(),
              "light power must not be negative, got " + formatNumber(light.power));
        ok = false;
    }
    if (b.find("fade_distance") && !(light.fadeDistance > 0 && std::isfinite(light.fadeDistance))) {
        error(b.find("fade_distance")->valueLoc(),
              "light fade_distance must be positive, got " + formatNumber(light.fadeDistance),
              "the light is at full strength within about this distance (POV-Ray's fade_distance)");
        ok = false;
    }
    if (light.kind == Light::Kind::Directional && light.direction == Vec3(0.0)) {
        error(b.find("direction")->valueLoc(), "light direction must not be zero");
        ok = false;
    }
    if (light.kind == Light::Kind::Area &&
        !(glm::length(glm::cross(light.edgeU, light.edgeV)) > 0)) {
        error(b.find("edge2")->valueLoc(),
              "area light edges " + formatVector(light.edgeU) + " and " +
                  formatVector(light.edgeV) + " span no area",
              "edge1 and edge2 are two sides of the parallelogram from its corner; they must not "
              "be parallel");
        ok = false;
    }
    if (light.kind == Light::Kind::Sphere && !(light.radius > 0 && std::isfinite(light.radius))) {
        error(b.find("radius")->valueLoc(),
              "sphere light radius must be positive, got " + formatNumber(light.radius),
              "a point light is a sphere light of radius 0: write light point { … }");
        ok = false;
    }
    return ok;
}

void Lowering::lowerBackground(const Statement& s, Scene& scene) {
    if (s.name == "gradient") {
        const PropertyBlock b(s.properties,
                              {{"horizon", PropertyType::Vector, true},
                               {"zenith", PropertyType::Vector, true},
                               {"nadir", PropertyType::Vector},
                               {"up", PropertyType::Vector}},
                              "background gradient", s.loc, mSink);
        Sky sky;
        sky.gradient = true;
        bool ok = b.ok();
        ok &= readVector(b, "horizon", sky.horizon);
        ok &= readVector(b, "zenith", sky.zenith);
        sky.nadir = sky.horizon;
        ok &= readVector(b, "nadir", sky.nadir);
        ok &= readVector(b, "up", sky.up);
        if (!ok) return;
        for (const char* name : {"horizon", "zenith", "nadir"}) {
            const Vec3& c = name[0] == 'h' ? sky.horizon : name[0] == 'z' ? sky.zenith : sky.nadir;
            if (b.find(name) && !allNonNegative(c)) {
                error(b.find(name)->valueLoc(), std::string("background ") + name +
                                                    " must not have negative components, got " +
                                                    formatVector(c));
                ok = false;
            }
        }
        if (!(glm::length(sky.up) > 0) || !std::isfinite(glm::length(sky.up))) {
            error(b.find("up")->valueLoc(),
                  "background up must be a finite non-zero vector, got " + formatVector(sky.up));
            ok = false;
        }
        if (!ok) return;
        sky.up = glm::normalize(sky.up);
        scene.sky = sky;
        scene.background = sky.horizon;
        return;
    }
    const auto v = evaluate(*s.expr, nullptr);
    if (!v) return;
    if (v->type != Value::Type::Vector) {
        error(s.expr->start, "background expects a colour vector, got " + typeName(v->type),
              "write background <r, g, b>; or background gradient { horizon … zenith … }");
        return;
    }
    if (!allNonNegative(v->vector)) {
        error(s.expr->start,
              "background color must not have negative components, got " + formatVector(v->vector));
        return;
    }
    scene.background = v->vector;
}

}  // namespace kerf
