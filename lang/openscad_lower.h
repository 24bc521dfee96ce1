/// @file lang/openscad_lower.h
/// @brief Inside the .csg reader: the lowering of a parsed tree onto csg/ nodes, split by
/// subject (openscad_lower.cpp: Booleans, transforms, colour, solids and the scene;
/// openscad_polyhedron.cpp: polyhedra as mesh solids; openscad_profiles.cpp: the one
/// adapter through which 2-D nodes and extrusions go).
#pragma once

#include "lang/openscad_csg.h"
#include "scene/assets.h"

#include <map>
#include <tuple>

namespace kerf {

class ScadLowering {
public:
    /// Fonts and polyhedra's meshes come from `assets` (scene/assets.h).
    ScadLowering(DiagnosticSink& sink, Scene& scene, AssetProvider& assets)
        : mSink(sink), mScene(scene), mAssets(assets) {}

    /// The union of the top-level calls in OpenSCAD's coordinates; null when the model is
    /// empty or had errors (reported).
    NodePtr lowerAll(const std::vector<ScadCall>& calls);
    /// After lowerAll: the one note on the facets OpenSCAD would have used (if any curve).
    void reportFacets();

    // Argument readers: false, with an error at the argument, on a wrong type; `out` is left
    // alone when the argument is absent or undef.
    bool number(const ScadCall& c, const std::string& name, int position, double& out);
    bool flag(const ScadCall& c, const std::string& name, int position, bool& out);
    /// A radius given as `rName` (or positionally) or as the diameter `dName`, which wins
    /// when both are given, as in OpenSCAD.
    bool radius(const ScadCall& c, const std::string& rName, int position, const std::string& dName,
                double& out);
    /// A number (all three equal) or a vector of three numbers.
    bool triple(const ScadCall& c, const std::string& name, int position, Vec3& out);

    void error(SourcePos pos, std::string message, std::string hint = {}) {
        mSink.error(pos, std::move(message), std::move(hint));
    }
    void warning(SourcePos pos, std::string message);

    SourceLoc locate(SourcePos pos) const { return mSink.locate(pos); }
    AssetProvider& assets() { return mAssets; }
    /// An error at a node that cannot be read; past kMaxUnsupportedReports of them only
    /// counted, and summed up in one error by finish().
    void unsupported(const ScadCall& c, const std::string& message);
    /// Reports every node under `calls` that no part of the reader can read.
    void reportUnsupportedWithin(const std::vector<ScadCall>& calls);
    /// The summary of unsupported nodes past the first kMaxUnsupportedReports.
    void finish();

    /// `child` in the material of color call `c` (the colour checked first, an error at it
    /// when wrong); null when child is null or on error.
    NodePtr applyColor(const ScadCall& c, NodePtr child);
    /// Counts a circle of radius r for the facet note, from the call's $fn, $fa, $fs.
    void countFacets(const ScadCall& c, double r);

private:
    NodePtr lower(const ScadCall& c);
    /// The calls lowered, `%` and `*` ones left out; empty solids come back null.
    std::vector<NodePtr> lowerChildren(const std::vector<ScadCall>& calls);
    /// "difference", "intersection", else a union (group, union, render) of the calls.
    NodePtr lowerBoolean(const std::string& op, const std::vector<ScadCall>& calls);
    NodePtr lowerMultmatrix(const ScadCall& c);
    NodePtr lowerColor(const ScadCall& c);
    NodePtr lowerCube(const ScadCall& c);
    NodePtr lowerSphere(const ScadCall& c);
    NodePtr lowerCylinder(const ScadCall& c);
    bool reportIfUnsupported(const ScadCall& c);

    DiagnosticSink& mSink;
    Scene& mScene;
    AssetProvider& mAssets;
    std::map<std::tuple<double, double, double>, int> mColorMaterials;
    static constexpr int kMaxUnsupportedReports = 20;
    int mUnsupported = 0;
    SourcePos mFirstUnlisted;
    int mCurves = 0;
    int mFewestFacets = 0;
    int mMostFacets = 0;
    SourcePos mFirstCurve;
};

// openscad_polyhedron.cpp
/// polyhedron(points, faces): a closed mesh solid, or null with an error.
NodePtr lowerScadPolyhedron(const ScadCall& c, ScadLowering& lowering);

// openscad_profiles.cpp: the 2-D adapter.
/// circle, square, polygon, linear_extrude, rotate_extrude.
bool isScadProfileNode(const std::string& name);
/// A 2-D node or an extrusion lowered to a solid (extrusions) or reported (null).
NodePtr lowerScadProfileNode(const ScadCall& c, ScadLowering& lowering);

}  // namespace kerf
