/// @file render/srgb.h
/// @brief The sRGB transfer function (IEC 61966-2-1) between linear values and 8-bit codes.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace kerf {

/// Linear [0, 1] → sRGB-encoded [0, 1].
inline double srgbEncode(double linear) {
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

/// sRGB-encoded [0, 1] → linear [0, 1].
inline double srgbDecode(double encoded) {
    return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

/// A linear value as an 8-bit sRGB code: clamped to [0, 1] (NaN as 0), encoded, rounded.
inline uint8_t srgbByte(float linear) {
    const double v = linear > 0 ? std::min(double(linear), 1.0) : 0.0;  // NaN fails > 0
    return uint8_t(std::lround(srgbEncode(v) * 255.0));
}

}  // namespace kerf
