/// @file render/camera.cpp
/// @brief Pinhole camera rays.
#include "render/camera.h"

#include "csg/normalize.h"

#include <glm/gtc/constants.hpp>

namespace kerf {

Camera::Camera(const CameraDesc& desc, int width, int height)
    : mEye(desc.eye),
      mForward(normalizeSafe(desc.lookAt - desc.eye)),
      mTanHalfFov(std::tan(0.5 * desc.fovDegrees * glm::pi<double>() / 180.0)),
      mWidth(width),
      mHeight(height) {
    // Overflow-safe: eye and look_at may be 1e300 apart, and up may be as long.
    mRight = normalizeSafe(glm::cross(mForward, normalizeSafe(desc.up)));
    mUp = glm::cross(mRight, mForward);
}

Ray Camera::rayThrough(double x, double y) const {
    const double sx = (x / mWidth * 2.0 - 1.0) * mTanHalfFov * (mWidth / mHeight);
    const double sy = (1.0 - y / mHeight * 2.0) * mTanHalfFov;
    return Ray{mEye, glm::normalize(mForward + sx * mRight + sy * mUp)};
}

}  // namespace kerf
