/// @file render/shading.cpp
/// @brief The Whitted integrator (see shading.h for the material model).
#include "render/shading.h"

#include "render/light_sample.h"
#include "render/pattern_eval.h"
#include "render/ray_offset.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace kerf {
namespace {

double maxComponent(const Vec3& v) { return std::max({v.x, v.y, v.z}); }

/// exp(−absorb·length) per channel; a channel that does not absorb passes everything, even
/// over an infinite length (where 0·inf would be NaN).
Vec3 beer(const Vec3& absorb, double length) {
    Vec3 r(1.0);
    for (int i = 0; i < 3; ++i)
        if (absorb[i] > 0) r[i] = std::exp(-absorb[i] * length);
    return r;
}

/// Schlick's approximation of the Fresnel reflectance between media n1 and n2, with cosine
/// `cosine` taken on the side of the lower index.
double schlick(double n1, double n2, double cosine) {
    const double r0 = (n1 - n2) / (n1 + n2);
    const double f0 = r0 * r0;
    const double m = 1.0 - cosine;
    return f0 + (1.0 - f0) * (m * m) * (m * m) * m;
}

}  // namespace

/// The light's falloff against the inverse square that sampleLight applies: at distance d
/// from the light (its centre; an area light's corner region is near enough to one distance
/// for this to be a scale of its samples, exact for its nearest point as d grows).
double falloffScale(const Light& light, const Vec3& p) {
    if (light.kind == Light::Kind::Directional) return 1.0;
    if (light.falloff == Falloff::InverseSquare && light.fadeDistance <= 0.0) return 1.0;
    Vec3 centre = light.position;
    if (light.kind == Light::Kind::Area) centre += 0.5 * (light.edgeU + light.edgeV);
    const double d = glm::length(centre - p);
    if (!(d > 0.0)) return 1.0;
    const double k = light.falloff == Falloff::InverseSquare ? 2.0
                     : light.falloff == Falloff::Linear      ? 1.0
                                                             : 0.0;
    // The irradiance at distance 1 times the falloff's law, over the 1/d² already applied.
    const double law = light.fadeDistance > 0.0 ? 2.0 / (1.0 + std::pow(d / light.fadeDistance, k))
                                                : std::pow(d, -k);
    return law * d * d;
}

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
      mShadowGeometry(shadowGeometry ? *shadowGeometry : geometry),
      mMaxDepth(std::max(0, maxDepth)) {
    for (const Material& m : scene.materials)
        if (m.transmit > 0) mAnyTransmissive = true;
    mMedium = scene.medium.enabled();
    for (const Light& light : scene.lights)
        mLightLattice.push_back(
            light.samples > 1 ? PixelSampler::latticeGenerator(uint32_t(light.samples)) : 1);
}

const Material& WhittedIntegrator::material(int32_t index) const {
    if (index < 0 || size_t(index) >= mScene.materials.size()) return mScene.materials.front();
    return mScene.materials[size_t(index)];
}

Vec3 WhittedIntegrator::missColor(const Vec3& d) const {
    if (mScene.mist.enabled) return mScene.mist.color;
    const Sky& sky = mScene.sky;
    if (!sky.gradient) return mScene.background;
    const double h = glm::dot(d, sky.up);
    return h >= 0.0 ? sky.horizon + h * (sky.zenith - sky.horizon)
                    : sky.horizon - h * (sky.nadir - sky.horizon);
}

Vec3 WhittedIntegrator::applyMist(const Vec3& c, double distance) const {
    if (!mScene.mist.enabled) return c;
    const Vec3& mist = mScene.mist.color;
    return mist + (c - mist) * std::exp(-distance / mScene.mist.distance);
}

Vec3 WhittedIntegrator::traceCamera(const Ray& ray, ShadingContext& ctx,
                                    std::optional<Hit>* firstHit, double tStart) const {
    ++ctx.rays.camera;
    return trace(ray, ray.origin, 0, Vec3(1.0), kRayBudget, ctx, firstHit, tStart);
}

