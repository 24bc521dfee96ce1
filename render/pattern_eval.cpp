/// @file render/pattern_eval.cpp
/// @brief Solid textures and gradient noise.
#include "render/pattern_eval.h"

#include "io/texture.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace kerf {
namespace {

/// The largest absolute row sum of the map's linear part: how much it can stretch a length.
double stretch(const Affine& a) {
    double best = 0.0;
    for (int r = 0; r < 3; ++r)
        best = std::max(best, std::fabs(a.linear[0][r]) + std::fabs(a.linear[1][r]) +
                                  std::fabs(a.linear[2][r]));
    return best;
}

/// ⌊v⌋, taking values within `slack` below a whole number as that number.
int64_t cell(double v, double slack) { return int64_t(std::floor(v + slack)); }

Vec3 entryColor(const Pattern::Entry& e, const Vec3& p, double errorBound,
                const Footprint& footprint) {
    return e.pattern ? patternColor(*e.pattern, p, errorBound, footprint) : e.color;
}

/// ∫₀ˣ (−1)^⌊u⌋ du: the triangle wave 1 − |(x mod 2) − 1|, periodic with period 2.
double squareWaveIntegral(double x) {
    const double m = x - 2.0 * std::floor(0.5 * x);
    return 1.0 - std::fabs(m - 1.0);
}

}  // namespace

double filteredSquareWave(double x, double w, double slack) {
    if (!(w > kFilterFloor)) return (cell(x, slack) & 1) == 0 ? 1.0 : -1.0;
    if (w >= 2.0 * 1e6) return 0.0;  // millions of periods: the mean, exactly enough
    const double lo = x - 0.5 * w, hi = x + 0.5 * w;
    if (std::floor(lo) == std::floor(hi))  // inside one cell: its value, exactly
        return (int64_t(std::floor(lo)) & 1) == 0 ? 1.0 : -1.0;
    return std::clamp((squareWaveIntegral(hi) - squareWaveIntegral(lo)) / w, -1.0, 1.0);
}

namespace {

/// How a pattern weighs its entries at a point: b's weight in [0, 1] (a's is 1 − that).
double weightOfB(const Pattern& pattern, const Vec3& p, double errorBound,
                 const Footprint& footprint) {
    const Affine& map = pattern.toPattern;
    const Vec3 q = map.point(p);
    // How far q may be from the true point, in the pattern's units (and a little more).
    const double slack = 4.0 * errorBound * stretch(map);
    // The box holding the footprint in the pattern's space, side by side.
    const Vec3 w = glm::abs(map.vector(footprint.du)) + glm::abs(map.vector(footprint.dv));
    const double widest = std::max({w.x, w.y, w.z});
    // A square-wave product v in [−1, 1] (+1: all a) as b's weight.
    const auto fromSigned = [](double v) {
        return v == 1.0 ? 0.0 : v == -1.0 ? 1.0 : 0.5 * (1.0 - v);
    };
    switch (pattern.kind) {
        case Pattern::Kind::Checker:
            // (−1)^(⌊x⌋+⌊y⌋+⌊z⌋) is the product of three square waves, and a box filter of a
            // product of functions of one axis each is the product of their filters.
            return fromSigned(filteredSquareWave(q.x, w.x, slack) *
                              filteredSquareWave(q.y, w.y, slack) *
                              filteredSquareWave(q.z, w.z, slack));
        case Pattern::Kind::Stripes: return fromSigned(filteredSquareWave(q.x, w.x, slack));
        case Pattern::Kind::Rings:
            return fromSigned(
                filteredSquareWave(std::sqrt(q.x * q.x + q.z * q.z), std::max(w.x, w.z), slack));
        case Pattern::Kind::Gradient: return q.x - std::floor(q.x);
        case Pattern::Kind::Image: {
            const Vec3 c = imageColor(pattern, p, footprint);
            return std::clamp(0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z, 0.0, 1.0);
        }
        case Pattern::Kind::Noise:
            return std::clamp(0.5 + 0.5 * gradientNoise(q, pattern.seed), 0.0, 1.0);
        case Pattern::Kind::Turbulence: {
            double sum = 0.0, norm = 0.0, scale = 1.0;
            for (int o = 0; o < std::max(1, pattern.octaves); ++o) {
                // An octave whose features (about 1/scale) are finer than the footprint would
                // alias; it fades to its mean instead (|noise| averages about 1/4).
                const double detail = std::clamp(2.0 - widest * scale, 0.0, 1.0);
                const double n =
                    detail > 0.0 ? std::fabs(gradientNoise(q * scale, pattern.seed + uint64_t(o)))
                                 : 0.0;
                sum += (detail * n + (1.0 - detail) * 0.25) / scale;
                norm += 1.0 / scale;
                scale *= 2.0;
            }
            return std::clamp(sum / norm, 0.0, 1.0);
        }
    }
    return 0.0;
}

}  // namespace

double patternValue(const Pattern& pattern, const Vec3& p, double errorBound,
                    const Footprint& footprint) {
    return weightOfB(pattern, p, errorBound, footprint);
}

Vec3 patternColor(const Pattern& pattern, const Vec3& p, double errorBound,
                  const Footprint& footprint) {
    if (pattern.kind == Pattern::Kind::Image) return imageColor(pattern, p, footprint);
    const double t = weightOfB(pattern, p, errorBound, footprint);
    // Only the entries with weight are looked at (a nested pattern costs nothing unseen).
    if (t == 0.0) return entryColor(pattern.a, p, errorBound, footprint);
    if (t == 1.0) return entryColor(pattern.b, p, errorBound, footprint);
    const Vec3 a = entryColor(pattern.a, p, errorBound, footprint);
    return a + t * (entryColor(pattern.b, p, errorBound, footprint) - a);
}

