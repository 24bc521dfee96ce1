/// @file render/image.h
/// @brief A float image (linear values, interleaved channels) and its output through
/// OpenImageIO: written to a temporary file beside the target and renamed, so a failed run
/// never leaves a half-written file nor clobbers an earlier one.
#pragma once

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

/// Thrown for an output that cannot be written; what() names the file and the reason.
struct ImageWriteError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Writes by the file's extension: .png/.jpg/.jpeg as 8-bit sRGB, .exr/.tif/.tiff as float
/// linear. Throws ImageWriteError for an unknown extension or a failed write.
void writeImage(const Image& image, const std::string& path);

/// Reads any format OpenImageIO knows into float values (8-bit files decoded from sRGB to
/// linear). Throws std::runtime_error naming the file on failure. Used by tests.
Image readImage(const std::string& path);

}  // namespace kerf
