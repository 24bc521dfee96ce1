/// @file io/image_plugin_loader.h
/// @brief Loading the image plug-in once per process, on first use (io/image.h declares the
/// public side: setImagePluginPath).
#pragma once

#include "io/image_plugin.h"

namespace kerf {

/// The loaded plug-in; loads it on the first call (thread-safe: concurrent callers wait for
/// the one load). Throws ImageSupportError when it cannot be loaded, on every call.
const KerfImagePlugin& imagePlugin();

}  // namespace kerf
