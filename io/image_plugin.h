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
/// 3: image textures (`textureOpen`, `textureLookup`) through OpenImageIO's TextureSystem.
/// 4: images placed in a larger one (`encodeWindow`, `readWindow`: EXR data windows).
#define KERF_IMAGE_PLUGIN_ABI 4

/// A texture opened by `textureOpen`; owned by the plug-in and valid until the process ends.
typedef struct KerfTexture KerfTexture;

/// How a texture coordinate outside [0, 1) is taken (KerfImagePlugin::textureLookup).
#define KERF_TEXTURE_WRAP_PERIODIC 0
#define KERF_TEXTURE_WRAP_CLAMP 1

/// The largest texture `textureOpen` decodes, checked on the file's header before any pixel is
/// allocated (docs/robustness.md, "Limits"): 16,384 texels a side and 2^26 texels in all
/// (8,192², or 16,384 × 4,096). At the limit the linear RGB copy is 768 MB and the cache's
/// MIP levels about as much again; a header may claim 2^31 a side in 70 bytes.
#define KERF_TEXTURE_MAX_SIDE 16384
#define KERF_TEXTURE_MAX_TEXELS (1 << 26)

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
    /// Opens `path` as a texture: decodes it once (8- and 16-bit codes taken as sRGB and
    /// made linear, so filtering averages light, not codes) and hands it to the process's
    /// one TextureSystem, which builds its MIP levels. Opening the same path again returns the
    /// same texture. Returns 0 with `*texture`, `*width` and `*height` set, or nonzero with a
    /// message in `error` (missing file, unreadable, not an image).
    int (*textureOpen)(const char* path, KerfTexture** texture, int* width, int* height,
                       char* error, size_t errorSize);
    /// The texture's linear RGB filtered over the footprint whose axes in texture space are
    /// (dsdx, dtdx) and (dsdy, dtdy), centred at (s, t): s across, t down the image (0 at
    /// the top row, texel centres at (i + ½)/width). MIP-mapped with anisotropic filtering;
    /// a zero footprint still gets the bilinear filter of the texels. A grey image gives its
    /// value in all three channels. Thread-safe (per-thread state stays with each thread).
    /// `wrapS` and `wrapT` are KERF_TEXTURE_WRAP_*.
    void (*textureLookup)(const KerfTexture* texture, float s, float t, float dsdx, float dtdx,
                          float dsdy, float dtdy, int wrapS, int wrapT, float rgb[3]);
    /// `encode` of an image that is the part at (x, y) of a fullWidth × fullHeight image: the
    /// file's data window inside its display window, where the format has them (OpenEXR,
    /// TIFF); other formats store the part alone.
    int (*encodeWindow)(const char* fileName, int width, int height, int channels, int bytes,
                        const void* pixels, const char* colorSpace, int x, int y, int fullWidth,
                        int fullHeight, KerfImageBytes sink, void* user, char* error,
                        size_t errorSize);
    /// `read`, also giving where the pixels sit: window = {x, y, fullWidth, fullHeight} (the
    /// data window's corner and the display window's size; the display window starts at 0).
    int (*readWindow)(const char* path, KerfImageAllocate allocate, void* user, int window[4],
                      char* error, size_t errorSize);
};

/// The plug-in's one exported symbol.
typedef const KerfImagePlugin* (*KerfImagePluginEntry)(void);
#define KERF_IMAGE_PLUGIN_ENTRY "kerf_image_plugin"

}  // extern "C"
