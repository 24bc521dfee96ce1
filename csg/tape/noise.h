/// @file csg/tape/noise.h
/// @brief Seeded gradient noise (Perlin's improved noise, 2002, its gradients picked by a
/// hash of the lattice point and the seed) and what the tape evaluators need of it: the
/// value, its gradient, and enclosures of both over a box. With the enclosures, a solid
/// displaced by noise (f − D·noise) is traced as soundly as any other implicit: interval
/// root isolation can never step over its surface.
#pragma once

#include "csg/interval/interval.h"
#include "csg/types.h"

#include <cstdint>

namespace kerf {

/// The noise at p: C² smooth, 0 at every lattice point (integer coordinates), clamped to
/// [−1, 1]. NaN where p has a NaN; 0 where a coordinate's magnitude is 2⁵² or more (every
/// such double is a lattice coordinate).
double gradientNoise(const Vec3& p, uint64_t seed);

/// The same in long double throughout (reference evaluation).
long double gradientNoise(const glm::tvec3<long double>& p, uint64_t seed);

/// The value (the same bits as gradientNoise(p, seed)) and its gradient, which is 0 where
/// the clamp holds.
double gradientNoise(const Vec3& p, uint64_t seed, Vec3& gradient);

/// An enclosure of the noise over the box x × y × z, and (when `gradient` is not null)
/// enclosures of its three partial derivatives there (each holding every one-sided derivative
/// where the clamp sets in).
/// A box inside one lattice cell gets the interpolation itself enclosed; one across cell
/// walls the mean-value form about its centre with the global slope bound (slopes
/// ±kNoiseSlopeBound), clipped to [−1, 1].
Interval gradientNoiseRange(const Interval& x, const Interval& y, const Interval& z, uint64_t seed,
                            Interval* gradient = nullptr);

/// A bound on every partial derivative of the noise anywhere (derived in csg/tape/noise.cpp).
constexpr double kNoiseSlopeBound = 8.5;

}  // namespace kerf
