/// @file render/camera.h
/// @brief The pinhole camera: film positions to world rays, by exactly the formula of the
/// documentation (right-handed world, vertical field of view, pixel (0, 0) at the top left).
#pragma once

#include "scene/scene.h"
#include "csg/types.h"

namespace kerf {

class Camera {
public:
    /// A camera for an image of width × height pixels. The description is assumed valid
    /// (up not parallel to the view direction, fov in (0, 180)); lang/ checks it.
    Camera(const CameraDesc& desc, int width, int height);

    /// The ray through film position (x, y), in pixels from the top-left corner of the image:
    /// the centre of pixel (i, j) is (i + 0.5, j + 0.5). The origin is the eye and the
    /// direction unit length:
    /// d = normalize(f + (x/W·2 − 1)·tan(fov/2)·(W/H)·r + (1 − y/H·2)·tan(fov/2)·u).
    Ray rayThrough(double x, double y) const;

    const Vec3& eye() const { return mEye; }

private:
    Vec3 mEye;
    Vec3 mForward;  ///< f = normalize(look_at − eye)
    Vec3 mRight;    ///< r = normalize(f × up)
    Vec3 mUp;       ///< u = r × f
    double mTanHalfFov = 0;
    double mWidth = 0;
    double mHeight = 0;
};

}  // namespace kerf
