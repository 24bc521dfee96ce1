/// @file csg/frustum_interval.h
/// @brief TraceMethod::Interval for the solids around an axis (cylinder, cone): the frustum
/// isolation of csg/polynomial_isolation.h on a ray normalised in the solid's axial frame.
#pragma once

#include "csg/axial_frame.h"
#include "csg/polynomial_isolation.h"

#include <cmath>

namespace kerf {

/// The radii of a frustum: r1 at the base, growing by `slope` per unit along the axis; rMax is
/// the larger end radius.
struct FrustumRadii {
    double r1, slope, rMax;
};

/// Interval isolation of the cap slab's two linear functions and the lateral quadric,
/// normalised by the radius of the ball around the axis' middle that holds the solid, s
/// measured from the ray's point nearest that middle. lateralNormal(x, y): the outward normal
/// at local (x, y) across the axis (any common scale); surface(t, n): the boundary of a root;
/// window(t): that of an end of the caller's range [tmin, tmax].
template <class LateralNormal, class Surface, class Window>
void frustumIntervalSpans(const AxialFrame& frame, const FrustumRadii& radii, const Ray& ray,
                          double tmin, double tmax, TraceContext& ctx,
                          const LateralNormal& lateralNormal, const Surface& surface,
                          const Window& window, SpanList& out) {
    const Vec3& d = ray.dir;
    const double dd = glm::dot(d, d);
    if (!(dd > 0.0)) return;
    const Vec3 fl = frame.localPoint(ray.origin), dl = frame.localDirection(d);
    const double half = 0.5 * frame.length;
    const double ts = -(fl.x * dl.x + fl.y * dl.y + (fl.z - half) * dl.z) / dd;
    const double scale = std::sqrt(half * half + radii.rMax * radii.rMax), inv = 1.0 / scale;
    const double len = std::sqrt(dd), sPerT = len * inv;
    const FrustumAlongRay fr{(fl + ts * dl) * inv, dl / len, radii.r1 * inv, radii.slope,
                             frame.length * inv};
    const double sMin = (tmin - ts) * sPerT, sMax = (tmax - ts) * sPerT;
    const auto at = [&](double sv, int face, double windowT) {
        if (face == kFrustumWindow) return window(windowT);
        const double t = ts + sv / sPerT;
        if (face != kFrustumLateral)
            return surface(t, frame.capNormal(face == kFrustumTop ? 1 : -1));
        const Vec3 p = fr.g + sv * fr.u;
        return surface(t, lateralNormal(p.x, p.y));
    };
    frustumSpans(fr, sMin, sMax, ts * sPerT, ctx, [&](double sIn, int fIn, double sOut, int fOut) {
        out.push_back({at(sIn, fIn, sIn == sMin ? tmin : ts + sIn / sPerT),
                       at(sOut, fOut, sOut == sMax ? tmax : ts + sOut / sPerT)});
    });
    dropThinSpans(out, ctx.relTolerance);
}

}  // namespace kerf
