/// @file render/medium_bake.h
/// @brief A mist's `bake N` made where the medium is prepared for rendering: the scene only
/// records the request (scene/medium.h MediumBake), so commands that render nothing (`kerf
/// check`) never sample the density.
#pragma once

#include "scene/scene.h"

namespace kerf {

/// The scene with its medium's density sampled into bricked storage
/// (volume/grids/bricked_field.h) as max(0, density) when a bake is requested; the request is
/// then cleared. Throws std::invalid_argument naming the request's "file:line:col" when a
/// sample is not finite or out of float range.
Scene withBakedMedium(const Scene& scene);

}  // namespace kerf
