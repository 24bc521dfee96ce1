/// @file render/sampler.h
/// @brief Per-pixel random numbers and the n×n jittered sample grid.
///
/// Every random number is a hash of (pixel, sample, dimension), not the state of a stream:
/// a pixel gets the same numbers whichever thread renders it and in whatever order, so the
/// image is the same bit for bit whatever the thread count.
#pragma once

#include "scene/limits.h"

#include <algorithm>
#include <cstdint>

namespace kerf {

/// SplitMix64's output function (Steele, Lea, Flood 2014): a bijection on 64 bits whose
/// every output bit depends on every input bit.
inline uint64_t mixBits(uint64_t z) {
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

/// A number in [0, 1) that depends only on its three arguments. Two rounds of mixing so
/// neighbouring pixels and neighbouring samples are uncorrelated.
inline double hashUniform(uint64_t pixel, uint32_t sample, uint32_t dimension) {
    const uint64_t h = mixBits(mixBits(pixel) ^ ((uint64_t(sample) << 32) | dimension));
    return double(h >> 11) * 0x1.0p-53;  // the top 53 bits: exact in a double, < 1
}

/// A sample's position inside its pixel, each coordinate in [0, 1].
struct SubPixel {
    double x = 0.5;
    double y = 0.5;
};

/// An n×n jittered grid per pixel, n = ceil(sqrt(spp)): spp is rounded up to a square.
/// With one sample the ray goes exactly through the pixel centre.
class PixelSampler {
public:
    /// spp is capped at kMaxSamplesPerPixel (the model and the command line refuse more), so
    /// sampleCount() stays far inside an int.
    explicit PixelSampler(int spp) : mSide(gridSide(std::min(spp, kMaxSamplesPerPixel))) {}

    /// The smallest n with n·n ≥ spp (1 for spp ≤ 1), in integers so that no rounding of
    /// sqrt can make it off by one.
    static int gridSide(int spp) {
        int64_t n = 1;  // 64-bit: n·n for spp near INT_MAX would overflow an int
        while (n * n < spp) ++n;
        return static_cast<int>(n);
    }

    int side() const { return mSide; }
    int sampleCount() const { return mSide * mSide; }

    /// Sample s (0 ≤ s < sampleCount()) of the pixel with linear index `pixel`: a uniform
    /// point of stratum (s mod n, s div n), i.e. inside [sx/n, (sx+1)/n] × [sy/n, (sy+1)/n].
    SubPixel position(uint64_t pixel, int s) const {
        if (mSide == 1) return SubPixel{};
        const int sx = s % mSide;
        const int sy = s / mSide;
        const double inv = 1.0 / mSide;
        return SubPixel{(sx + hashUniform(pixel, uint32_t(s), 0)) * inv,
                        (sy + hashUniform(pixel, uint32_t(s), 1)) * inv};
    }

private:
    int mSide;
};

}  // namespace kerf
