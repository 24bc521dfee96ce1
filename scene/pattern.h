/// @file scene/pattern.h
/// @brief Solid textures (Perlin 1985): a material's colour as a function of the point in
/// space, so no surface mapping is needed. A pattern picks or blends its two entries, each a
/// colour or a nested pattern, by a function of the point in the pattern's own space.
#pragma once

#include "csg/types.h"

#include <cstdint>
#include <memory>

namespace kerf {

struct Pattern {
    enum class Kind : uint8_t {
        Checker,     ///< unit cubes alternate: a where ⌊x⌋ + ⌊y⌋ + ⌊z⌋ is even, else b
        Stripes,     ///< slabs of unit width across x alternate
        Rings,       ///< unit-wide rings about the y axis alternate (by ⌊√(x² + z²)⌋)
        Gradient,    ///< a to b across each unit of x (a sawtooth: frac(x))
        Noise,       ///< a to b by seeded gradient noise, in [0, 1]
        Turbulence,  ///< a to b by the sum of |noise| over octaves, in [0, 1]
    };
    /// One of the two entries: a colour, or a nested pattern when `pattern` is set.
    struct Entry {
        Vec3 color{0.0};
        std::shared_ptr<const Pattern> pattern;
    };

    Kind kind = Kind::Checker;
    Entry a, b;
    /// World space to the pattern's space: the inverse of the pattern's own transform.
    Affine toPattern;
    uint64_t seed = 0;  ///< noise and turbulence
    int octaves = 6;    ///< turbulence
};

}  // namespace kerf