Vec3 bumpedNormal(const Pattern& bump, double depth, const Vec3& p, const Vec3& n,
                  double errorBound, const Footprint& footprint) {
    if (depth == 0.0) return n;
    const double unit = 1.0 / std::max(stretch(bump.toPattern), 1e-300);
    const double step =
        std::max({1e-3 * unit, glm::length(footprint.du), glm::length(footprint.dv)});
    Vec3 gradient;
    for (int k = 0; k < 3; ++k) {
        Vec3 e(0.0);
        e[k] = step;
        // An image is filtered over the footprint (its texels alias otherwise); solid
        // textures are taken at points, as they always were.
        const Footprint at = bump.kind == Pattern::Kind::Image
                                 ? Footprint{footprint.du, footprint.dv, n}
                                 : Footprint{};
        gradient[k] = (patternValue(bump, p + e, 0.0, at) - patternValue(bump, p - e, 0.0, at)) /
                      (2.0 * step);
    }
    const Vec3 along = gradient - glm::dot(gradient, n) * n;  // its part along the surface
    const Vec3 tilted = n - depth * along;
    const double length = glm::length(tilted);
    return length > 0.0 && std::isfinite(length) ? tilted / length : n;
}

ImageCoordinates mapToImage(ImageMap::Mapping mapping, const Vec3& q, const Vec3& a, const Vec3& b,
                            const Vec3& nq) {
    ImageCoordinates c;
    // Linear maps (planar, box faces): u = eu·q, v = ev·q.
    const auto linear = [&](const Vec3& eu, const Vec3& ev) {
        c.u = glm::dot(eu, q), c.v = glm::dot(ev, q);
        c.dua = glm::dot(eu, a), c.dva = glm::dot(ev, a);
        c.dub = glm::dot(eu, b), c.dvb = glm::dot(ev, b);
    };
    constexpr double kTwoPi = 2.0 * glm::pi<double>();
    const double rho2 = q.x * q.x + q.z * q.z;
    // The angle about y, from +z toward +x, in turns: u = atan2(x, z) / 2π, and its gradient
    // (z, 0, −x) / (2π ρ²) (infinite on the axis: the whole image's width, clamped later).
    // g·w, 0 for a zero w even where g is infinite (a point footprint at a pole).
    const auto along = [](const Vec3& g, const Vec3& w) {
        return w == Vec3(0.0) ? 0.0 : glm::dot(g, w);
    };
    const auto around = [&] {
        c.u = std::atan2(q.x, q.z) / kTwoPi;
        const Vec3 gu = Vec3(q.z, 0.0, -q.x) / (kTwoPi * rho2);
        c.dua = along(gu, a), c.dub = along(gu, b);
    };
    switch (mapping) {
        case ImageMap::Mapping::Planar: linear(Vec3(1, 0, 0), Vec3(0, 1, 0)); break;
        case ImageMap::Mapping::Cylindrical:
            around();
            c.v = q.y, c.dva = a.y, c.dvb = b.y;
            break;
        case ImageMap::Mapping::Spherical: {
            around();
            // Latitude in half turns: v = ½ + atan2(y, ρ) / π, so 0 at the south pole, 1 at
            // the north; its gradient is (−xy/ρ, ρ, −zy/ρ) / (π r²).
            const double rho = std::sqrt(rho2), r2 = rho2 + q.y * q.y;
            c.v = 0.5 + std::atan2(q.y, rho) / glm::pi<double>();
            const Vec3 gv =
                Vec3(-q.x * q.y / rho, rho, -q.z * q.y / rho) / (glm::pi<double>() * r2);
            c.dva = along(gv, a), c.dvb = along(gv, b);
            break;
        }
        case ImageMap::Mapping::Box: {
            // The face the normal points through most; ties go to x, then y. Each face shows
            // the image upright and unmirrored from outside (y up on the sides, −z up on top).
            const Vec3 m = glm::abs(nq);
            if (m.x > 0.0 && m.x >= m.y && m.x >= m.z)
                linear(Vec3(0, 0, nq.x > 0 ? -1 : 1), Vec3(0, 1, 0));
            else if (m.y > 0.0 && m.y >= m.z)
                linear(Vec3(1, 0, 0), Vec3(0, 0, nq.y > 0 ? -1 : 1));
            else
                linear(Vec3(nq.z < 0 ? -1 : 1, 0, 0), Vec3(0, 1, 0));
            break;
        }
    }
    return c;
}

Vec3 imageColor(const Pattern& pattern, const Vec3& p, const Footprint& footprint) {
    if (!pattern.image || !pattern.image->texture) return Vec3(0.0);
    const ImageMap& image = *pattern.image;
    const Affine& map = pattern.toPattern;
    // Normals go into the pattern's space by the inverse transpose of its linear part.
    const Vec3 nq = image.mapping == ImageMap::Mapping::Box
                        ? glm::transpose(glm::inverse(map.linear)) * footprint.normal
                        : Vec3(0.0);
    const ImageCoordinates c = mapToImage(image.mapping, map.point(p), map.vector(footprint.du),
                                          map.vector(footprint.dv), nq);
    // Texture coordinates run down the image (t = 0 at its top row); v runs up.
    const Texture::Wrap wrapT = image.mapping == ImageMap::Mapping::Spherical
                                    ? Texture::Wrap::Clamp
                                    : Texture::Wrap::Periodic;
    const auto rgb = image.texture->lookup(c.u, 1.0 - c.v, c.dua, -c.dva, c.dub, -c.dvb,
                                           Texture::Wrap::Periodic, wrapT);
    return Vec3(rgb[0], rgb[1], rgb[2]);
}

}  // namespace kerf
