// Lowering, part 4: materials, the camera and render settings, each validated where it is
// read (lights and the background: lower_lights.cpp; mist: lower_mist.cpp).
#include "lang/lower.h"

#include "csg/normalize.h"
#include "lang/names.h"

#include <cmath>

namespace kerf {

void Lowering::lowerMaterial(const Statement& s, Material& m) {
    const PropertyBlock b(s.properties,
                          {{"color", PropertyType::Vector},
                           {"ambient", PropertyType::Number},
                           {"diffuse", PropertyType::Number},
                           {"specular", PropertyType::Number},
                           {"shininess", PropertyType::Number},
                           {"reflect", PropertyType::Number},
                           {"transmit", PropertyType::Number},
                           {"ior", PropertyType::Number},
                           {"absorb", PropertyType::Vector},
                           {"emit", PropertyType::Vector},
                           {"glossy", PropertyType::Number},
                           {"translucent", PropertyType::Number},
                           {"pattern", PropertyType::Solid},
                           {"bump", PropertyType::Solid},
                           {"bump_depth", PropertyType::Number}},
                          "material", s.loc, mSink);
    if (const Property* p = b.find("bump")) {
        if (p->solid)
            m.bump = lowerPattern(*p->solid);
        else
            error(p->valueLoc(), "property 'bump' of material expects a pattern",
                  "write e.g. bump noise { } scale 0.1 bump_depth 0.2");
    }
    m.bumpDepth = m.bump ? 0.1 : 0.0;  // a bump without a depth is a gentle one
    if (readNumber(b, "bump_depth", m.bumpDepth) && !std::isfinite(m.bumpDepth))
        error(b.find("bump_depth")->valueLoc(), "material bump_depth must be finite");
    if (const Property* p = b.find("pattern")) {
        if (p->solid)
            m.pattern = lowerPattern(*p->solid);
        else
            error(p->valueLoc(), "property 'pattern' of material expects a pattern",
                  "write e.g. pattern checker { a <1, 1, 1> b <0, 0, 0> } scale 0.5");
    }
    const auto number = [&](const char* name, double& out) {
        if (readNumber(b, name, out) && out < 0)
            error(b.find(name)->valueLoc(), std::string("material ") + name +
                                                " must not be negative, got " + formatNumber(out));
    };
    const auto colour = [&](const char* name, Vec3& out) {
        if (readVector(b, name, out) && !allNonNegative(out))
            error(b.find(name)->valueLoc(), std::string("material ") + name +
                                                " must not have negative components, got " +
                                                formatVector(out));
    };
    colour("color", m.color);
    number("ambient", m.ambient);
    number("diffuse", m.diffuse);
    number("specular", m.specular);
    number("shininess", m.shininess);
    number("reflect", m.reflect);
    number("transmit", m.transmit);
    colour("absorb", m.absorb);
    colour("emit", m.emit);
    for (const auto& [name, out] :
         {std::pair<const char*, double*>{"glossy", &m.glossy}, {"translucent", &m.translucent}})
        if (readNumber(b, name, *out) && !(*out >= 0 && *out <= 90))
            error(b.find(name)->valueLoc(),
                  std::string("material ") + name + " must be an angle from 0 to 90 degrees, got " +
                      formatNumber(*out),
                  std::string(name) + " is the half-angle of the cone the " +
                      (name[0] == 'g' ? "reflected" : "refracted") + " rays are spread over");
    if (readNumber(b, "ior", m.ior) && !(m.ior > 0))
        error(b.find("ior")->valueLoc(),
              "material ior must be positive, got " + formatNumber(m.ior));
    checkEnergy(b, m);
}

/// Reflection and refraction may pass on at most the light that arrives: each weight in
/// [0, 1], their sum ≤ 1, and a transmissive colour (which tints the refracted light) ≤ 1.
/// Weights above that made each bounce brighter: +inf pixels, and trees of rays that grow
/// with depth instead of dying out (docs/robustness.md, "Values").
void Lowering::checkEnergy(const PropertyBlock& b, const Material& m) {
    bool ok = true;
    for (const auto& [name, w] :
         {std::pair<const char*, double>{"reflect", m.reflect}, {"transmit", m.transmit}}) {
        if (b.find(name) && w > 1) {
            error(b.find(name)->valueLoc(),
                  std::string("material ") + name + " must be at most 1, got " + formatNumber(w),
                  "reflect and transmit are the fractions of light mirrored and refracted");
            ok = false;
        }
    }
    if (ok && m.reflect >= 0 && m.transmit >= 0 && m.reflect + m.transmit > 1) {
        SourcePos r = b.find("reflect")->valueLoc();
        SourcePos t = b.find("transmit")->valueLoc();
        const bool reflectFirst = r.offset < t.offset;  // one block, so one file
        const Property* later = reflectFirst ? b.find("transmit") : b.find("reflect");
        error(later->valueLoc(),
              "material reflect + transmit must be at most 1, got " + formatNumber(m.reflect) +
                  " + " + formatNumber(m.transmit),
              "together they are the fraction of light passed on; lower one of them");
    }
    if (m.transmit > 0 && b.find("color") && (m.color.x > 1 || m.color.y > 1 || m.color.z > 1))
        error(
            b.find("color")->valueLoc(),
            "the color of a material that transmits must not exceed 1, got " +
                formatVector(m.color),
            "its color tints the refracted light, which cannot come out brighter than it went in");
}

void Lowering::lowerCamera(const Statement& s, CameraDesc& camera) {
    const PropertyBlock b(s.properties,
                          {{"eye", PropertyType::Vector},
                           {"look_at", PropertyType::Vector},
                           {"up", PropertyType::Vector},
                           {"fov", PropertyType::Number},
                           {"aperture", PropertyType::Number},
                           {"focus_distance", PropertyType::Number},
                           {"shutter_open", PropertyType::Number},
                           {"shutter_close", PropertyType::Number}},
                          "camera", s.loc, mSink);
    bool ok = b.ok();
    readCameraLens(b, camera, ok);
    ok &= readVector(b, "eye", camera.eye);
    ok &= readVector(b, "look_at", camera.lookAt);
    ok &= readVector(b, "up", camera.up);
    ok &= readNumber(b, "fov", camera.fovDegrees);
    if (!ok) return;
    checkCameraView(s, b, camera);
}

void Lowering::readCameraLens(const PropertyBlock& b, CameraDesc& camera, bool& ok) {
    ok &= readNumber(b, "shutter_open", camera.shutterOpen);
    ok &= readNumber(b, "shutter_close", camera.shutterClose);
    if (b.find("shutter_open") && !b.find("shutter_close"))
        camera.shutterClose = camera.shutterOpen;
    if (ok && !(camera.shutterOpen >= 0 && camera.shutterOpen <= camera.shutterClose &&
                camera.shutterClose <= 1)) {
        const Property* at =
            b.find("shutter_close") ? b.find("shutter_close") : b.find("shutter_open");
        error(at->valueLoc(),
              "camera shutter must open and close within the scene time 0 to 1, got " +
                  formatNumber(camera.shutterOpen) + " to " + formatNumber(camera.shutterClose),
              "move and spin give each solid's motion over the scene time 0 to 1");
        ok = false;
    }
    ok &= readNumber(b, "aperture", camera.aperture);
    ok &= readNumber(b, "focus_distance", camera.focusDistance);
    if (ok && !(camera.aperture >= 0 && std::isfinite(camera.aperture))) {
        error(b.find("aperture")->valueLoc(),
              "camera aperture must not be negative, got " + formatNumber(camera.aperture),
              "aperture is the lens diameter; 0 is a pinhole");
        ok = false;
    }
    if (ok && b.find("focus_distance") &&
        !(camera.focusDistance > 0 && std::isfinite(camera.focusDistance))) {
        error(b.find("focus_distance")->valueLoc(),
              "camera focus_distance must be positive, got " + formatNumber(camera.focusDistance),
              "the distance from the eye, along the view, of the plane in focus");
        ok = false;
    }
}

void Lowering::checkCameraView(const Statement& s, const PropertyBlock& b,
                               const CameraDesc& camera) {
    const auto at = [&](const char* name) {
        return b.find(name) ? b.find(name)->valueLoc() : s.loc;
    };
    if (!(camera.fovDegrees > 0 && camera.fovDegrees < 180))
        error(at("fov"),
              "camera fov must be between 0 and 180 degrees (exclusive), got " +
                  formatNumber(camera.fovDegrees),
              "fov is the vertical field of view in degrees, e.g. 40");
    for (const char* name : {"eye", "look_at", "up"}) {
        const Vec3& v = name[0] == 'e' ? camera.eye : name[0] == 'l' ? camera.lookAt : camera.up;
        if (!allFinite(v)) {
            error(at(name),
                  std::string("camera ") + name + " is not finite, got " + formatVector(v));
            return;
        }
    }
    const Vec3 view = camera.lookAt - camera.eye;
    if (view == Vec3(0.0)) {
        error(at("look_at"),
              "camera eye and look_at are the same point " + formatVector(camera.eye),
              "look_at is the point the camera looks toward");
        return;
    }
    if (!allFinite(view)) {
        error(at("look_at"),
              "camera look_at - eye is not finite (" + formatVector(view) +
                  "): they are too far apart",
              "eye and look_at must differ by less than about 1.8e308 on each axis");
        return;
    }
    if (camera.up == Vec3(0.0)) {
        error(at("up"), "camera up must not be zero", "up is usually <0, 1, 0>");
        return;
    }
    // Both unit vectors are taken overflow-safe, so the test is relative whatever the scale.
    const double sine = glm::length(glm::cross(normalizeSafe(view), normalizeSafe(camera.up)));
    if (!(sine > 1e-9))
        error(at("up"),
              "camera up " + formatVector(camera.up) + " is parallel to the view direction " +
                  formatVector(view),
              "choose an up vector that is not parallel to look_at - eye, e.g. <0, 0, 1>");
}

void Lowering::lowerRender(const Statement& s, RenderSettings& settings) {
    const PropertyBlock b(s.properties,
                          {{"width", PropertyType::Number},
                           {"height", PropertyType::Number},
                           {"spp", PropertyType::Number},
                           {"max_depth", PropertyType::Number},
                           {"sampler", PropertyType::Word},
                           {"filter", PropertyType::Word},
                           {"noise", PropertyType::Number}},
                          "render", s.loc, mSink);
    std::string filter;
    if (readWord(b, "filter", {"box", "gaussian", "mitchell"}, filter) && !filter.empty())
        settings.filter = *parseFilter(filter);
    if (readNumber(b, "noise", settings.noise) &&
        !(settings.noise >= 0 && std::isfinite(settings.noise)))
        error(b.find("noise")->valueLoc(),
              "render noise must be 0 or more, got " + formatNumber(settings.noise),
              "noise is the standard error at which a pixel stops sampling; 0 turns adaptive "
              "sampling off");
    std::string sampler;
    if (readWord(b, "sampler", {"jittered", "lattice", "random", "regular"}, sampler) &&
        !sampler.empty())
        settings.sampler = *parseSampler(sampler);
    readInteger(b, "width", 1, kMaxImageSide, settings.width);
    readInteger(b, "height", 1, kMaxImageSide, settings.height);
    readInteger(b, "spp", 1, kMaxSamplesPerPixel, settings.spp);
    readInteger(b, "max_depth", 0, 1000, settings.maxDepth);
}

}  // namespace kerf
