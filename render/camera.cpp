/// @file render/camera.cpp
/// @brief Pinhole camera rays.
#include "render/camera.h"

#include "csg/normalize.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

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

Bounds3 Camera::frustumSlice(double x0, double y0, double x1, double y1, double ta,
                             double tb) const {
    const double aspect = mWidth / mHeight;
    const double sx[2] = {(x0 / mWidth * 2.0 - 1.0) * mTanHalfFov * aspect,
                          (x1 / mWidth * 2.0 - 1.0) * mTanHalfFov * aspect};
    const double sy[2] = {(1.0 - y1 / mHeight * 2.0) * mTanHalfFov,
                          (1.0 - y0 / mHeight * 2.0) * mTanHalfFov};
    // d = v/|v| with v = f + sx·r + sy·u and |v|² = 1 + sx² + sy² (f, r, u orthonormal), so
    // t·d = s·v with s = t/|v| in [ta/|v|max, tb/|v|min]; s·v for v in the rectangle and s in
    // that range lies in the hull of the eight scaled corners.
    auto nearestToZero = [](const double (&r)[2]) { return std::clamp(0.0, r[0], r[1]); };
    const double nx = nearestToZero(sx), ny = nearestToZero(sy);
    const double fx = std::max(std::fabs(sx[0]), std::fabs(sx[1]));
    const double fy = std::max(std::fabs(sy[0]), std::fabs(sy[1]));
    const double sNear = ta / std::sqrt(1.0 + fx * fx + fy * fy);
    const double sFar = tb / std::sqrt(1.0 + nx * nx + ny * ny);
    Bounds3 box;
    double magnitude = 0.0;
    for (double s : {sNear, sFar})
        for (double x : sx)
            for (double y : sy) {
                const Vec3 p = mEye + s * (mForward + x * mRight + y * mUp);
                box.extend(p);
                for (int a = 0; a < 3; ++a) magnitude = std::max(magnitude, std::fabs(p[a]));
            }
    // Rounding of both this hull and rayThrough's normalisation and scaling: a few ulps of the
    // largest coordinate (and of the reach, for an eye at the origin).
    const double pad = 64.0 * 0x1p-52 * std::max(magnitude, tb);
    box.lo -= Vec3(pad);
    box.hi += Vec3(pad);
    return box;
}

}  // namespace kerf
