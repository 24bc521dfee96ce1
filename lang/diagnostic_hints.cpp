// The tables behind the hints for people coming from POV-Ray and OpenSCAD. Every claim a hint
// makes about kerf must stay true (docs/language.md, "Messages for habits from other modellers").
#include "lang/diagnostic_hints.h"

#include <algorithm>
#include <iterator>

#include "lang/names.h"
#include "lang/solid_kinds.h"

namespace kerf {

namespace {

struct ForeignSolid {
    const char* name;
    const char* kerf;  ///< kerf's solid of the same meaning, or "" when there is none
    const char* note;
};

// POV-Ray's and OpenSCAD's solids that kerf names differently or does not have.
const ForeignSolid kForeignSolids[] = {
    {"merge", "union", "kerf's union keeps no inner surfaces, like POV-Ray's merge"},
    {"plane", "halfspace",
     "POV-Ray's plane { n, d } is halfspace { normal n offset d }: all p with n·p <= d"},
    {"cube", "box", "write box { min <0, 0, 0> max <s, s, s> }"},
    {"cuboid", "box", "write box { min <x0, y0, z0> max <x1, y1, z1> }"},
    {"ellipsoid", "sphere", "write sphere { radius 1 } scale <a, b, c>"},
    {"spheroid", "sphere", "write sphere { radius 1 } scale <a, b, c>"},
    {"isosurface", "implicit",
     "write implicit { f EXPR bound box { min … max … } }; f <= 0 is inside"},
    {"superellipsoid", "implicit",
     "write its function in an implicit { f … }, e.g. pow(abs(x), p) + pow(abs(y), p) + "
     "pow(abs(z), p) - 1"},
    {"quadric", "implicit", "write the polynomial in x, y, z as implicit { f … bound box { … } }"},
    {"cubic", "implicit", "write the polynomial in x, y, z as implicit { f … bound box { … } }"},
    {"quartic", "implicit", "write the polynomial in x, y, z as implicit { f … bound box { … } }"},
    {"poly", "implicit", "write the polynomial in x, y, z as implicit { f … bound box { … } }"},
    {"blob", "", "blobs are not supported yet; an implicit { f … } can sum your own falloff terms"},
    {"disc", "", "discs are not supported; a thin cylinder { … } is the nearest solid"},
    {"lathe", "", "lathes are not supported yet"},
    {"sor", "", "surfaces of revolution are not supported yet"},
    {"prism", "", "prisms are not supported yet"},
    {"sphere_sweep", "", "sphere sweeps are not supported yet"},
    {"polygon", "",
     "a polygon is a 2-D profile: extrude { profile polygon { points [[0, 0], [1, 0], [0, 1]] } "
     "height 1 }"},
    {"triangle", "", "triangles are not supported (kerf's solids are closed)"},
    {"mesh", "", "kerf reads meshes from files: write mesh \"file.stl\" (OBJ, PLY, STL, glTF)"},
    {"mesh2", "", "kerf reads meshes from files: write mesh \"file.stl\" (OBJ, PLY, STL, glTF)"},
    {"polyhedron", "", "polyhedra are not supported yet"},
    {"height_field", "", "height fields are not supported yet"},
    {"linear_extrude", "extrude",
     "write extrude { profile circle { radius 1 } height 2 twist 0 scale 1 }"},
    {"rotate_extrude", "revolve",
     "write revolve { profile circle { center [2, 0] radius 1 } angle 360 }"},
    {"hull", "", "hulls are not supported"},
    {"minkowski", "", "Minkowski sums are not supported"},
};

const ForeignSolid* foreignSolid(const std::string& name) {
    for (const ForeignSolid& f : kForeignSolids)
        if (name == f.name) return &f;
    return nullptr;
}

/// The candidate at edit distance 1 or 2 (and less than the name's length), nearest first.
std::string nearMiss(const std::string& name, const std::vector<std::string>& candidates) {
    std::string best;
    int bestDistance = 3;
    for (const std::string& c : candidates) {
        const int d = editDistance(name, c);
        if (d > 0 && d < bestDistance && d < static_cast<int>(name.size())) {
            best = c;
            bestDistance = d;
        }
    }
    return best;
}

std::vector<std::string> allSolidKinds() { return solidKeywords(kListed, true); }

/// The candidates for a near miss: the listed kinds and the primitives left out of the list.
std::vector<std::string> nearMissKinds() {
    std::vector<std::string> all = allSolidKinds();
    for (const std::string& k : solidKeywords(kNeedsBlock))
        if (std::find(all.begin(), all.end(), k) == all.end()) all.push_back(k);
    return all;
}

struct ForeignProperty {
    const char* name;
    const char* note;
};

const ForeignProperty kForeignProperties[] = {
    {"open", "kerf writes it 'open true' (the side alone: a surface, not a solid)"},
    {"sturm", "not needed: kerf isolates every root by interval arithmetic"},
    {"max_gradient", "not needed: kerf bounds the function by interval arithmetic"},
    {"accuracy", "not needed: the tolerance is set by --tolerance"},
    {"contained_by", "an implicit's search box is its bound: bound box { min … max … }"},
    {"function", "an implicit's function is its property f"},
    {"threshold", "write the threshold into f: f EXPR - threshold"},
    {"pigment",
     "colours are materials: material NAME { color … } and 'material NAME' after the solid"},
    {"texture",
     "colours are materials: material NAME { color … } and 'material NAME' after the solid"},
    {"finish", "surface finish is a material: material NAME { diffuse … specular … }"},
    {"interior", "glass is a material: material NAME { transmit … ior … }"},
    {"location", "the camera's position is eye"},
    {"angle", "the camera's field of view is fov (vertical, in degrees)"},
    {"center", "center belongs to sphere; move other solids with translate"},
};

}  // namespace

const std::vector<std::string>& primitiveKinds() {
    static const std::vector<std::string> kinds = solidKeywords(kListed);
    return kinds;
}

bool isProfileKind(const std::string& name) {
    return name == "circle" || name == "rect" || name == "polygon" || name == "path" ||
           name == "offset" || name == "text";
}

const std::vector<std::string>& booleanKinds() {
    static const std::vector<std::string> kinds = solidKeywords(kBoolean, true);
    return kinds;
}

bool isSolidKind(const std::string& name) {
    const SolidKind* kind = findSolidKind(name);  // lang/solid_kinds.cpp
    return (kind && kind->has(kSolidValue)) || isProfileKind(name);
}

std::string kerfSolidFor(const std::string& foreign) {
    const ForeignSolid* f = foreignSolid(foreign);
    return f ? f->kerf : "";
}

std::string unknownSolidHint(const std::string& name, const std::vector<std::string>& values) {
    std::string hint;
    if (const ForeignSolid* f = foreignSolid(name)) {
        const std::string form = values.empty() ? std::string() : namedForm(f->kerf, values);
        if (!form.empty())
            hint = "write '" + form + "' (" + f->note + "). ";
        else
            hint = foreignSolidHint(name) + ". ";
    } else if (const std::string close = nearMiss(name, nearMissKinds()); !close.empty()) {
        hint = "did you mean '" + close + "'? ";
    }
    return hint + (hint.empty() ? "the" : "The") + " solids are: " + joinNames(allSolidKinds());
}

std::string foreignSolidHint(const std::string& name) {
    const ForeignSolid* f = foreignSolid(name);
    if (!f) return "";
    return (*f->kerf ? "use '" + std::string(f->kerf) + "': " : std::string()) + f->note;
}

bool isForeignFlag(const std::string& property) {
    static const char* const kFlags[] = {
        "open",      "sturm",    "hollow",        "inverse",
        "no_shadow", "no_image", "no_reflection", "double_illuminate",
        "smooth"};
    return std::any_of(std::begin(kFlags), std::end(kFlags),
                       [&](const char* f) { return property == f; });
}

std::string foreignStatementHint(const std::string& word) {
    if (word == "light_source") return "a light is light point { at <x, y, z> color <r, g, b> }";
    if (word == "global_settings")
        return "image settings are render { width … height … spp … max_depth … }";
    if (word == "module") return "a named solid is solid NAME = …; and is placed with object NAME;";
    return "";
}

std::string foreignPropertyNote(const std::string& property) {
    for (const ForeignProperty& p : kForeignProperties)
        if (property == p.name) return p.note;
    return "";
}

std::string namedForm(const std::string& kind, const std::vector<std::string>& values) {
    const SolidKind* row = findSolidKind(kind);  // lang/solid_kinds.cpp
    if (!row || row->positionalNames.empty()) return "";
    const std::vector<const char*>& names = row->positionalNames;
    const bool fill = values.size() == names.size();
    std::string form = kind + " {";
    for (size_t i = 0; i < names.size(); ++i)
        form +=
            std::string(" ") + names[i] + " " + (fill ? values[i] : row->positionalPlaceholders[i]);
    return form + " }";
}

std::string positionalHint(const std::string& kind, const std::vector<std::string>& values,
                           const std::string& flag) {
    const std::string form = namedForm(kind, values);
    std::string hint = form.empty() ? kind + " takes named properties"
                                    : "kerf names each property: write '" + form + "'";
    if (const std::string note = foreignPropertyNote(flag); !flag.empty() && !note.empty())
        hint += "; " + note;
    return hint;
}

std::string callSyntaxHint(const std::string& name) {
    static const std::pair<const char*, const char*> kCalls[] = {
        {"cube", "a box is box { min <0, 0, 0> max <s, s, s> }"},
        {"sphere", "a sphere is sphere { center <x, y, z> radius r }"},
        {"cylinder",
         "a cylinder is cylinder { from <x0, y0, z0> to <x1, y1, z1> radius r }, and one with "
         "two radii is cone { from … to … radius1 r1 radius2 r2 }"},
        {"union", "a Boolean lists its solids in braces: union { A B }"},
        {"difference", "a Boolean lists its solids in braces: difference { A B }"},
        {"intersection", "a Boolean lists its solids in braces: intersection { A B }"},
        {"translate", "transforms follow the solid: sphere { … } translate <x, y, z>"},
        {"rotate", "transforms follow the solid: sphere { … } rotate <x, y, z> (degrees)"},
        {"scale", "transforms follow the solid: sphere { … } scale <x, y, z>"},
        {"mirror",
         "transforms follow the solid: mirror with a negative scale, e.g. scale <-1, 1, 1>"},
        {"multmatrix", "transforms follow the solid: sphere { … } matrix [12 numbers, row-major]"},
        {"color",
         "colours are materials: material NAME { color … } and 'material NAME' after the solid"},
    };
    for (const auto& [call, hint] : kCalls)
        if (name == call) return std::string("kerf has no call syntax for solids; ") + hint;
    return "";
}

std::string implicitBoundHint() {
    return "the bound is an axis-aligned box in the implicit's own coordinates, read when the "
           "model is "
           "compiled: the solid is the part of it where f <= 0, and the surface is searched only "
           "inside it. "
           "A named solid is a finished solid (perhaps moved, rotated or not a box), so write the "
           "box in "
           "place; to share corners, put them in lets: bound box { min lo max hi }";
}

}  // namespace kerf
