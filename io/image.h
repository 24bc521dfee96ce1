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

/// Where an image sits inside a larger one: its top-left pixel at (x, y) of a fullWidth ×
/// fullHeight image (a region render, `kerf render --region`).
struct ImageWindow {
    int x = 0, y = 0;
    int fullWidth = 0, fullHeight = 0;
};

/// writeImage of a part of a larger image: .exr and .tif files record the window (the data
/// window inside the display window); .png and .jpg hold the part alone, without its place.
void writeImage(const Image& image, const std::string& path, const ImageWindow& window);

/// readImage that also gives where the pixels sit (for a file without a data window: at 0, 0
/// of an image of their own size).
Image readImage(const std::string& path, ImageWindow& window);

/// Reads any format OpenImageIO knows into float values (8-bit files decoded from sRGB to
/// linear). Throws std::runtime_error naming the file on failure. Used by tests.
Image readImage(const std::string& path);

/// Where the image plug-in is looked for: by default `kerf_image_plugin.so` in the folder of
/// the running executable (/proc/self/exe). Programs elsewhere (the test executables) set it
/// before the first image is read or written; later calls have no effect.
void setImagePluginPath(const std::string& path);
std::string imagePluginPath();

}  // namespace kerf
