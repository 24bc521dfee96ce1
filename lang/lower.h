/// @file lang/lower.h
/// @brief Lowering: a parsed Program (includes already spliced in) becomes a Scene. Names are
/// declarative (a solid, let or material may be used before its definition); each `solid` is
/// lowered once and every use shares the same NodePtr. All meaning is checked here: types,
/// ranges, undefined names and cycles, each reported once at its own location.
///
/// The work is split by subject: lower.cpp (definitions and statements), one lower_<subject>.cpp
/// per subject (expressions, values, calls, blocks, solids, modifiers, ...; each file's first
/// comment says what it lowers).
///
/// Scopes: top-level lets, solids, materials and functions are order-independent. Names made
/// inside a block (a loop variable, a let in a for or if body, a comprehension variable, a
/// function's parameters) are local: visible after their line to the end of their block,
/// shadowing top-level names. A function body sees its parameters and the top level only.
#pragma once

#include "csg/profiles/profile.h"
#include "csg/tape/expr.h"
#include "lang/ast.h"
#include "lang/eval_limits.h"
#include "lang/no_assets.h"
#include "lang/properties.h"
#include "lang/sequence_frame.h"
#include "lang/value.h"
#include "scene/assets.h"
#include "scene/limits.h"
#include "scene/scene.h"

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace kerf {

struct SolidKind;

class Lowering {
    friend struct SolidKindRows;  // lang/solid_kinds.cpp: the rows name the lowering functions

public:
    /// Assets (meshes, volumes, textures, fonts) come from `assets` (scene/assets.h).
    Lowering(DiagnosticSink& sink, AssetProvider& assets, EvalLimits limits = {})
        : mSink(sink), mAssets(assets), mLimits(limits) {}
    /// Without assets (lang/no_assets.h): a model that names a file is an error there.
    explicit Lowering(DiagnosticSink& sink, EvalLimits limits = {})
        : mSink(sink), mAssets(mNoAssets), mLimits(limits) {}
    Lowering(const Lowering&) = delete;
    Lowering& operator=(const Lowering&) = delete;

    /// Lowers the program; nullopt if it reported any error. The syntax tree of each `solid`
    /// definition and `object` is freed once it is lowered (Statement::releaseTree), so the
    /// memory held follows the compiled scene, not the text.
    std::optional<Scene> lower(Program& program);

    /// The values of the predefined names `frame` and `time` (both 0 unless set). Any
    /// definition of the same name in the model hides them, so older models keep their meaning.
    void setSequenceFrame(SequenceFrame frame) { mSequenceFrame = frame; }

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
    /// castsShadow false: the object is `no_shadow`.
    void addObject(NodePtr node, Scene& scene, bool castsShadow = true);
    /// Lowers the lets and solids each after those it uses (lang/definition_order.h), so
    /// no chain of names recurses; a chain deeper than kMaxNameDepth is an error.
    void lowerDefinitions();
    void lowerStatement(Statement& s, Scene& scene);
    bool onlyOnce(const Statement& s, const Statement*& first, const char* what);
    std::string cycleMessage(const char* what, const std::vector<std::string>& busy,
                             const std::string& name) const;
    bool enter(SourcePos at);
    /// A file name written at `at`, relative to the folder of the model file it is written in
    /// (as includes are), unless absolute.
    std::string resolvedPath(const std::string& written, SourcePos at) const;
    void error(SourcePos loc, std::string message, std::string hint = {});

    // lower_expr.cpp
    std::optional<Value> evaluate(const Expr& e, ExprGraph* field);
    std::optional<Value> evaluateName(const Expr& e, ExprGraph* field);
    std::optional<Value> evaluateCall(const Expr& e, ExprGraph* field);
    std::optional<Value> arithmetic(char op, const Value& a, const Value& b, SourcePos at,
                                    ExprGraph* field);
    std::optional<Value> letValue(const std::string& name, SourcePos use);
    /// A value that must be a number (its type named in the error otherwise).
    std::optional<double> numberValue(const Expr& e, const char* what);

    // lower_values.cpp
    std::optional<Value> evaluateValue(const Expr& e, ExprGraph* field);
    std::optional<Value> compare(char op, const Value& a, const Value& b, SourcePos at);
    std::optional<Value> logic(const Expr& e, ExprGraph* field);
    std::optional<Value> index(const Expr& e, ExprGraph* field);
    std::optional<Value> member(const Expr& e, ExprGraph* field);
    std::optional<Value> listOf(const Expr& e, ExprGraph* field);
    std::optional<Value> comprehension(const Expr& e, ExprGraph* field);
    std::optional<Value> concatenate(const Value& a, const Value& b, SourcePos at);
    /// Calls `body(value)` for each element of a range or list expression, with the loop
    /// variable bound; a range is walked as a + i·step, never materialised. False on error
    /// (already reported) or when body returns false.
    bool iterate(const Expr& range, const std::string& var, SourcePos varLoc,
                 const std::function<bool()>& body);
    /// Counts one loop iteration against kMaxLoopIterations.
    bool countIteration(SourcePos at);
    /// len, dot, cross, length, normalize, deg, rad, random, str; nullopt with `handled`
    /// false when `name` is none of them.
    std::optional<Value> builtinValue(const Expr& e, const std::vector<Value>& args, bool& handled);
    std::string show(const Value& v) const;

    // lower_calls.cpp
    std::optional<Value> callFunction(const Statement& fn, const Expr& call, ExprGraph* field);
    /// The local named `name` in the current frame, or null.
    const Value* local(const std::string& name) const;
    void pushLocal(const std::string& name, Value v) { mLocals.emplace_back(name, std::move(v)); }
    /// A solid (or the empty solid) from a value, or an error naming its type.
    bool solidOf(const Value& v, SourcePos at, NodePtr& out, bool& empty);

    // lower_blocks.cpp
    void runBlock(const std::vector<Statement>& body, Scene& scene);
    void runFor(const Statement& s, Scene& scene);
    void runIf(const Statement& s, Scene& scene);
    void runAssert(const Statement& s);
    void runEcho(const Statement& s);
    /// A Boolean body's children with for and if expanded; false on error. Empty solids
    /// (a union of nothing) are left out.
    bool expandChildren(const ArenaList<Solid>& children, std::vector<NodePtr>& out);

    std::optional<Value> finite(Value v, SourcePos at, const std::string& what);
    static bool isFinite(const Value& v);
    /// finite() with the message built only when it is needed (numbers are formatted slowly).
    template <class Message>
    std::optional<Value> finiteLazy(Value v, SourcePos at, const Message& what) {
        if (isFinite(v)) return v;
        error(at, "value is not finite: " + what());
        return std::nullopt;
    }
    /// Evaluates a property (which must exist) and checks its type against its spec.
    std::optional<Value> propertyValue(const PropertyBlock& block, const std::string& name);
    /// Read an optional property into `out` (left alone when absent); false on any error.
    bool readNumber(const PropertyBlock& block, const std::string& name, double& out);
    bool readVector(const PropertyBlock& block, const std::string& name, Vec3& out);
    /// A number that must be an integer in [lo, hi].
    bool readInteger(const PropertyBlock& block, const std::string& name, int lo, int hi, int& out);
    bool readBool(const PropertyBlock& block, const std::string& name, bool& out);
    /// A Word property: one of `choices`, written as a bare name.
    bool readWord(const PropertyBlock& block, const std::string& name,
                  const std::vector<std::string>& choices, std::string& out);

    // lower_solids.cpp
    NodePtr lowerSolid(const Solid& s);
    NodePtr lowerReference(const Solid& s);
    NodePtr lowerBoolean(const Solid& s);
    NodePtr lowerPrimitive(const Solid& s);
    /// A kind lowered by its row in lang/solid_kinds.cpp: properties, checks, factory.
    NodePtr lowerTabled(const Solid& s, const SolidKind& kind);
    /// Counts one primitive against kMaxPrimitives.
    bool countPrimitive(SourcePos at);
    /// Counts one node made (of any kind) against kMaxNodes.
    bool countNode(SourcePos at);
    NodePtr lowerBox(const Solid& s);
    NodePtr lowerCylinder(const Solid& s);
    NodePtr lowerCone(const Solid& s);
    NodePtr lowerTorus(const Solid& s);
    NodePtr lowerHalfSpace(const Solid& s);
    NodePtr lowerImplicit(const Solid& s);
    // lower_mesh.cpp
    /// `mesh FILE smooth B`: the file loaded once per compile (mMeshFiles), one leaf per use.
    NodePtr lowerMesh(const Solid& s);
    /// The shape of the file `written` at `at`, resolved against the model's folder; null
    /// with an error when it cannot be loaded.
    std::shared_ptr<const MeshAsset> meshAsset(const std::string& written, SourcePos at);
    /// False, with an error at the mesh, when one of `operands` is (a transform, material or
    /// motion of) a mesh that is not a solid; `use` says what needs a solid ("an operand of
    /// difference"), written at `at`. Each such mesh is reported once.
    bool checkSolidOperands(const std::vector<NodePtr>& operands, const std::string& use,
                            SourcePos at);
    /// The same for the objects of a scene with section planes: an object a plane crosses is cut.
    void checkSectionedSurfaces(const Scene& scene);
    // lower_volume.cpp
    /// `volume "FILE" grid NAME`: a level set read from a .vdb file (volume/grids/vdb_level_set.h),
    /// each (file, grid) loaded once per compile and shared by its uses.
    NodePtr lowerVolume(const Solid& s);
    // lower_surfaces.cpp
    /// `disc`, `triangle`, `surface SOLID`, `clip SURFACE by SOLID` (csg/primitives/surfaces.h).
    NodePtr lowerSurface(const Solid& s);
    /// A surface node made at `at`, remembered so that using it as a solid names it.
    NodePtr noteSurface(NodePtr surface, SourcePos at);
    /// checkSolidOperands' part for surfaces: false, with an error, when an operand is one.
    bool checkSurfaceOperands(const std::vector<NodePtr>& operands, const std::string& use,
                              SourcePos at);
    /// `interior MATERIAL`: makeInterior below any material modifiers (the innermost wins).
    NodePtr interiorOf(const NodePtr& node, int32_t material);
    // lower_text.cpp
    /// A `text { string … font … size … }` profile laid out (scene/assets.h); nullopt with
    /// an error at the property at fault (a missing font at `font`, a missing glyph at
    /// `string`). The caller takes the union of `glyphs` when `glyphsOverlap`.
    std::optional<TextShape> lowerText(const Solid& s);
    /// lowerText as a profile: one path, or the union of the glyphs when they overlap.
    std::optional<Profile> textProfile(const Solid& s);

    /// The box of a `box { min max }` block; `what` is "box" or "bound" (for the message).
    std::optional<Bounds3> boxBounds(const Solid& s, const char* what);
    NodePtr applyModifiers(NodePtr node, const Solid& s);
    std::optional<Affine> modifierTransform(const Modifier& m);
    /// lower_displace.cpp: `node` displaced by m's pattern (null with an error when it cannot be).
    NodePtr displaced(const NodePtr& node, const Modifier& m);
    /// A move's or spin's vector, checked.
    std::optional<Vec3> motionVector(const Modifier& m);
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

    // lower_profiles.cpp: 2-D profiles (csg/profiles/profile.h) and the solids made from them.
    /// circle, rect, polygon, path, offset, or a union / intersection / difference of them.
    std::optional<Profile> lowerProfile(const Solid& s);
    std::optional<Profile> lowerPath(const Solid& s);
    /// The block's required `profile` property, lowered.
    std::optional<Profile> profileProperty(const PropertyBlock& b);
    NodePtr lowerExtrude(const Solid& s);
    NodePtr lowerRevolve(const Solid& s);
    /// A 2-D point written [x, y]; `what` names it in messages.
    bool point2(const Expr& e, const std::string& what, Vec2& out);
    /// extrude's `scale`: a number, or [sx, sy] per profile axis; both positive.
    bool extrudeScale(const Expr& e, Vec2& out);
    /// A list of at least three 2-D points.
    bool points2(const Value& v, SourcePos at, const std::string& what, std::vector<Vec2>& out);

    // lower_scene.cpp
    void lowerMaterial(const Statement& s, Material& m);
    // lower_patterns.cpp: a `pattern KIND { … }` (kept as a Primitive solid by the parser).
    std::shared_ptr<const Pattern> lowerPattern(const Solid& s);
    /// An image pattern's `file` (opened now: a bad file is an error here) and `mapping`.
    bool lowerImage(const PropertyBlock& b, Pattern& pattern);
    void checkEnergy(const PropertyBlock& b, const Material& m);
    void lowerCamera(const Statement& s, CameraDesc& camera);
    std::optional<Light> lowerLight(const Statement& s);
    // lower_mist.cpp: homogeneous mist, or a heterogeneous medium when it has a density.
    void lowerMist(const Statement& s, Scene& scene);
    /// The homogeneous mist (no density).
    void lowerUniformMist(const PropertyBlock& b, const Statement& s, Scene& scene);
    /// A medium's scalar properties (extinction, albedo, …), checked; false on error.
    bool lowerMediumProperties(const PropertyBlock& b, Medium& medium);
    /// `bounds box { … }` or min and max; false on error, nullopt in `out` when absent.
    bool lowerMistBounds(const PropertyBlock& b, const Statement& s, std::optional<Bounds3>& out);
    /// `density volume "file.vdb" [grid "name"]`.
    bool lowerFogDensity(const PropertyBlock& b, const Statement& s,
                         const std::optional<Bounds3>& bounds, Medium& medium);
    /// `density EXPR`, and the `bake N` request (the bake is made by render/).
    bool lowerExprDensity(const PropertyBlock& b, const std::optional<Bounds3>& bounds,
                          Medium& medium);
    /// The density's finite bound and sign over its box; false with an error.
    bool checkDensity(const Property& density, const Medium& medium);
    void lowerRender(const Statement& s, RenderSettings& settings);
    void lowerBackground(const Statement& s, Scene& scene);
    // lower_sections.cpp
    void lowerSection(const Statement& s, Scene& scene);

    // lower_calls.cpp: the steps of callFunction
    /// The parameter slot a named argument binds to, or nullopt with an error.
    std::optional<size_t> namedSlot(const Statement& fn, const Expr& a,
                                    const std::vector<std::optional<Value>>& bound);
    /// Binds a call's arguments, evaluated in the caller's scope, by position then by name;
    /// false, with an error, when one is unknown, repeated or missing without a default.
    bool bindArguments(const Statement& fn, const Expr& call, ExprGraph* field,
                       std::vector<std::optional<Value>>& bound);
    /// Evaluates fn's body in a frame of its parameters (defaults evaluated there first),
    /// returning a memoised result for a call seen before.
    std::optional<Value> runCall(const Statement& fn, const Expr& call, ExprGraph* field,
                                 std::vector<std::optional<Value>>& bound);

    // lower_expr.cpp: the steps of evaluateCall
    /// len, dot, cross, … (builtinValue) on arguments evaluated here, none a field.
    std::optional<Value> callValueBuiltin(const Expr& e, ExprGraph* field);
    /// The error for a call of a name that is no function, with a hint.
    void reportUnknownFunction(const Expr& e);
    /// A math function (sin, pow, mix, noise, …, by its index in lower_expr.cpp's table) on
    /// numbers or fields.
    std::optional<Value> applyMathFunction(const Expr& e, int function,
                                           const std::vector<Value>& args, ExprGraph* field);

    // lower_lights.cpp: the steps of lowerLight
    /// The light's kind from its name, and the properties that kind takes; false, with an
    /// error, for an unknown kind.
    bool lightKind(const Statement& s, Light& light, std::vector<PropertySpec>& specs);
    /// Reads the properties of the light's kind; false on any error.
    bool readLight(const PropertyBlock& b, Light& light);
    /// Checks the values read (colour, power, fade, direction, edges, radius), reporting each
    /// one at fault.
    bool checkLight(const PropertyBlock& b, const Light& light);

    // lower_profiles.cpp: the profiles of lowerProfile and the steps of lowerPath
    std::optional<Profile> profileBoolean(const Solid& s);
    std::optional<Profile> circleProfile(const Solid& s);
    std::optional<Profile> rectProfile(const Solid& s);
    std::optional<Profile> polygonProfile(const Solid& s);
    std::optional<Profile> offsetProfile(const Solid& s);
    /// The `count` points of path step `name` (one point, or a list of `count`); false with
    /// an error.
    bool readPathPoints(const Property& p, const std::string& name, int count,
                        std::vector<Vec2>& pts);
    /// The segment of path step `name` from `at`; an arc's ends must be equally far from its
    /// center.
    std::optional<PathSegment> pathSegment(const Property& p, const std::string& name, Vec2 at,
                                           const std::vector<Vec2>& pts);

    // lower_scene.cpp: the steps of lowerCamera
    /// Reads and checks the shutter, aperture and focus distance; `ok` false on any error
    /// (the checks run only while it is true).
    void readCameraLens(const PropertyBlock& b, CameraDesc& camera, bool& ok);
    /// Checks the field of view, and that eye, look_at and up make a view (finite, apart, not
    /// parallel); reports the first fault of the view.
    void checkCameraView(const Statement& s, const PropertyBlock& b, const CameraDesc& camera);

    // lower_surfaces.cpp: the kinds of lowerSurface
    NodePtr lowerDisc(const Solid& s);
    NodePtr lowerTriangle(const Solid& s);

    // lower_values.cpp: the steps of builtinValue
    /// True when argument i of call e has type t; false with an error naming both types.
    bool expectArgument(const Expr& e, const std::vector<Value>& args, size_t i, Value::Type t);
    /// random(seed, index): a hash of two whole numbers into [0, 1), the same on every machine.
    std::optional<Value> randomValue(const Expr& e, const std::vector<Value>& args);
    /// str(a, b, …): the values written out and joined.
    std::optional<Value> joinedString(const Expr& e, const std::vector<Value>& args);

    DiagnosticSink& mSink;
    NoAssets mNoAssets;  ///< mAssets when no provider was given
    AssetProvider& mAssets;
    EvalLimits mLimits;
    SequenceFrame mSequenceFrame;
    std::map<std::string, const Statement*> mFunctions;
    /// Locals, innermost last; a function call hides those below mFrameBase.
    std::vector<std::pair<std::string, Value>> mLocals;
    size_t mFrameBase = 0;
    struct Call {
        const std::string* name;
        SourcePos at;
    };
    std::vector<Call> mCalls;  ///< the function calls being evaluated, innermost last
    /// Results of calls that made solids, by function and argument values: the same call
    /// returns the same shared subtree.
    std::unordered_map<std::string, Value> mCallMemo;
    std::unordered_set<const Statement*> mReturnsOther;  ///< functions seen returning a non-solid
    int64_t mIterations = 0;
    int64_t mPrimitives = 0;
    int64_t mNodes = 0;
    bool mLimitReported = false;
    std::optional<int> mDefaultMaterial;
    const Statement* mDefaultMaterialDef = nullptr;
    std::map<std::string, LetEntry> mLets;
    std::map<std::string, SolidEntry> mSolids;
    std::map<std::string, MaterialEntry> mMaterials;
    std::vector<std::string> mBusyLets;    ///< lets being evaluated, innermost last
    std::vector<std::string> mBusySolids;  ///< solids being lowered, innermost last
    int mDepth = 0;                        ///< current recursion depth of lowering
    /// heightOf's memo; holding the NodePtr keeps the key's address from being reused.
    std::unordered_map<const Node*, std::pair<NodePtr, int>> mHeights;
    bool mTooDeepReported = false;
    /// Mesh files by canonical path: each is loaded once and its shape shared by every use
    /// (null after a failed load, which was reported at its first use).
    std::map<std::string, std::shared_ptr<const MeshAsset>> mMeshFiles;
    /// Level sets by canonical path and grid name (null after a failed load, reported once).
    std::map<std::pair<std::string, std::string>, std::shared_ptr<const LevelSetAsset>>
        mVolumeFiles;
    /// The leaves of meshes that are not solids, with where they were written (holding the
    /// node keeps its address from being reused).
    struct OpenMesh {
        NodePtr leaf;
        SourcePos at;
        std::shared_ptr<const MeshAsset> mesh;
    };
    std::unordered_map<const Node*, OpenMesh> mOpenMeshes;
    /// The `mesh` expressions already reported as not solid (file index << 32 | offset): a
    /// loop or a function makes a leaf per pass, the error is given once.
    std::unordered_set<uint64_t> mReportedOpenMeshes;
    /// Surface nodes by where they were written (holding the node keeps its address).
    std::unordered_map<const Node*, std::pair<NodePtr, SourcePos>> mSurfaces;
    std::vector<SourcePos> mSectionLocs;  ///< where each of scene.sections was written
    const Statement* mCamera = nullptr;
    const Statement* mMist = nullptr;
    const Statement* mRender = nullptr;
    const Statement* mBackground = nullptr;
};

/// The empty solid (a union of nothing, e.g. from a loop over an empty range): a marker
/// compared by identity, never put into a scene. Booleans drop it, objects of it add nothing.
const NodePtr& emptySolid();

/// True for the names of built-in functions (sin, len, random, …), which a `fn` may not take.
bool isBuiltinFunction(const std::string& name);

/// Formats a number for messages, shortest form ("1", "0.5", "1e+400" is inf).
std::string formatNumber(double v);
std::string formatVector(const Vec3& v);

}  // namespace kerf
