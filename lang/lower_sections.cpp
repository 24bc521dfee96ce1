// Lowering of `section { point P normal N color C }`: a plane the render cuts the model by
// (render/section_cut.h), the side the normal points to removed.
#include "lang/lower.h"

#include "csg/normalize.h"

#include <cmath>

namespace kerf {

void Lowering::lowerSection(const Statement& s, Scene& scene) {
    const PropertyBlock b(s.properties,
                          {{"point", PropertyType::Vector, true},
                           {"normal", PropertyType::Vector, true},
                           {"color", PropertyType::Vector}},
                          "section", s.loc, mSink);
    SectionPlane plane;
    bool ok = b.ok();
    ok &= readVector(b, "point", plane.point);
    ok &= readVector(b, "normal", plane.normal);
    ok &= readVector(b, "color", plane.color);
    if (!ok) return;
    if (!allFinite(plane.point)) {
        error(b.find("point")->valueLoc(),
              "section point must be finite, got " + formatVector(plane.point));
        ok = false;
    }
    if (!allFinite(plane.normal)) {
        error(b.find("normal")->valueLoc(),
              "section normal must be finite, got " + formatVector(plane.normal));
        ok = false;
    } else if (plane.normal == Vec3(0.0)) {
        error(b.find("normal")->valueLoc(), "section normal must not be zero",
              "the normal points to the side that is removed, e.g. normal <0, 0, 1> removes z "
              "above the point");
        ok = false;
    }
    if (const Property* c = b.find("color"); c && !(allFinite(plane.color) && plane.color.x >= 0 &&
                                                    plane.color.y >= 0 && plane.color.z >= 0)) {
        error(c->valueLoc(),
              "section color must not have negative components, got " + formatVector(plane.color));
        ok = false;
    }
    if (!ok) return;
    if (scene.sections.size() > size_t(kMaxSections)) return;  // reported at the first one over
    if (scene.sections.size() == size_t(kMaxSections))
        error(s.loc, "more than " + std::to_string(kMaxSections) + " section planes",
              "every object a plane crosses is cut by each of them; keep the cuts you need");
    plane.normal = normalizeSafe(plane.normal);
    scene.sections.push_back(plane);
    mSectionLocs.push_back(s.loc);
}

}  // namespace kerf
