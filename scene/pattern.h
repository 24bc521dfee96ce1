/// @file scene/pattern.h
/// @brief Solid textures (Perlin 1985): a material's colour as a function of the point in
/// space, so no surface mapping is needed. A pattern picks or blends its two entries, each a
/// colour or a nested pattern, by a function of the point in the pattern's own space.
#pragma once

#include "csg/types.h"

#include <cstdint>
#include <memory>
#include <string>

namespace kerf {

class Texture;  // io/texture.h: scene/ only holds it

/// An image texture (`pattern image { file … mapping … }`): the image, and how points of the
/// pattern's space become image coordinates (u, v), repeating per unit, v up the image. The
/// formulas are in docs/language.md, "Image textures".
struct ImageMap {
    enum class Mapping : uint8_t {
        Planar,       ///< u = x, v = y
        Spherical,    ///< longitude and latitude about the origin, y up
        Cylindrical,  ///< the angle about y, v = y
        Box,          ///< a planar map on the face of the dominant axis of the normal
    };
    Mapping mapping = Mapping::Planar;
    std::shared_ptr<const Texture> texture;  ///< opened while the model is lowered
    std::string path;                        ///< as opened (for messages and summaries)
};

struct Pattern {
    enum class Kind : uint8_t {
        Checker,     ///< unit cubes alternate: a where ⌊x⌋ + ⌊y⌋ + ⌊z⌋ is even, else b
        Stripes,     ///< slabs of unit width across x alternate
        Rings,       ///< unit-wide rings about the y axis alternate (by ⌊√(x² + z²)⌋)
        Gradient,    ///< a to b across each unit of x (a sawtooth: frac(x))
        Noise,       ///< a to b by seeded gradient noise, in [0, 1]
        Turbulence,  ///< a to b by the sum of |noise| over octaves, in [0, 1]
        Image,       ///< an image's colour (`image`); its value is the colour's luminance
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
    uint64_t seed = 0;                      ///< noise and turbulence
    int octaves = 6;                        ///< turbulence
    std::shared_ptr<const ImageMap> image;  ///< Image: set, and a and b are not used
};

}  // namespace kerf
