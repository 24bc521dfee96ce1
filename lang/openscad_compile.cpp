// The .csg front door: parse, lower, turn OpenSCAD's z-up model to kerf's y-up and frame it
// with a default camera and lights (openscad_lower.cpp lowers the nodes).
#include "lang/openscad_lower.h"

#include "csg/affine_check.h"
#include "csg/tree/solids.h"
#include "lang/no_assets.h"
#include "lang/source.h"

#include <algorithm>
#include <cmath>

namespace kerf {

namespace {

/// OpenSCAD (x, y, z) with z up ↦ kerf (x, z, −y) with y up: a rotation by −90° about x.
Affine kerfFromOpenScad() {
    const double m[12] = {1, 0, 0, 0, 0, 0, 1, 0, 0, -1, 0, 0};
    return Affine::fromRowMajor(m);
}

/// A camera looking at the whole model from OpenSCAD's default direction (front, right,
/// above: its default view turns 55° about x and 25° about z), and lights from the camera's
/// side, so an exported model looks as it did in OpenSCAD.
void frameScene(Scene& scene, const Bounds3& box) {
    const Vec3 center = 0.5 * (box.lo + box.hi);
    const double radius = std::max(0.5 * glm::length(box.hi - box.lo), 1e-300);
    const double a = 55.0 * M_PI / 180.0, b = 25.0 * M_PI / 180.0;
    const Vec3 scadView(std::sin(b) * std::sin(a), -std::cos(b) * std::sin(a), std::cos(a));
    const Vec3 view = kerfFromOpenScad().vector(scadView);
    scene.camera.fovDegrees = 40.0;
    const double distance = 1.1 * radius / std::sin(0.5 * scene.camera.fovDegrees * M_PI / 180.0);
    scene.camera.eye = center + distance * view;
    scene.camera.lookAt = center;
    scene.camera.up = Vec3(0, 1, 0);
    Light key;
    key.kind = Light::Kind::Directional;
    key.direction = -glm::normalize(view + Vec3(-0.9, 1.1, 0.0));
    key.color = Vec3(0.9);
    Light fill = key;
    fill.direction = -glm::normalize(view + Vec3(0.6, -0.2, 0.0));
    fill.color = Vec3(0.35);
    fill.shadows = false;
    scene.lights = {key, fill};
    scene.background = Vec3(1.0, 1.0, 0.9);  // OpenSCAD's pale background
}

}  // namespace

std::optional<Scene> compileOpenScadString(const std::string& text, const std::string& name,
                                           DiagnosticSink& sink) {
    NoAssets none;
    return compileOpenScadString(text, name, sink, none);
}

std::optional<Scene> compileOpenScadString(const std::string& text, const std::string& name,
                                           DiagnosticSink& sink, AssetProvider& assets) {
    const int errorsBefore = sink.errorCount();
    const size_t diagnosticsBefore = sink.diagnostics().size();
    SourceText source{std::make_shared<const std::string>(name),
                      std::make_shared<const std::string>(text)};
    const uint32_t file = sink.sourceIndex(source.name, source.text);
    if (!checkSourceText(source, sink)) return std::nullopt;
    const std::vector<ScadCall> calls = parseOpenScadCsg(*source.text, file, sink);
    Scene scene;
    scene.materials[0].color = Vec3(0.976, 0.843, 0.173);  // OpenSCAD's default face colour
    scene.materials[0].specular = 0.2;
    ScadLowering lowering(sink, scene, assets);
    NodePtr root;
    if (sink.errorCount() == errorsBefore) root = lowering.lowerAll(calls);
    lowering.finish();
    if (sink.errorCount() == errorsBefore) lowering.reportFacets();
    sink.sortByLocation(diagnosticsBefore);
    if (sink.errorCount() > errorsBefore) return std::nullopt;
    if (!root) {
        Diagnostic d;
        d.loc = SourceLoc{source.name, 1, 1};
        d.severity = Severity::Warning;
        d.message = "the file holds no solid: the scene is empty";
        sink.report(std::move(d));
        return scene;
    }
    NodePtr turned = makeTransform(root, kerfFromOpenScad());
    if (!turned->bounds().finite()) {  // only sizes near the largest double get here
        sink.error(SourceLoc{source.name, 1, 1},
                   "the model's extent overflows the range of doubles");
        return std::nullopt;
    }
    frameScene(scene, turned->bounds());
    scene.objects.push_back(turned);
    return scene;
}

std::optional<Scene> compileOpenScadFile(const std::string& path, DiagnosticSink& sink) {
    NoAssets none;
    return compileOpenScadFile(path, sink, none);
}

std::optional<Scene> compileOpenScadFile(const std::string& path, DiagnosticSink& sink,
                                         AssetProvider& assets) {
    const std::optional<SourceText> source = readModelFile(path, sink);
    if (!source) return std::nullopt;
    assets.sourceRead(path);
    return compileOpenScadString(*source->text, path, sink, assets);
}

bool isOpenScadCsgPath(const std::string& path) {
    if (path.size() < 4) return false;
    std::string ext = path.substr(path.size() - 4);
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char ch) { return std::tolower(ch); });
    return ext == ".csg";
}

}  // namespace kerf
