/// @file io/image_plugin_loader.h
/// @brief Loading the image plug-in once per process, on first use (io/image.h declares the
/// public side: setImagePluginPath).
#pragma once

#include <string>
#include <vector>

#include "io/image_plugin.h"

namespace kerf {

/// The loaded plug-in; loads it on the first call (thread-safe: concurrent callers wait for
/// the one load). Throws ImageSupportError when it cannot be loaded, on every call.
const KerfImagePlugin& imagePlugin();

/// @brief The places the plug-in is looked for, in order: the path set by setImagePluginPath
/// alone, or else `kerf_image_plugin.so` beside the running executable (the build tree:
/// build/kerf) and in `../lib/kerf/` from it (an install: P/bin/kerf, P/lib/kerf/).
std::vector<std::string> imagePluginCandidates();

/// @brief Loads the plug-in now, so a command that will read or write an image fails before
/// any work when it cannot (throws ImageSupportError naming every path tried).
void requireImagePlugin();

}  // namespace kerf
