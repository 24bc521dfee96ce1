/// @file io/image.h
/// @brief A float image (linear values, interleaved channels) and its files. Image files go
/// through OpenImageIO, which lives in a plug-in loaded on first use (io/image_plugin.h), so
/// a process that reads or writes no image loads no image library. Images are encoded in
/// memory and written through io/atomic_file.h, so a failed run never leaves a half-written
/// file nor clobbers an earlier one.
#pragma once

#include "io/atomic_file.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace kerf {

struct Image {
    int width = 0;
    int height = 0;
    int channels = 0;
    std::vector<float> pixels;  ///< row-major from the top row, channels interleaved

    Image() = default;
    Image(int w, int h, int c) : width(w), height(h), channels(c), pixels(size_t(w) * h * c, 0.f) {}
    float& at(int x, int y, int c) { return pixels[(size_t(y) * width + x) * channels + c]; }
    float at(int x, int y, int c) const { return pixels[(size_t(y) * width + x) * channels + c]; }
};

/// Thrown for an output that cannot be written; what() is "cannot write 'F': <reason>".
struct ImageWriteError : FileWriteError {
    using FileWriteError::FileWriteError;
};

/// Thrown when the image plug-in cannot be loaded; what() is
/// "cannot load image support '<path>': <reason>".
struct ImageSupportError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Writes by the file's extension: .png/.jpg/.jpeg as 8-bit sRGB, .exr/.tif/.tiff as float
/// linear. Throws ImageWriteError for an unknown extension or a failed write, and
/// ImageSupportError when the plug-in cannot be loaded.
void writeImage(const Image& image, const std::string& path);

/// Reads any format OpenImageIO knows into float values (8-bit files decoded from sRGB to
/// linear). Throws std::runtime_error naming the file on failure. Used by tests.
Image readImage(const std::string& path);

/// Where the image plug-in is looked for: by default `kerf_image_plugin.so` in the folder of
/// the running executable (/proc/self/exe). Programs elsewhere (the test executables) set it
/// before the first image is read or written; later calls have no effect.
void setImagePluginPath(const std::string& path);
std::string imagePluginPath();

}  // namespace kerf
