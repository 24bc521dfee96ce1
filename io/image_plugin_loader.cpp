/// @file io/image_plugin_loader.cpp
/// @brief dlopen of the image plug-in, once, from beside the running executable or from
/// ../lib/kerf/ relative to it (an installed kerf).
#include "io/image_plugin_loader.h"

#include <dlfcn.h>

#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "io/image.h"
#include "io/png_errors_quiet.h"

namespace kerf {
namespace {

constexpr const char* kPluginFile = "kerf_image_plugin.so";

struct PluginState {
    std::mutex pathMutex;
    std::string path;  ///< empty: beside the executable
    std::once_flag once;
    const KerfImagePlugin* plugin = nullptr;
    std::string error;  ///< why loading failed, when plugin is null after the load
};

PluginState& state() {
    static PluginState s;
    return s;
}

std::vector<std::string> nearExecutable() {
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) return {kPluginFile};  // no /proc: let dlopen search its usual places
    const std::filesystem::path dir = exe.parent_path();
    return {(dir / kPluginFile).string(),
            (dir.parent_path() / "lib" / "kerf" / kPluginFile).lexically_normal().string()};
}

/// The first candidate that exists, or none when no candidate does.
std::string firstExisting(const std::vector<std::string>& candidates) {
    for (const std::string& path : candidates) {
        std::error_code ec;
        if (std::filesystem::exists(path, ec)) return path;
    }
    return {};
}

std::string notFoundMessage(const std::vector<std::string>& candidates) {
    std::string tried;
    for (const std::string& path : candidates) tried += (tried.empty() ? "'" : ", '") + path + "'";
    return "cannot load image support: " + std::string(kPluginFile) +
           " is in none of the places kerf looks: " + tried;
}

void load(PluginState& s, const std::string& path) {
    const auto fail = [&](const std::string& reason) {
        s.error = "cannot load image support '" + path + "': " + reason;
    };
    // Never closed: OpenImageIO keeps threads and static state until the process ends.
    // RTLD_LAZY as at process start: RTLD_NOW would bind every symbol of the ~260 libraries
    // OpenImageIO pulls in, most of which are never called.
    keepPngErrorsQuiet();
    void* handle = ::dlopen(path.c_str(), RTLD_LAZY | RTLD_LOCAL);
    if (handle == nullptr) return fail(::dlerror());
    const auto entry =
        reinterpret_cast<KerfImagePluginEntry>(::dlsym(handle, KERF_IMAGE_PLUGIN_ENTRY));
    if (entry == nullptr) return fail(std::string("no entry point: ") + ::dlerror());
    const KerfImagePlugin* plugin = entry();
    if (plugin == nullptr || plugin->abiVersion != KERF_IMAGE_PLUGIN_ABI)
        return fail("it was built for another version of kerf");
    s.plugin = plugin;
}

}  // namespace

void setImagePluginPath(const std::string& path) {
    PluginState& s = state();
    std::lock_guard<std::mutex> lock(s.pathMutex);
    s.path = path;
}

std::vector<std::string> imagePluginCandidates() {
    PluginState& s = state();
    std::lock_guard<std::mutex> lock(s.pathMutex);
    if (!s.path.empty()) return {s.path};
    return nearExecutable();
}

std::string imagePluginPath() {
    const std::vector<std::string> candidates = imagePluginCandidates();
    const std::string found = firstExisting(candidates);
    return found.empty() ? candidates.front() : found;
}

const KerfImagePlugin& imagePlugin() {
    PluginState& s = state();
    std::call_once(s.once, [&] {
        const std::vector<std::string> candidates = imagePluginCandidates();
        const std::string found = firstExisting(candidates);
        // A set path or a bare name (no /proc) goes to dlopen as it is, which explains itself.
        if (found.empty() && candidates.size() > 1) {
            s.error = notFoundMessage(candidates);
            return;
        }
        load(s, found.empty() ? candidates.front() : found);
    });
    if (s.plugin == nullptr) throw ImageSupportError(s.error);
    return *s.plugin;
}

void requireImagePlugin() { imagePlugin(); }

}  // namespace kerf
