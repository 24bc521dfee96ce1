/// @file io/png_write.h
/// @brief PNG encoding in memory through libpng, without the image plug-in: a PNG output
/// costs no OpenImageIO load (about 0.2 s and 260 shared objects), which the plug-in keeps
/// for EXR, TIFF, JPEG, windows of a larger image and every read.
#pragma once

#include <cstdint>
#include <string>

namespace kerf {

/// Encodes 8-bit sRGB codes, `channels` (1 grey, 2 grey + alpha, 3 RGB, 4 RGBA; alpha written
/// as given, unassociated) per pixel, row by row from the top, as a PNG marked sRGB (with the gAMA
/// and cHRM chunks readers without sRGB support use) into `bytes`. Returns "" or libpng's reason.
std::string encodePngSrgb8(const uint8_t* codes, int width, int height, int channels,
                           std::string& bytes);

}  // namespace kerf
