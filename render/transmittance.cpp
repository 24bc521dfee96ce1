/// @file render/transmittance.cpp
/// @brief Shadow transmittance, Beer absorption, mist and the miss colour (transmittance.h).
#include "render/transmittance.h"

#include "render/medium_transport.h"
#include "render/pattern_eval.h"

#include <cmath>

namespace kerf {

Vec3 beer(const Vec3& absorb, double length) {
    Vec3 r(1.0);
    for (int i = 0; i < 3; ++i)
        if (absorb[i] > 0) r[i] = std::exp(-absorb[i] * length);
    return r;
}

Vec3 missColor(const Scene& scene, const Vec3& d) {
    if (scene.mist.enabled) return scene.mist.color;
    const Sky& sky = scene.sky;
    if (!sky.gradient) return scene.background;
    const double h = glm::dot(d, sky.up);
    return h >= 0.0 ? sky.horizon + h * (sky.zenith - sky.horizon)
                    : sky.horizon - h * (sky.nadir - sky.horizon);
}

Vec3 applyMist(const Scene& scene, const Vec3& c, double distance) {
    if (!scene.mist.enabled) return c;
    const Vec3& mist = scene.mist.color;
    return mist + (c - mist) * std::exp(-distance / scene.mist.distance);
}

Transmittance::Transmittance(const Scene& scene, const SceneGeometry& shadowGeometry)
    : mScene(scene), mShadowGeometry(shadowGeometry) {
    for (const Material& m : scene.materials)
        if (m.transmit > 0) mAnyTransmissive = true;
    mMedium = scene.medium.enabled();
}

Vec3 Transmittance::along(const Ray& ray, double tmax, ShadingContext& ctx) const {
    const Vec3 pass = surfaces(ray, tmax, ctx);
    if (!mMedium || maxComponent(pass) <= 0.0) return pass;
    MediumRandom rng(mediumSeed(ctx, ray, 2));
    return pass * mediumTransmittance(mScene.medium, Ray{ray.origin, glm::normalize(ray.dir)},
                                      tmax * glm::length(ray.dir), rng);
}

Vec3 Transmittance::surfaces(const Ray& ray, double tmax, ShadingContext& ctx) const {
    if (!mAnyTransmissive)
        return mShadowGeometry.occluded(ray, 0.0, tmax, ctx.trace) ? Vec3(0.0) : Vec3(1.0);

    Vec3 pass(1.0);
    bool blocked = false;
    const double dirLength = glm::length(ray.dir);
    // A surface crossed within the segment: opaque ones block, transmissive ones tint.
    auto cross = [&](const Boundary& b) {
        if (!b.isSurface() || !(b.t > 0.0 && b.t < tmax)) return;
        const Material& mb = materialOf(mScene, b.material);
        if (mb.transmit <= 0)
            blocked = true;
        else
            pass *= mb.transmit *
                    surfaceColor(mb, ray.at(b.t), 0.0, Footprint{Vec3(0.0), Vec3(0.0), b.normal});
    };
    // Only the spans' extents and materials matter here, within the tolerance.
    const OcclusionScope scope(ctx.trace);
    mShadowGeometry.forEachObjectSpans(ray, 0.0, tmax, ctx.trace, [&](int, const SpanList& spans) {
        for (const Span& s : spans) {
            if (blocked) return false;
            if (s.in.t == s.out.t) {  // a surface's crossing (csg/primitives/surfaces.h)
                cross(s.in);
                continue;
            }
            const double a = std::max(s.in.t, 0.0);
            const double b = std::min(s.out.t, tmax);
            if (!(a < b)) continue;  // the span misses the segment
            // The span's material is that of its entry, or of its exit if the entry is a clip.
            const Material& ms =
                materialOf(mScene, s.in.isSurface() ? s.in.material : s.out.material);
            if (ms.transmit <= 0) {
                blocked = true;
                return false;
            }
            pass *= beer(ms.absorb, (b - a) * dirLength);
            cross(s.in);
            cross(s.out);
        }
        return !blocked;
    });
    return blocked ? Vec3(0.0) : pass;
}

}  // namespace kerf
