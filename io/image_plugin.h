/// @file io/image_plugin.h
/// @brief The C interface between kerf and its image plug-in (io/plugin/), the only code that
/// includes OpenImageIO. Plain C types across the boundary: no exceptions, no std::string, so
/// the plug-in and the executable need not agree on anything but this struct.
#pragma once

#include <stddef.h>
#include <stdint.h>

extern "C" {

/// Bumped whenever KerfImagePlugin changes; the loader refuses a plug-in of another version.
#define KERF_IMAGE_PLUGIN_ABI 1

/// Called by `read` once the file's size is known; returns room for width·height·channels
/// floats (or null to abort). `integerCoded` is 1 when the file stores 8- or 16-bit codes.
typedef float* (*KerfImageAllocate)(void* user, int width, int height, int channels,
                                    int integerCoded);

struct KerfImagePlugin {
    int abiVersion;  ///< KERF_IMAGE_PLUGIN_ABI
    /// Writes interleaved pixels, top row first, to `path` in the format its extension names:
    /// 8-bit codes (`pixels` is uint8_t[]) when `bytes` is 1, else float (`pixels` is float[]).
    /// `colorSpace` is stored as the file's colour space. Returns 0, or nonzero with a message
    /// in `error` (NUL-terminated, cut to `errorSize`).
    int (*write)(const char* path, int width, int height, int channels, int bytes,
                 const void* pixels, const char* colorSpace, char* error, size_t errorSize);
    /// Reads `path` as floats into the buffer `allocate` returns. Returns 0 or nonzero with a
    /// message in `error`.
    int (*read)(const char* path, KerfImageAllocate allocate, void* user, char* error,
                size_t errorSize);
};

/// The plug-in's one exported symbol.
typedef const KerfImagePlugin* (*KerfImagePluginEntry)(void);
#define KERF_IMAGE_PLUGIN_ENTRY "kerf_image_plugin"

}  // extern "C"
