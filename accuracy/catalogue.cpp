/// @file accuracy/catalogue.cpp
/// @brief The benchmark's scene list and names.
#include "accuracy/catalogue.h"

#include <string>

namespace kerf {

const std::vector<AccuracySceneSpec>& accuracySceneCatalogue() {
    static const std::vector<AccuracySceneSpec> catalogue = {
        {"sphere", "sphere.kerf", true, 1, "a unit sphere (quadratic)"},
        {"cylcone", "cylcone.kerf", true, 1,
         "cylinder − cone and cylinder ∪ cone sharing cap planes; a tube (coincident faces)"},
        {"torus", "torus.kerf", true, 1,
         "a fat torus and a thin ring, R/r = 20 (quartics: closed = the torus's own root solver)"},
        {"gyroid", "gyroid.kerf", false, 2, "a gyroid sheet clipped to a box (implicit)"},
        {"tangle", "tangle.kerf", false, 2, "the tangle cube (quartic implicit)"},
        {"box_minus_spheres", "box_minus_spheres.kerf", true, 1,
         "a box minus 1000 spheres on a floor (wide CSG)"},
        {"thin_shell", "thin_shell.kerf", true, 1,
         "open spherical shells 1e-5 of their radius thick, seen at grazing angles"},
        {"grazing", "grazing.kerf", true, 1, "rays skimming long cylinders and rows of spheres"},
    };
    return catalogue;
}

const AccuracySceneSpec* findAccuracyScene(const std::string& name) {
    for (const AccuracySceneSpec& spec : accuracySceneCatalogue())
        if (spec.name == name) return &spec;
    return nullptr;
}

std::vector<double> accuracyDecadeTolerances() {
    std::vector<double> tolerances;
    // Parsed from text, so each value is the double nearest the decade (1e-7, not 1e-7·(1+ε)).
    for (int e = 2; e <= 12; ++e) tolerances.push_back(std::stod("1e-" + std::to_string(e)));
    return tolerances;
}

}  // namespace kerf
