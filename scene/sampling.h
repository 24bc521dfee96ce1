/// @file scene/sampling.h
/// @brief How a pixel's samples are placed: a render setting the model and the command line
/// choose (render/sampler.h makes the samples).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace kerf {

enum class SamplerKind : uint8_t {
    Regular,  ///< the centres of N cells of a cols × rows grid (all of them when N = cols × rows,
              ///< else a shuffled choice per pixel): no noise, aliasing
    Random,   ///< independent uniform points
    Jittered,  ///< one uniform point in each cell of a cols × rows grid (the default)
    Lattice,   ///< a rank-1 lattice (Korobov) shifted per pixel: low discrepancy
};

/// How samples are weighed into pixels (render/film.h).
enum class FilterKind : uint8_t { Box, Gaussian, Mitchell };

inline const char* filterName(FilterKind kind) {
    switch (kind) {
        case FilterKind::Box: return "box";
        case FilterKind::Gaussian: return "gaussian";
        case FilterKind::Mitchell: return "mitchell";
    }
    return "?";
}

inline std::optional<FilterKind> parseFilter(const std::string& name) {
    for (FilterKind k : {FilterKind::Box, FilterKind::Gaussian, FilterKind::Mitchell})
        if (name == filterName(k)) return k;
    return std::nullopt;
}

/// "regular", "random", "jittered", "lattice".
inline const char* samplerName(SamplerKind kind) {
    switch (kind) {
        case SamplerKind::Regular: return "regular";
        case SamplerKind::Random: return "random";
        case SamplerKind::Jittered: return "jittered";
        case SamplerKind::Lattice: return "lattice";
    }
    return "?";
}

inline std::optional<SamplerKind> parseSampler(const std::string& name) {
    for (SamplerKind k :
         {SamplerKind::Regular, SamplerKind::Random, SamplerKind::Jittered, SamplerKind::Lattice})
        if (name == samplerName(k)) return k;
    return std::nullopt;
}

}  // namespace kerf
