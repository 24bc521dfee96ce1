/// @file app/model_loader.cpp
#include "app/model_loader.h"

#include "lang/compile.h"
#include "lang/diagnostic.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <system_error>

namespace kerf::app {

namespace {

/// Why `path` cannot be read as a model, or an empty string when it can. Checked here so the
/// message names the file even before the compiler sees it.
std::string unreadableReason(const std::string& path) {
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status)) return "no such file";
    if (std::filesystem::is_directory(status)) return "it is a directory";
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::strerror(errno);
    return {};
}

}  // namespace

std::optional<Scene> loadModel(const std::string& path, std::ostream& err) {
    const std::string reason = unreadableReason(path);
    if (!reason.empty()) {
        err << "kerf: error: cannot read model file '" << path << "': " << reason << "\n";
        return std::nullopt;
    }
    DiagnosticSink sink;
    std::optional<Scene> scene = compileFile(path, sink);
    if (!sink.diagnostics().empty()) err << sink.format();
    if (!scene && !sink.hasErrors()) {
        // The contract says errors are reported; never fail silently if one was not.
        err << "kerf: error: '" << path << "' could not be compiled\n";
    }
    return scene;
}

}  // namespace kerf::app