Vec3 WhittedIntegrator::trace(const Ray& ray, const Vec3& segmentStart, int depth,
                              const Vec3& weight, uint64_t budget, ShadingContext& ctx,
                              std::optional<Hit>* firstHit, double tStart, double travelled) const {
    const std::optional<Hit> hit = mGeometry.nearestHit(ray, tStart, kInf, ctx.trace);
    if (firstHit) *firstHit = hit;
    if (!hit) {
        const Vec3 d = glm::normalize(ray.dir);
        return mMedium ? throughMedium(Ray{segmentStart, d}, kInf, missColor(d), depth, ctx)
                       : missColor(d);
    }

    const Material& m = material(hit->material);
    const Vec3 p = ray.at(hit->t);
    const Vec3 d = glm::normalize(ray.dir);
    // Shade with the normal turned toward the viewer; the outward normal decides nothing else.
    Vec3 n = glm::dot(hit->normal, d) < 0 ? hit->normal : -hit->normal;
    const double err = hitErrorBound(ray, hit->t, p, hit->relError);
    const double length = glm::length(p - segmentStart);
    if (m.bump && m.bumpDepth != 0.0) {
        // The bumped normal shades; one tilted to face away from the viewer (a bump steeper
        // than the view is grazing) would light the back of the surface, so it is not taken.
        const Vec3 bumped = bumpedNormal(*m.bump, m.bumpDepth, p, n, err,
                                         footprintAt(d, n, travelled + length, ctx));
        if (glm::dot(bumped, d) < 0.0) n = bumped;
    }

    const Vec3 albedo =
        m.pattern ? surfaceColor(m, p, err, footprintAt(d, n, travelled + length, ctx)) : m.color;
    Vec3 c = m.emit + (1.0 - m.transmit) * m.ambient * albedo;
    c += directLight(m, albedo, p, n, d, err, depth, ctx);

    if (depth < mMaxDepth && budget > 0) {
        const double cosIn = -glm::dot(d, n);  // ≥ 0 with the face-forward normal
        Vec3 reflectWeight(m.reflect);
        Vec3 refractWeight(0.0);
        Vec3 refractDir(0.0);
        if (m.transmit > 0) {
            const double n1 = hit->entering ? 1.0 : m.ior;
            const double n2 = hit->entering ? m.ior : 1.0;
            const double eta = n1 / n2;
            const double k = 1.0 - eta * eta * (1.0 - cosIn * cosIn);
            if (k < 0) {
                reflectWeight += Vec3(m.transmit);  // total internal reflection
            } else {
                const double cosOut = std::sqrt(k);
                const double f = schlick(n1, n2, n1 <= n2 ? cosIn : cosOut);
                reflectWeight += Vec3(m.transmit * f);
                refractWeight = m.transmit * (1.0 - f) * albedo;
                refractDir = glm::normalize(eta * d + (eta * cosIn - cosOut) * n);
            }
        }
        const Vec3 wReflect = weight * reflectWeight;
        const Vec3 wRefract = weight * refractWeight;
        const RayBudgetSplit split =
            splitRayBudget(budget, maxComponent(wReflect), maxComponent(wRefract));
        if (split.reflect > 0) {
            ++ctx.rays.reflection;
            Vec3 dir = d + 2.0 * cosIn * n;
            if (m.glossy > 0.0)
                dir = sampleConeAbove(dir, n, m.glossy, ctx.sample2D(sample_dim::gloss(depth)));
            const Ray r{offsetRayOrigin(p, n, err), dir};
            c += reflectWeight * trace(r, p, depth + 1, wReflect, split.reflect - 1, ctx, nullptr,
                                       0.0, travelled + length);
        }
        if (split.refract > 0) {
            ++ctx.rays.refraction;
            if (m.translucent > 0.0)
                refractDir =
                    sampleConeAbove(refractDir, -n, m.translucent,
                                    ctx.sample2D(sample_dim::gloss(depth) | kTranslucentDim));
            const Ray r{offsetRayOrigin(p, -n, err), refractDir};
            c += refractWeight * trace(r, p, depth + 1, wRefract, split.refract - 1, ctx, nullptr,
                                       0.0, travelled + length);
        }
    }

    // Everything seen through a leaving hit travelled the whole segment inside the solid.
    if (!hit->entering) c *= beer(m.absorb, length);
    if (mMedium) c = throughMedium(Ray{segmentStart, d}, length, c, depth, ctx);
    return applyMist(c, length);
}

