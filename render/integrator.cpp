/// @file render/integrator.cpp
/// @brief The integrator factory: the one place that names the implementations.
#include "render/integrator.h"

#include "render/whitted_integrator.h"

namespace kerf {

std::unique_ptr<Integrator> makeIntegrator(const IntegratorInputs& inputs) {
    return std::make_unique<WhittedIntegrator>(
        inputs.scene, inputs.geometry, inputs.scene.settings.maxDepth, inputs.shadowGeometry);
}

}  // namespace kerf
