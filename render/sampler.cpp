/// @file render/sampler.cpp
/// @brief The sample sets: regular and jittered grids, random points, a shifted rank-1
/// lattice; shuffled per pixel and dimension.
#include "render/sampler.h"

#include "csg/check.h"
#include "render/sample_permutation.h"

#include <cmath>
#include <limits>

namespace kerf {
namespace {

/// The squared distance on the unit torus between lattice point s and the origin.
double torusDistance2(uint32_t s, uint32_t a, uint32_t n) {
    const double x = double(s) / n;
    const double y = double((uint64_t(s) * a) % n) / n;
    const double dx = std::min(x, 1.0 - x), dy = std::min(y, 1.0 - y);
    return dx * dx + dy * dy;
}

double smallestDistance2(uint32_t a, uint32_t n) {
    double best = std::numeric_limits<double>::infinity();
    for (uint32_t s = 1; s < n; ++s) best = std::min(best, torusDistance2(s, a, n));
    return best;
}

/// v with its `bits` low bits reversed.
uint32_t reverseBits(uint32_t v, uint32_t bits) {
    uint32_t r = 0;
    for (uint32_t b = 0; b < bits; ++b) r |= ((v >> b) & 1u) << (bits - 1 - b);
    return r;
}

/// An order of the N samples whose every prefix is spread over the pixel. A full grid
/// (jittered or regular, cols × rows = N) is visited cell by cell in the order that splits
/// both axes alike: the visit number's bits are dealt alternately to x and y (a Morton code),
/// then reversed on each axis, so the first 4 cells are 2 × 2 apart, the first 16 4 × 4, and
/// so on. The lattice (sample s at x = s/N) and random or partial sets take the sample
/// numbers in bit-reversed order. Numbers past the set are skipped.
std::vector<uint32_t> spreadOrderFor(SamplerKind kind, int count, int columns, int rows) {
    std::vector<uint32_t> order;
    order.reserve(size_t(count));
    const bool grid = (kind == SamplerKind::Jittered || kind == SamplerKind::Regular) &&
                      columns * rows == count && count > 1;
    if (grid) {
        uint32_t bits = 0;  // per axis
        while ((1u << bits) < uint32_t(std::max(columns, rows))) ++bits;
        for (uint64_t i = 0; i < (uint64_t(1) << (2 * bits)); ++i) {
            uint32_t x = 0, y = 0;
            for (uint32_t b = 0; b < bits; ++b) {
                x |= uint32_t((i >> (2 * b)) & 1u) << b;
                y |= uint32_t((i >> (2 * b + 1)) & 1u) << b;
            }
            const uint32_t cx = reverseBits(x, bits), cy = reverseBits(y, bits);
            if (cx < uint32_t(columns) && cy < uint32_t(rows))
                order.push_back(cy * uint32_t(columns) + cx);
        }
        return order;
    }
    uint32_t bits = 0;
    while ((uint64_t(1) << bits) < uint64_t(count)) ++bits;
    for (uint64_t i = 0; i < (uint64_t(1) << bits); ++i) {
        const uint32_t r = reverseBits(uint32_t(i), bits);
        if (r < uint32_t(count)) order.push_back(r);
    }
    return order;
}

}  // namespace

uint32_t PixelSampler::latticeGenerator(uint32_t n) {
    if (n <= 2) return 1;
    constexpr uint32_t kExhaustive = 4096;
    constexpr uint32_t kCandidates = 1024;
    uint32_t best = 1;
    double bestDistance = -1.0;
    auto consider = [&](uint32_t a) {
        if (a == 0 || a >= n) return;
        const double d = smallestDistance2(a, n);
        if (d > bestDistance) bestDistance = d, best = a;
    };
    if (n <= kExhaustive) {
        for (uint32_t a = 1; a <= n / 2; ++a) consider(a);
    } else {
        // Near n/φ (the Fibonacci lattice's generator), then spread over (0, n/2].
        const uint32_t golden = uint32_t(std::llround(n * 0.6180339887498949));
        for (uint32_t k = 0; k < kCandidates / 2; ++k) {
            consider(golden - kCandidates / 4 + k);
            consider(uint32_t(uint64_t(n / 2) * (k + 1) / (kCandidates / 2)));
        }
    }
    return best;
}

PixelSampler::PixelSampler(int spp, SamplerKind kind)
    : mKind(kind), mCount(std::clamp(spp, 1, kMaxSamplesPerPixel)) {
    mColumns = gridSide(mCount);
    mRows = (mCount + mColumns - 1) / mColumns;
    if (mKind == SamplerKind::Lattice) mLatticeA = latticeGenerator(uint32_t(mCount));
    mSpreadOrder = spreadOrderFor(mKind, mCount, mColumns, mRows);
}

SubPixel PixelSampler::get2D(uint64_t pixel, int s, uint32_t dim) const {
    KERF_DCHECK_LT(uint32_t(s), uint32_t(mCount));  // 0 ≤ s < sampleCount()
    if (dim == sample_dim::kFilm) {
        if (mCount == 1) return SubPixel{};  // one camera ray: through the pixel centre
        return point(pixel, uint32_t(s), dim);
    }
    // Other dimensions take the set's sample at a shuffled index, so they do not correlate
    // with the film position or with each other.
    const uint64_t seed = mixBits(mixBits(pixel) ^ (uint64_t(dim) * 0x632be59bd9b4e019ull));
    return point(pixel, permuteIndex(uint32_t(s), uint32_t(mCount), seed), dim);
}

SubPixel PixelSampler::point(uint64_t pixel, uint32_t index, uint32_t dim) const {
    const uint32_t hx = 2 * dim, hy = 2 * dim + 1;  // hash dimensions of this 2D dimension
    switch (mKind) {
        case SamplerKind::Random:
            return {hashUniform(pixel, index, hx), hashUniform(pixel, index, hy)};
        case SamplerKind::Lattice: {
            // Cranley–Patterson rotation: one random shift per pixel and dimension keeps the
            // lattice's structure and makes each pixel's estimate unbiased.
            const double ux = hashUniform(pixel, 0xffffffffu, hx);
            const double uy = hashUniform(pixel, 0xffffffffu, hy);
            const double x = double(index) / mCount + ux;
            const double y = double((uint64_t(index) * mLatticeA) % uint64_t(mCount)) / mCount + uy;
            return {x - std::floor(x), y - std::floor(y)};
        }
        case SamplerKind::Regular:
        case SamplerKind::Jittered: {
            // A full grid uses cell s for sample s; a partial one (N < cols × rows) a shuffled
            // choice of N cells, different in each pixel.
            const uint32_t cells = uint32_t(mColumns) * uint32_t(mRows);
            const uint32_t cell =
                cells == uint32_t(mCount)
                    ? index
                    : permuteIndex(index, cells, mixBits(pixel ^ (uint64_t(dim) << 40)));
            const uint32_t cx = cell % uint32_t(mColumns), cy = cell / uint32_t(mColumns);
            const double jx = mKind == SamplerKind::Regular ? 0.5 : hashUniform(pixel, index, hx);
            const double jy = mKind == SamplerKind::Regular ? 0.5 : hashUniform(pixel, index, hy);
            return {(cx + jx) / mColumns, (cy + jy) / mRows};
        }
    }
    return {};
}

}  // namespace kerf
