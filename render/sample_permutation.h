/// @file render/sample_permutation.h
/// @brief A permutation of 0 … n−1 chosen by a seed, computed per element without a table:
/// each sample dimension of a pixel pairs its samples with another shuffle of the same set
/// (Shirley's shuffled sample sets), so the pixel position, the lens and the light do not
/// correlate, and no memory is needed per pixel.
#pragma once

#include <cstdint>

namespace kerf {

/// π_seed(i) for 0 ≤ i < n: a bijection of 0 … n−1. Each round (xor with a seed-derived
/// constant, multiply by an odd constant, xor-shift) is a bijection of the k-bit words with
/// 2^k ≥ n, so their composition is; values that land at or past n are mapped again (cycle
/// walking), which keeps it a bijection of 0 … n−1. At most a few walks: at most half of the
/// k-bit words lie past n.
inline uint32_t permuteIndex(uint32_t i, uint32_t n, uint64_t seed) {
    if (n <= 1) return 0;
    uint32_t bits = 1;
    while (bits < 32 && (uint64_t(1) << bits) < n) ++bits;
    const uint32_t mask = bits == 32 ? 0xffffffffu : (uint32_t(1) << bits) - 1u;
    const uint32_t a = uint32_t(seed) & mask, b = uint32_t(seed >> 32) & mask;
    const uint32_t shift = bits > 1 ? (bits + 1) / 2 : 1;
    do {
        i = (i ^ a) & mask;
        i = (i * 0x9e3779b1u) & mask;
        i ^= i >> shift;
        i = (i + b) & mask;
        i = (i * 0x85ebca6bu) & mask;
        i ^= i >> shift;
    } while (i >= n);
    return i;
}

}  // namespace kerf
