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
    mLensRadius = 0.5 * desc.aperture;
    mFocusDistance =
        desc.focusDistance > 0.0 ? desc.focusDistance : glm::length(desc.lookAt - desc.eye);
}

Ray Camera::rayThrough(double x, double y, double lensU, double lensV) const {
    const Ray pinhole = rayThrough(x, y);
    if (mLensRadius <= 0.0) return pinhole;
    // Shirley and Chiu's concentric map: the unit square onto the unit disc, area-preserving
    // and with little distortion, so stratified lens samples stay stratified.
    const double a = 2.0 * lensU - 1.0, b = 2.0 * lensV - 1.0;
    double r = 0.0, phi = 0.0;
    const double quarter = 0.25 * glm::pi<double>();
    if (a == 0.0 && b == 0.0) {
        r = 0.0;
    } else if (std::fabs(a) > std::fabs(b)) {
        r = a;
        phi = quarter * (b / a);
    } else {
        r = b;
        phi = 2.0 * quarter - quarter * (a / b);
    }
    const Vec3 offset = mLensRadius * r * (std::cos(phi) * mRight + std::sin(phi) * mUp);
    const Vec3 focus =
        pinhole.origin + (mFocusDistance / glm::dot(pinhole.dir, mForward)) * pinhole.dir;
    const Vec3 origin = mEye + offset;
    return Ray{origin, glm::normalize(focus - origin)};
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
    auto nearestToZero = [](const double(&r)[2]) { return std::clamp(0.0, r[0], r[1]); };
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
