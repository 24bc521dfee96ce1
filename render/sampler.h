/// @file render/sampler.h
/// @brief The samples a pixel draws: its film positions and, per further dimension (the lens,
/// the shutter time, the light and the gloss of each bounce), 2D points from the same kind of
/// set, shuffled against the others.
///
/// Every number is a function of (pixel, sample, dimension), not the state of a stream: a
/// pixel gets the same numbers whichever thread renders it and in whatever order, so the image
/// is the same bit for bit whatever the thread count.
#pragma once

#include "csg/mix_bits.h"
#include "scene/limits.h"
#include "scene/sampling.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace kerf {

/// A number in [0, 1) that depends only on its three arguments. Two rounds of mixing so
/// neighbouring pixels and neighbouring samples are uncorrelated.
inline double hashUniform(uint64_t pixel, uint32_t sample, uint32_t dimension) {
    const uint64_t h = mixBits(mixBits(pixel) ^ ((uint64_t(sample) << 32) | dimension));
    return double(h >> 11) * 0x1.0p-53;  // the top 53 bits: exact in a double, < 1
}

/// A point of the unit square.
struct SubPixel {
    double x = 0.5;
    double y = 0.5;
};

/// The 2D dimensions a path draws from. Dimension 0 is the film position; the lens and the
/// shutter come next; each bounce d then has its own light and gloss dimensions, so no two
/// uses of one sample share numbers.
namespace sample_dim {
constexpr uint32_t kFilm = 0;
constexpr uint32_t kLens = 1;
constexpr uint32_t kTime = 2;
constexpr uint32_t kFirstBounce = 3;
constexpr uint32_t kPerBounce = 2;
inline uint32_t light(int depth) { return kFirstBounce + kPerBounce * uint32_t(depth); }
inline uint32_t gloss(int depth) { return kFirstBounce + kPerBounce * uint32_t(depth) + 1; }
}  // namespace sample_dim

class PixelSampler {
public:
    /// spp is clamped to 1 … kMaxSamplesPerPixel (the model and the command line refuse more);
    /// exactly that many samples are taken.
    explicit PixelSampler(int spp, SamplerKind kind = SamplerKind::Jittered);

    int sampleCount() const { return mCount; }
    SamplerKind kind() const { return mKind; }
    /// The grid the regular and jittered kinds use: cols = ⌈√N⌉, rows = ⌈N / cols⌉.
    int columns() const { return mColumns; }
    int rows() const { return mRows; }

    /// Sample s (0 ≤ s < sampleCount()) of the pixel with linear index `pixel`, in dimension
    /// `dim`: a point of [0, 1]². In the film dimension one sample is the pixel centre; with
    /// N = n × n jittered samples sample s lies in stratum (s mod n, s div n).
    SubPixel get2D(uint64_t pixel, int s, uint32_t dim) const;
    SubPixel position(uint64_t pixel, int s) const { return get2D(pixel, s, sample_dim::kFilm); }

    /// The smallest n with n·n ≥ spp (1 for spp ≤ 1), in integers so that no rounding of
    /// sqrt can make it off by one.
    static int gridSide(int spp) {
        int64_t n = 1;  // 64-bit: n·n for spp near INT_MAX would overflow an int
        while (n * n < spp) ++n;
        return static_cast<int>(n);
    }

    /// The order adaptive sampling takes the samples in: a prefix of any length is spread over
    /// the pixel (a full grid's cells by axis-wise bit reversal of a Morton code, other sets
    /// by bit-reversed sample numbers), so a pixel that stops early has samples all over it,
    /// not one strip of its grid or lattice.
    const std::vector<uint32_t>& spreadOrder() const { return mSpreadOrder; }

    /// The lattice's generator for N points: (1, a)/N with a chosen for the largest smallest
    /// distance between points on the torus (exhaustively up to 4096 points, among a sample
    /// of candidates above).
    static uint32_t latticeGenerator(uint32_t n);

private:
    SubPixel point(uint64_t pixel, uint32_t index, uint32_t dim) const;

    SamplerKind mKind;
    int mCount;
    int mColumns, mRows;
    uint32_t mLatticeA = 1;
    std::vector<uint32_t> mSpreadOrder;
};

}  // namespace kerf
