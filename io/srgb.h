/// @file io/srgb.h
/// @brief The sRGB transfer function (IEC 61966-2-1) between linear values and 8-bit codes.
#pragma once

#include <algorithm>
#include <array>
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

/// A linear value as an 8-bit sRGB code: clamped to [0, 1] (NaN as 0), encoded, rounded to
/// the nearest code. Found by binary search among the linear values where the rounded code
/// steps up (decoded half-codes), instead of a pow per channel.
inline uint8_t srgbByte(float linear) {
    static const auto steps = [] {
        std::array<double, 255> t{};
        for (int k = 0; k < 255; ++k) t[k] = srgbDecode((k + 0.5) / 255.0);
        return t;
    }();
    const double v = linear > 0 ? double(linear) : 0.0;  // NaN fails > 0
    return uint8_t(std::upper_bound(steps.begin(), steps.end(), v) - steps.begin());
}

}  // namespace kerf