Vec3 WhittedIntegrator::directLight(const Material& m, const Vec3& albedo, const Vec3& p,
                                    const Vec3& n, const Vec3& d, double errorBound, int depth,
                                    ShadingContext& ctx) const {
    Vec3 sum(0.0);
    const Vec3 origin = offsetRayOrigin(p, n, errorBound);
    for (size_t k = 0; k < mScene.lights.size(); ++k) {
        const Light& light = mScene.lights[k];
        const bool sampled = light.kind == Light::Kind::Area || light.kind == Light::Kind::Sphere;
        // Each light of each bounce draws from its own dimension; its `samples` points are a
        // rank-1 lattice shifted by that one point (Cranley–Patterson), so they cover the
        // light evenly and their mean stays unbiased. With several points the shift also
        // takes a hashed offset per pixel sample: the pixel's own points may form the same
        // lattice (the lattice sampler with spp = samples), and lattice plus lattice point is
        // the same lattice again, which would visit only `samples` places on the light.
        const uint32_t dim = sample_dim::light(depth) + (uint32_t(k) << 16);
        SubPixel u0 = sampled ? ctx.sample2D(dim) : SubPixel{};
        const uint32_t count = sampled ? uint32_t(std::max(1, light.samples)) : 1;
        if (count > 1) {
            u0.x += hashUniform(ctx.pixel, uint32_t(ctx.sample), dim ^ 0x9e3779b9u);
            u0.y += hashUniform(ctx.pixel, uint32_t(ctx.sample), dim ^ 0x7f4a7c15u);
        }
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
            const Vec3& l = ls.direction;
            const Vec3& radiance = ls.radiance;
            const double tmax = ls.distance;
            if (maxComponent(radiance) <= 0) continue;
            const double cosL = glm::dot(n, l);
            if (cosL <= 0) continue;  // the light is behind the surface as seen

            Vec3 pass(1.0);
            if (light.shadows) {
                ++ctx.rays.shadow;
                pass = transmittance(Ray{origin, l}, tmax, ctx);
                if (maxComponent(pass) <= 0) continue;
            }

            Vec3 term = (1.0 - m.transmit) * m.diffuse * cosL * albedo;
            if (m.specular > 0) {
                const Vec3 r = 2.0 * cosL * n - l;  // l mirrored about n
                const double cosR = std::max(0.0, -glm::dot(r, d));
                term += Vec3(m.specular * std::pow(cosR, m.shininess));
            }
            lightSum += pass * radiance * term;
        }
        sum += lightSum / double(count);
    }
    return sum;
}

Vec3 WhittedIntegrator::transmittance(const Ray& ray, double tmax, ShadingContext& ctx) const {
    const Vec3 pass = surfaceTransmittance(ray, tmax, ctx);
    if (!mMedium || maxComponent(pass) <= 0.0) return pass;
    MediumRandom rng(mediumSeed(ctx, ray, 2));
    return pass * mediumTransmittance(mScene.medium, Ray{ray.origin, glm::normalize(ray.dir)},
                                      tmax * glm::length(ray.dir), rng);
}

Vec3 WhittedIntegrator::surfaceTransmittance(const Ray& ray, double tmax,
                                             ShadingContext& ctx) const {
    if (!mAnyTransmissive)
        return mShadowGeometry.occluded(ray, 0.0, tmax, ctx.trace) ? Vec3(0.0) : Vec3(1.0);

    Vec3 pass(1.0);
    bool blocked = false;
    const double dirLength = glm::length(ray.dir);
    // A surface crossed within the segment: opaque ones block, transmissive ones tint.
    auto cross = [&](const Boundary& b) {
        if (!b.isSurface() || !(b.t > 0.0 && b.t < tmax)) return;
        const Material& mb = material(b.material);
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
            if (s.in.t ==
                s.out.t) {  // a surface's crossing (csg/primitives/surfaces.h): nothing inside
                cross(s.in);
                continue;
            }
            const double a = std::max(s.in.t, 0.0);
            const double b = std::min(s.out.t, tmax);
            if (!(a < b)) continue;  // the span misses the segment
            // The span's material is that of its entry, or of its exit if the entry is a clip.
            const Material& ms = material(s.in.isSurface() ? s.in.material : s.out.material);
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
