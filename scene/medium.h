/// @file scene/medium.h
/// @brief A heterogeneous participating medium: a density field inside a box, with its
/// extinction scale, scattering albedo, emission and Henyey–Greenstein phase, and the method
/// render/medium.h estimates its transmittance with. The homogeneous `Mist` (scene/scene.h)
/// stays the cheap special case; this is what `mist { density … bounds … }` builds.
#pragma once

#include "csg/tape/scalar_field.h"
#include "csg/types.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace kerf {

/// How transmittance (and, for March, the in-scattered light) is estimated.
enum class MediumMethod : uint8_t {
    /// Residual ratio tracking (Novák et al. 2014): unbiased, continuous in [0, 1]; the
    /// field's range over pieces of the ray gives each piece a control (its lower bound) and
    /// a residual majorant, so a constant piece is exact and empty pieces cost nothing.
    Ratio,
    /// Delta tracking (Woodcock): unbiased, each estimate 0 or 1. The measured alternative.
    Delta,
    /// Deterministic midpoint marching with step `step`: biased, no noise; its error in
    /// optical depth is at most Σ (hi − lo)·h over the steps (the range over each step).
    March,
};

inline const char* mediumMethodName(MediumMethod m) {
    switch (m) {
        case MediumMethod::Ratio: return "ratio";
        case MediumMethod::Delta: return "delta";
        case MediumMethod::March: return "march";
    }
    return "?";
}

/// `mist { … bake N }`: the density is to be sampled into bricked storage
/// (volume/grids/bricked_field.h) and traced as its trilinear interpolant. Only requested by
/// the scene: render/medium_bake.h makes the grid when it prepares the medium for rendering.
struct MediumBake {
    int resolution = 0;  ///< samples along the box's longest side, in [2, 4096]
    std::string where;   ///< "file:line:col" of the request, for a bake that fails
};

/// σt(p) = extinction · density(p), σs = albedo · σt, emitted radiance per unit length
/// σt(p) · emission (a thick cloud glows with radiance `emission`).
struct Medium {
    /// The density, ≥ 0 inside `bounds` (a negative value is read as 0), zero outside; its
    /// range() over a box must hold every value there (the majorant). Null: no medium.
    std::shared_ptr<const ScalarField> density;
    Bounds3 bounds;
    double extinction = 1.0;  ///< σt per unit density, per unit length
    Vec3 albedo{1.0};         ///< scattering albedo per channel, in [0, 1]
    Vec3 emission{0.0};       ///< see above
    double g = 0.0;           ///< Henyey–Greenstein asymmetry, in (−1, 1)
    MediumMethod method = MediumMethod::Ratio;
    double step = 0.0;  ///< March: the step length; 0: the box's diagonal / 128
    int samples = 1;    ///< in-scattering points per camera segment (Ratio, Delta)
    /// Set: `density` is the exact field, to be baked before tracing (max(0, density)).
    std::optional<MediumBake> bake;

    bool enabled() const { return density != nullptr; }
};

}  // namespace kerf
