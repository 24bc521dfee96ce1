/// @file render/whitted_integrator.cpp
/// @brief The Whitted integrator (see whitted_integrator.h for the material model).
#include "render/whitted_integrator.h"

#include "render/bsdf.h"
#include "render/light_sample.h"
#include "render/pattern_eval.h"
#include "render/ray_offset.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace kerf {
namespace {

/// The patch of surface a sample stands for where a ray along d (unit) meets a surface of
/// normal n (unit, facing the ray) after travelling `distance`: the sample's cone is
/// `sampleAngle · distance` wide there, and stretched by the slant along the tangent the ray
/// runs along (at most 20 times: further, the box would blur a whole horizon into one tone).
Footprint footprintAt(const Vec3& d, const Vec3& n, double distance, const ShadingContext& ctx) {
    const double width = ctx.sampleAngle * distance;
    if (!(width > 0.0)) return {Vec3(0.0), Vec3(0.0), n};
    const double cosine = std::max(-glm::dot(d, n), 0.05);
    const Vec3 along = d + cosine * n;  // d's part in the tangent plane
    const double alongLength = glm::length(along);
    const Vec3 t1 = alongLength > 1e-6 ? along / alongLength : perpendicularTo(n);
    const Vec3 t2 = glm::cross(n, t1);
    return {t1 * (width / cosine), t2 * width, n};
}

/// The translucency dimension of a bounce: its gloss dimension with this bit set.
constexpr uint32_t kTranslucentDim = 1u << 30;

}  // namespace

RayBudgetSplit splitRayBudget(uint64_t budget, double reflectWeight, double refractWeight) {
    const bool reflect = reflectWeight >= kMinRayWeight;  // false for NaN too
    const bool refract = refractWeight >= kMinRayWeight;
    if (!reflect && !refract) return {0, 0};
    if (!refract) return {budget, 0};
    if (!reflect) return {0, budget};
    // In proportion to the weights; inf or NaN ratios (weights past the policy) split evenly.
    double share = reflectWeight / (reflectWeight + refractWeight);
    if (!(share >= 0.0 && share <= 1.0)) share = 0.5;
    const uint64_t r = std::min(budget, uint64_t(std::floor(double(budget) * share)));
    return {r, budget - r};
}

WhittedIntegrator::WhittedIntegrator(const Scene& scene, const SceneGeometry& geometry,
                                     int maxDepth, const SceneGeometry* shadowGeometry)
    : mScene(scene),
      mGeometry(geometry),
      mMaxDepth(std::max(0, maxDepth)),
      mShadows(scene, shadowGeometry ? *shadowGeometry : geometry),
      mMedium(scene, mShadows) {
    for (const Light& light : scene.lights)
        mLightLattice.push_back(
            light.samples > 1 ? PixelSampler::latticeGenerator(uint32_t(light.samples)) : 1);
}

Vec3 WhittedIntegrator::traceCamera(const Ray& ray, ShadingContext& ctx,
                                    std::optional<Hit>* firstHit, double tStart) const {
    ++ctx.rays.camera;
    PathState path;
    path.segmentStart = ray.origin;
    path.budget = kRayBudget;
    return trace(ray, path, ctx, firstHit, tStart);
}

Vec3 WhittedIntegrator::trace(const Ray& ray, const PathState& path, ShadingContext& ctx,
                              std::optional<Hit>* firstHit, double tStart) const {
    const std::optional<Hit> hit = mGeometry.nearestHit(ray, tStart, kInf, ctx.trace);
    if (firstHit) *firstHit = hit;
    if (!hit) {
        const Vec3 d = glm::normalize(ray.dir);
        return mMedium.enabled() ? mMedium.through(Ray{path.segmentStart, d}, kInf,
                                                   missColor(mScene, d), path.depth, ctx)
                                 : missColor(mScene, d);
    }

    const Material& m = materialOf(mScene, hit->material);
    const Vec3 p = ray.at(hit->t);
    const Vec3 d = glm::normalize(ray.dir);
    // Shade with the normal turned toward the viewer; the outward normal decides nothing else.
    Vec3 n = glm::dot(hit->normal, d) < 0 ? hit->normal : -hit->normal;
    const double err = hitErrorBound(ray, hit->t, p, hit->relError);
    const double length = glm::length(p - path.segmentStart);
    const double travelled = path.travelled + length;
    if (m.bump && m.bumpDepth != 0.0) {
        // The bumped normal shades; one tilted to face away from the viewer (a bump steeper
        // than the view is grazing) would light the back of the surface, so it is not taken.
        const Vec3 bumped =
            bumpedNormal(*m.bump, m.bumpDepth, p, n, err, footprintAt(d, n, travelled, ctx));
        if (glm::dot(bumped, d) < 0.0) n = bumped;
    }

    const Vec3 albedo =
        m.pattern ? surfaceColor(m, p, err, footprintAt(d, n, travelled, ctx)) : m.color;
    const Bsdf bsdf(m, albedo, n, hit->entering);
    Vec3 c = m.emit + (1.0 - m.transmit) * m.ambient * albedo;
    c += directLight(bsdf, p, d, err, path.depth, ctx);
    if (path.depth < mMaxDepth && path.budget > 0)
        traceSecondary(bsdf, m, p, d, err, length, path, ctx, c);

    // Everything seen through a leaving hit travelled the whole segment inside the solid.
    if (!hit->entering) c *= beer(m.absorb, length);
    if (mMedium.enabled())
        c = mMedium.through(Ray{path.segmentStart, d}, length, c, path.depth, ctx);
    return applyMist(mScene, c, length);
}

