/// @file io/image_plugin_loader.cpp
/// @brief dlopen of the image plug-in, once, from the folder of the running executable.
#include "io/image_plugin_loader.h"

#include <dlfcn.h>

#include <filesystem>
#include <mutex>
#include <string>

#include "io/image.h"

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

std::string besideExecutable() {
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) return kPluginFile;  // no /proc: let dlopen search its usual places
    return (exe.parent_path() / kPluginFile).string();
}

void load(PluginState& s, const std::string& path) {
    const auto fail = [&](const std::string& reason) {
        s.error = "cannot load image support '" + path + "': " + reason;
    };
    // Never closed: OpenImageIO keeps threads and static state until the process ends.
    // RTLD_LAZY as at process start: RTLD_NOW would bind every symbol of the ~260 libraries
    // OpenImageIO pulls in, most of which are never called.
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

std::string imagePluginPath() {
    PluginState& s = state();
    std::lock_guard<std::mutex> lock(s.pathMutex);
    return s.path.empty() ? besideExecutable() : s.path;
}

const KerfImagePlugin& imagePlugin() {
    PluginState& s = state();
    std::call_once(s.once, [&] { load(s, imagePluginPath()); });
    if (s.plugin == nullptr) throw ImageSupportError(s.error);
    return *s.plugin;
}

}  // namespace kerf
