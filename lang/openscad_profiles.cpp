// The one adapter between the .csg reader and 2-D profiles: circle, square and polygon are
// outlines, linear_extrude and rotate_extrude make solids of them. kerf's profiles and
// extrusions are being written (csg/ profiles, lang/lower_profiles.cpp); until they land,
// each of these nodes is a clear error at its line, and only this file changes when they do.
#include "lang/openscad_lower.h"

namespace kerf {

bool isScadProfileNode(const std::string& name) {
    return name == "circle" || name == "square" || name == "polygon" || name == "linear_extrude" ||
           name == "rotate_extrude";
}

NodePtr lowerScadProfileNode(const ScadCall& c, ScadLowering& lowering) {
    lowering.unsupported(c, c.name +
                                " is not supported yet: 2-D profiles and extrusions are not read "
                                "from .csg files yet");
    // Nodes under it that no part of the reader reads are listed in the same run (the 2-D
    // nodes under an extrusion are not: they go with it).
    lowering.reportUnsupportedWithin(c.children);
    return nullptr;
}

}  // namespace kerf
