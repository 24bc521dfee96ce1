/// @file app/model_loader.cpp
#include "app/model_loader.h"

#include "lang/compile.h"
#include "lang/diagnostic.h"
#include "lang/openscad_csg.h"
#include "lang/source.h"

#include <cerrno>
#include <cstring>
#include <ostream>

#include <unistd.h>

namespace kerf::app {

namespace {

/// Why `path` cannot be read as a model, or an empty string when it can. Checked here so the
/// message names the file even before the compiler sees it; by stat() alone, so a FIFO
/// or a device is refused without being opened.
std::string unreadableReason(const std::string& path) {
    std::string reason = sourceFileProblem(path);
    if (!reason.empty()) return reason;
    if (::access(path.c_str(), R_OK) != 0) return std::strerror(errno);
    return {};
}

}  // namespace

AssetCache& processAssets() {
    static AssetCache assets;  // lives as long as the process: one compile at a time
    return assets;
}

std::optional<Scene> loadModel(const std::string& path, std::ostream& err, bool quiet,
                               SequenceFrame frame) {
    return loadModel(path, err, processAssets(), quiet, frame);
}

std::optional<Scene> loadModel(const std::string& path, std::ostream& err, AssetCache& assets,
                               bool quiet, SequenceFrame frame) {
    const std::string reason = unreadableReason(path);
    if (!reason.empty()) {
        err << "kerf: error: cannot read model file '" << path << "': " << reason << "\n";
        return std::nullopt;
    }
    DiagnosticSink sink;
    assets.clearInputs();
    // OpenSCAD's exported CSG trees (.csg) have their own reader; everything else is kerf's
    // language.
    std::optional<Scene> scene = isOpenScadCsgPath(path)
                                     ? compileOpenScadFile(path, sink, assets)
                                     : compileFile(path, sink, assets, EvalLimits{}, frame);
    if (!sink.diagnostics().empty()) err << sink.format(!quiet);  // --quiet silences echo
    if (!scene && !sink.hasErrors()) {
        // The contract says errors are reported; never fail silently if one was not.
        err << "kerf: error: '" << path << "' could not be compiled\n";
    }
    return scene;
}

}  // namespace kerf::app