void WhittedIntegrator::traceSecondary(const Bsdf& bsdf, const Material& m, const Vec3& p,
                                       const Vec3& d, double err, double length,
                                       const PathState& path, ShadingContext& ctx, Vec3& c) const {
    const Vec3& n = bsdf.normal();
    const SpecularLobes lobes = bsdf.specular(-d);
    const Vec3 wReflect = path.weight * lobes.reflectWeight;
    const Vec3 wRefract = path.weight * lobes.refractWeight;
    const RayBudgetSplit split =
        splitRayBudget(path.budget, maxComponent(wReflect), maxComponent(wRefract));
    PathState next;
    next.segmentStart = p;
    next.depth = path.depth + 1;
    next.travelled = path.travelled + length;
    if (split.reflect > 0) {
        ++ctx.rays.reflection;
        Vec3 dir = lobes.reflectDir;
        if (m.glossy > 0.0)
            dir = sampleConeAbove(dir, n, m.glossy, ctx.sample2D(sample_dim::gloss(path.depth)));
        next.weight = wReflect;
        next.budget = split.reflect - 1;
        c += lobes.reflectWeight * trace(Ray{offsetRayOrigin(p, n, err), dir}, next, ctx, nullptr);
    }
    if (split.refract > 0) {
        ++ctx.rays.refraction;
        Vec3 dir = lobes.refractDir;
        if (m.translucent > 0.0)
            dir = sampleConeAbove(dir, -n, m.translucent,
                                  ctx.sample2D(sample_dim::gloss(path.depth) | kTranslucentDim));
        next.weight = wRefract;
        next.budget = split.refract - 1;
        c += lobes.refractWeight * trace(Ray{offsetRayOrigin(p, -n, err), dir}, next, ctx, nullptr);
    }
}

SubPixel WhittedIntegrator::lightShift(size_t k, int depth, uint32_t count,
                                       const ShadingContext& ctx) const {
    // Each light of each bounce draws from its own dimension; its `samples` points are a
    // rank-1 lattice shifted by that one point (Cranley–Patterson), so they cover the
    // light evenly and their mean stays unbiased. With several points the shift also
    // takes a hashed offset per pixel sample: the pixel's own points may form the same
    // lattice (the lattice sampler with spp = samples), and lattice plus lattice point is
    // the same lattice again, which would visit only `samples` places on the light.
    const uint32_t dim = sample_dim::light(depth) + (uint32_t(k) << 16);
    SubPixel u0 = ctx.sample2D(dim);
    if (count > 1) {
        u0.x += hashUniform(ctx.pixel, uint32_t(ctx.sample), dim ^ 0x9e3779b9u);
        u0.y += hashUniform(ctx.pixel, uint32_t(ctx.sample), dim ^ 0x7f4a7c15u);
    }
    return u0;
}

Vec3 WhittedIntegrator::directLight(const Bsdf& bsdf, const Vec3& p, const Vec3& d,
                                    double errorBound, int depth, ShadingContext& ctx) const {
    Vec3 sum(0.0);
    const Vec3& n = bsdf.normal();
    const Vec3 wo = -d;
    const Vec3 origin = offsetRayOrigin(p, n, errorBound);
    for (size_t k = 0; k < mScene.lights.size(); ++k) {
        const Light& light = mScene.lights[k];
        const bool sampled = light.kind == Light::Kind::Area || light.kind == Light::Kind::Sphere;
        const uint32_t count = sampled ? uint32_t(std::max(1, light.samples)) : 1;
        const SubPixel u0 = sampled ? lightShift(k, depth, count, ctx) : SubPixel{};
        Vec3 lightSum(0.0);
        for (uint32_t s = 0; s < count; ++s) {
            SubPixel u = u0;
            if (count > 1) {
                u.x += double(s) / count;
                u.y += double((uint64_t(s) * mLightLattice[k]) % count) / count;
                u.x -= std::floor(u.x), u.y -= std::floor(u.y);
            }
            LightSample ls = sampleLight(light, p, origin, u);
            ls.radiance *= falloffScale(light, p);
            if (maxComponent(ls.radiance) <= 0) continue;
            if (glm::dot(n, ls.direction) <= 0) continue;  // the light is behind the surface

            Vec3 pass(1.0);
            if (light.shadows) {
                ++ctx.rays.shadow;
                pass = mShadows.along(Ray{origin, ls.direction}, ls.distance, ctx);
                if (maxComponent(pass) <= 0) continue;
            }
            // Whitted sums the Phong lobe per light: the BSDF's non-delta lobes but the glossy
            // mirror and translucency, which its traced rays carry.
            lightSum +=
                pass * ls.radiance * bsdf.evaluate(wo, ls.direction, kLobeDiffuse | kLobePhong);
        }
        sum += lightSum / double(count);
    }
    return sum;
}

}  // namespace kerf
