/// @file lang/lower.h
/// @brief Lowering: a parsed Program (includes already spliced in) becomes a Scene. Names are
/// declarative (a solid, let or material may be used before its definition); each `solid` is
/// lowered once and every use shares the same NodePtr. All meaning is checked here: types,
/// ranges, undefined names and cycles, each reported once at its own location.
///
/// The work is split by subject: lower.cpp (definitions and statements), lower_expr.cpp
/// (expressions), lower_solids.cpp (solids and modifiers), lower_scene.cpp (materials, camera,
/// lights, mist, render settings).
#pragma once

#include "csg/expr.h"
#include "scene/scene.h"
#include "lang/ast.h"
#include "lang/properties.h"
#include "lang/value.h"
#include "scene/limits.h"

#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace kerf {

class Lowering {
public:
    explicit Lowering(DiagnosticSink& sink) : mSink(sink) {}

    /// Lowers the program; nullopt if it reported any error. The syntax tree of each `solid`
    /// definition and `object` is freed once it is lowered (Statement::releaseTree), so the
    /// memory held follows the compiled scene, not the text.
    std::optional<Scene> lower(Program& program);

    /// After lower(): the tree of a `solid` definition, shared by all its uses (null if the
    /// name is undefined or its definition had errors).
    NodePtr solidNamed(const std::string& name) const;

private:
    enum class State { Pending, Busy, Done, Failed };
    struct LetEntry {
        const Statement* def = nullptr;
        State state = State::Pending;
        Value value;
    };
    struct SolidEntry {
        Statement* def = nullptr;  ///< not const: its tree is freed once lowered
        State state = State::Pending;
        NodePtr node;
    };
    struct MaterialEntry {
        const Statement* def = nullptr;
        int index = 0;
    };

    // lower.cpp
    void collectDefinitions(Program& program, Scene& scene);
    /// Lowers the lets and solids each after those it uses (lang/definition_order.h), so
    /// no chain of names recurses; a chain deeper than kMaxNameDepth is an error.
    void lowerDefinitions();
    void lowerStatement(Statement& s, Scene& scene);
    bool onlyOnce(const Statement& s, const Statement*& first, const char* what);
    std::string cycleMessage(const char* what, const std::vector<std::string>& busy,
                             const std::string& name) const;
    bool enter(SourcePos at);
    void error(SourcePos loc, std::string message, std::string hint = {});

    // lower_expr.cpp
    std::optional<Value> evaluate(const Expr& e, ExprGraph* field);
    std::optional<Value> evaluateName(const Expr& e, ExprGraph* field);
    std::optional<Value> evaluateCall(const Expr& e, ExprGraph* field);
    std::optional<Value> arithmetic(char op, const Value& a, const Value& b, SourcePos at,
                                    ExprGraph* field);
    std::optional<Value> letValue(const std::string& name, SourcePos use);
    std::optional<Value> finite(Value v, SourcePos at, const std::string& what);
    /// Evaluates a property (which must exist) and checks its type against its spec.
    std::optional<Value> propertyValue(const PropertyBlock& block, const std::string& name);
    /// Read an optional property into `out` (left alone when absent); false on any error.
    bool readNumber(const PropertyBlock& block, const std::string& name, double& out);
    bool readVector(const PropertyBlock& block, const std::string& name, Vec3& out);
    /// A number that must be an integer in [lo, hi].
    bool readInteger(const PropertyBlock& block, const std::string& name, int lo, int hi, int& out);

    // lower_solids.cpp
    NodePtr lowerSolid(const Solid& s);
    NodePtr lowerReference(const Solid& s);
    NodePtr lowerBoolean(const Solid& s);
    NodePtr lowerPrimitive(const Solid& s);
    NodePtr lowerSphere(const Solid& s);
    NodePtr lowerBox(const Solid& s);
    NodePtr lowerCylinder(const Solid& s);
    NodePtr lowerCone(const Solid& s);
    NodePtr lowerTorus(const Solid& s);
    NodePtr lowerHalfSpace(const Solid& s);
    NodePtr lowerImplicit(const Solid& s);
    /// The box of a `box { min max }` block; `what` is "box" or "bound" (for the message).
    std::optional<Bounds3> boxBounds(const Solid& s, const char* what);
    NodePtr applyModifiers(NodePtr node, const Solid& s);
    std::optional<Affine> modifierTransform(const Modifier& m);
    /// False, with an error at `m`, when the transforms folded up to `m` are unusable.
    bool checkFolded(const Affine& folded, const Modifier& m);
    /// makeTransform, or null with an error at `last` when the result's extent overflows.
    NodePtr transformed(const NodePtr& node, const Affine& map, const Modifier& last);
    std::optional<int> materialIndex(const std::string& name, SourcePos use);
    NodePtr solidByName(const std::string& name, SourcePos use);
    /// The height of a tree made while lowering (a leaf is 1), memoised on node identity.
    int heightOf(const NodePtr& node);
    /// `node`, or null with an error at `at` if its tree is deeper than kMaxCsgDepth.
    NodePtr limitDepth(NodePtr node, SourcePos at);

    // lower_scene.cpp
    void lowerMaterial(const Statement& s, Material& m);
    void checkEnergy(const PropertyBlock& b, const Material& m);
    void lowerCamera(const Statement& s, CameraDesc& camera);
    std::optional<Light> lowerLight(const Statement& s);
    void lowerMist(const Statement& s, Mist& mist);
    void lowerRender(const Statement& s, RenderSettings& settings);
    void lowerBackground(const Statement& s, Vec3& background);

    DiagnosticSink& mSink;
    std::map<std::string, LetEntry> mLets;
    std::map<std::string, SolidEntry> mSolids;
    std::map<std::string, MaterialEntry> mMaterials;
    std::vector<std::string> mBusyLets;    ///< lets being evaluated, innermost last
    std::vector<std::string> mBusySolids;  ///< solids being lowered, innermost last
    int mDepth = 0;  ///< current recursion depth of lowering
    /// heightOf's memo; holding the NodePtr keeps the key's address from being reused.
    std::unordered_map<const Node*, std::pair<NodePtr, int>> mHeights;
    bool mTooDeepReported = false;
    const Statement* mCamera = nullptr;
    const Statement* mMist = nullptr;
    const Statement* mRender = nullptr;
    const Statement* mBackground = nullptr;
};

/// Formats a number for messages, shortest form ("1", "0.5", "1e+400" is inf).
std::string formatNumber(double v);
std::string formatVector(const Vec3& v);

}  // namespace kerf
