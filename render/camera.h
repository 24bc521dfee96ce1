/// @file render/camera.h
/// @brief The camera (a pinhole, or a thin lens): film positions to world rays, by exactly the
/// formula of the documentation (right-handed world, vertical field of view, pixel (0, 0) at the
/// top left).
#pragma once

#include "csg/types.h"
#include "scene/scene.h"

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

    /// The thin lens (Shirley §13.4.3): the ray through film position (x, y) that leaves the
    /// lens at `lens` (a point of the unit square, mapped to the aperture's disc) and passes
    /// where the pinhole ray meets the plane of focus (perpendicular to the view direction at
    /// the focus distance). A pinhole camera (aperture 0) gives rayThrough(x, y).
    Ray rayThrough(double x, double y, double lensU, double lensV) const;
    bool hasLens() const { return mLensRadius > 0.0; }

    const Vec3& eye() const { return mEye; }
    /// The angle one pixel spans near the image centre (radians, small-angle): 2·tan(fov/2)/H.
    double pixelAngle() const { return 2.0 * mTanHalfFov / mHeight; }

    /// A box holding eye + t·d for every ray d through the film rectangle [x0, x1] × [y0, y1]
    /// (pixels, any position inside) and every t in [ta, tb] (0 ≤ ta ≤ tb < inf): the hull of
    /// the rectangle's corner directions scaled to the nearest and farthest reach, widened
    /// outward by a bound on the rounding of rayThrough and of the box itself.
    Bounds3 frustumSlice(double x0, double y0, double x1, double y1, double ta, double tb) const;

private:
    Vec3 mEye;
    Vec3 mForward;  ///< f = normalize(look_at − eye)
    Vec3 mRight;    ///< r = normalize(f × up)
    Vec3 mUp;       ///< u = r × f
    double mTanHalfFov = 0;
    double mLensRadius = 0;     ///< half the aperture
    double mFocusDistance = 0;  ///< along the view direction
    double mWidth = 0;
    double mHeight = 0;
};

}  // namespace kerf
