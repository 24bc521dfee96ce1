/// @file csg/mix_bits.h
/// @brief A 64-bit mixing function shared by the sampler's counter-based random numbers and
/// the gradient noise's lattice hash.
#pragma once

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

}  // namespace kerf
