/// @file io/image_plugin.h
/// @brief The C interface between kerf and its image plug-in (io/plugin/), the only code that
/// includes OpenImageIO. Plain C types across the boundary: no exceptions, no std::string, so
/// the plug-in and the executable need not agree on anything but this struct.
#pragma once

#include <stddef.h>
#include <stdint.h>

extern "C" {

/// Bumped whenever KerfImagePlugin changes; the loader refuses a plug-in of another version.
/// 2: images are encoded in memory (`encode`), no longer written to disk by the plug-in.
#define KERF_IMAGE_PLUGIN_ABI 2

/// Called by `read` once the file's size is known; returns room for width·height·channels
/// floats (or null to abort). `integerCoded` is 1 when the file stores 8- or 16-bit codes.
typedef float* (*KerfImageAllocate)(void* user, int width, int height, int channels,
                                    int integerCoded);

/// Called by `encode` once, with the whole encoded file; returns 0, or nonzero to fail.
typedef int (*KerfImageBytes)(void* user, const void* data, size_t size);

struct KerfImagePlugin {
    int abiVersion;  ///< KERF_IMAGE_PLUGIN_ABI
    /// Encodes interleaved pixels, top row first, in the format the extension of `fileName`
    /// names, and hands the file's bytes to `sink`; nothing is written to disk (kerf writes
    /// the bytes itself, checking every step: io/atomic_file.h). 8-bit codes (`pixels` is
    /// uint8_t[]) when `bytes` is 1, else float (`pixels` is float[]). `colorSpace` is stored
    /// as the file's colour space. Returns 0, or nonzero with a message in `error`
    /// (NUL-terminated, cut to `errorSize`).
    int (*encode)(const char* fileName, int width, int height, int channels, int bytes,
                  const void* pixels, const char* colorSpace, KerfImageBytes sink, void* user,
                  char* error, size_t errorSize);
    /// Reads `path` as floats into the buffer `allocate` returns. Returns 0 or nonzero with a
    /// message in `error`.
    int (*read)(const char* path, KerfImageAllocate allocate, void* user, char* error,
                size_t errorSize);
};

/// The plug-in's one exported symbol.
typedef const KerfImagePlugin* (*KerfImagePluginEntry)(void);
#define KERF_IMAGE_PLUGIN_ENTRY "kerf_image_plugin"

}  // extern "C"
