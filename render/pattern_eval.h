/// @file render/pattern_eval.h
/// @brief Evaluating solid textures (scene/pattern.h) at a shading point, and the seeded
/// gradient noise they use.
#pragma once

#include "csg/tape/noise.h"
#include "scene/pattern.h"
#include "scene/scene.h"

namespace kerf {

/// The patch of surface a sample stands for: the parallelogram p + a·du + b·dv, a and b in
/// [−½, ½] (world vectors in the tangent plane; zero vectors for a point), and the surface's
/// unit normal there, turned toward the viewer (which face of a box-mapped image shows; zero
/// when not known, which takes the +z face).
struct Footprint {
    Vec3 du{0.0};
    Vec3 dv{0.0};
    Vec3 normal{0.0};
};

/// The pattern's colour at world point p, averaged over the box that holds the footprint in
/// the pattern's space, so that detail finer than a pixel fades to its mean instead of
/// aliasing: checker, stripes and rings are box filtered exactly (their square waves
/// integrated axis by axis), turbulence drops the octaves finer than the footprint. Along an
/// axis the footprint does not extend (a plane's normal), the point is used: errorBound, how
/// far p may be from the true surface point (hitErrorBound), then decides a point that close
/// to a cell boundary for the boundary's upper side, so a plane at a whole coordinate does not
/// flicker between the two cells with the rounding of its hits.
Vec3 patternColor(const Pattern& pattern, const Vec3& p, double errorBound,
                  const Footprint& footprint = {});

/// The material's colour at p: its pattern's if it has one, else its flat colour.
inline Vec3 surfaceColor(const Material& m, const Vec3& p, double errorBound,
                         const Footprint& footprint = {}) {
    return m.pattern ? patternColor(*m.pattern, p, errorBound, footprint) : m.color;
}

/// An image texture's colour at world point p (`pattern image`): p mapped into the pattern's
/// space, then to image coordinates by the pattern's mapping (docs/language.md, "Image
/// textures"); the footprint goes through the mapping's Jacobian to the two axes of the
/// texture filter, so the image is MIP-mapped and filtered anisotropically over it (a zero
/// footprint still gets the bilinear filter of the texels).
Vec3 imageColor(const Pattern& pattern, const Vec3& p, const Footprint& footprint);

/// The image coordinates (u, v) of a point q of an image pattern's space and their
/// derivatives along two vectors a and b of that space (how a footprint's axes map), for the
/// surface normal nq in that space (used by the box mapping alone).
struct ImageCoordinates {
    double u = 0, v = 0;
    double dua = 0, dva = 0;  ///< along a
    double dub = 0, dvb = 0;  ///< along b
};
ImageCoordinates mapToImage(ImageMap::Mapping mapping, const Vec3& q, const Vec3& a, const Vec3& b,
                            const Vec3& nq);

/// The pattern's own scalar in [0, 1] at p, the weight of b against a (0: a, 1: b) before its
/// entries are looked at: a bump map's height (filtered over the footprint like the colour).
/// An image's is the luminance of its colour (Rec. 709 weights), clamped to [0, 1].
double patternValue(const Pattern& pattern, const Vec3& p, double errorBound,
                    const Footprint& footprint = {});

/// The shading normal of a bump map (Blinn 1978): the unit normal n tilted against the
/// gradient of depth · h(p) along the surface, h the pattern's value. The gradient is taken
/// by central differences over a step of a thousandth of the pattern's unit, or across the
/// footprint where that is wider (which smooths bumps finer than a pixel).
Vec3 bumpedNormal(const Pattern& bump, double depth, const Vec3& p, const Vec3& n,
                  double errorBound, const Footprint& footprint = {});

/// The mean of the ±1 square wave s(x) = (−1)^⌊x⌋ over [x − w/2, x + w/2]; for w at or
/// below kFilterFloor its value at x, taking x within `slack` below a whole number as that
/// number.
double filteredSquareWave(double x, double w, double slack = 0.0);

/// Footprints narrower than this (in a pattern's units) are points: filtering would change
/// nothing but rounding.
constexpr double kFilterFloor = 1e-9;

}  // namespace kerf
