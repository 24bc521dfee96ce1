/// @file scene/scene.h
/// @brief The scene description that lang/ builds and render/, slice/, accuracy/ and app/'s
/// commands (check, mesh, voxelize) consume: plain data, validated when it was built. It holds
/// nothing of the renderer's or the language's machinery, so any consumer can depend on it
/// without a cycle: lang → scene → csg, render → scene.
#pragma once

#include "csg/tree/node.h"
#include "csg/types.h"
#include "scene/medium.h"
#include "scene/pattern.h"
#include "scene/sampling.h"

#include <string>
#include <vector>

namespace kerf {

struct Material {
    std::string name = "default";
    Vec3 color{0.8, 0.8, 0.8};
    double ambient = 0.1;
    double diffuse = 0.8;
    double specular = 0.0;
    double shininess = 20.0;
    double reflect = 0.0;   ///< mirror weight
    double transmit = 0.0;  ///< refraction weight; > 0 makes the material a dielectric
    double ior = 1.5;
    Vec3 absorb{0.0};  ///< Beer absorption coefficient per unit length inside
    Vec3 emit{0.0};    ///< emitted radiance, added unlit
    /// Glossy reflection: the mirror ray is spread uniformly over a cone of this half-angle
    /// (degrees) about the mirror direction; 0 is a perfect mirror.
    double glossy = 0.0;
    /// Translucency (frosted glass): the refracted ray spread over a cone of this half-angle.
    double translucent = 0.0;
    /// A solid texture that gives the colour point by point in place of `color` (null: the
    /// flat `color`).
    std::shared_ptr<const Pattern> pattern;
    /// A bump map: the shading normal tilted by the gradient of bumpDepth · h, h the pattern's
    /// value in [0, 1] (null: none).
    std::shared_ptr<const Pattern> bump;
    double bumpDepth = 0.0;
};

/// How a light's irradiance falls off with distance d (scaled so that every choice gives the
/// same irradiance at distance 1).
enum class Falloff : uint8_t {
    InverseSquare,  ///< physical: ∝ 1/d² (kerf's default)
    Linear,         ///< ∝ 1/d
    None,           ///< constant, as POV-Ray's lights by default
};

struct Light {
    /// Point: a point at `position`. Directional: parallel light along `direction`. Area: the
    /// parallelogram position + u·edgeU + v·edgeV (u, v in [0, 1]), emitting from both faces.
    /// Sphere: the ball of `radius` about `position`. Area and sphere lights are sampled per
    /// shading point, so their shadows are soft.
    enum class Kind { Point, Directional, Area, Sphere };
    Kind kind = Kind::Point;
    Vec3 position{0.0};              ///< point and sphere lights: the centre; area: a corner
    Vec3 direction{0.0, -1.0, 0.0};  ///< directional lights: the direction light travels
    Vec3 color{1.0};
    /// Point lights: irradiance at distance d is color·power / (4π d²). Area and sphere lights
    /// emit the same total power as Lambertian emitters (radiance power / (2π·area) from each
    /// face of a parallelogram, power / (4π²r²) from a sphere), so far away they light as a
    /// point light of that power (a sphere exactly; a parallelogram facing the point within
    /// a factor 2·cos). Directional: color.
    double power = 1.0;
    Vec3 edgeU{0.0};  ///< area lights: the parallelogram's edges from `position`
    Vec3 edgeV{0.0};
    double radius = 0.0;  ///< sphere lights
    Falloff falloff = Falloff::InverseSquare;
    /// POV-Ray's fade_distance F (> 0): the irradiance at distance 1 times 2/(1 + (d/F)^k),
    /// k = 2 for inverse_square, 1 for linear (POV-Ray's fade_power); 0: the falloff alone.
    double fadeDistance = 0.0;
    bool shadows = true;  ///< false: this light's shadow rays are not traced (nothing blocks it)
    /// Area and sphere lights: points sampled on the light per shading point (their estimates
    /// averaged), placed by a rank-1 lattice shifted by the sample's own point, so they are
    /// stratified over the light and still unbiased.
    int samples = 1;
};

/// The sky rays that hit nothing see: a flat colour, or a gradient from the horizon to the
/// zenith (and to the nadir below the horizon) along `up`.
struct Sky {
    bool gradient = false;
    Vec3 horizon{0.0};
    Vec3 zenith{0.0};
    Vec3 nadir{0.0};
    Vec3 up{0.0, 1.0, 0.0};  ///< unit length
};

/// Per-object options beside the object's tree.
struct ObjectFlags {
    bool castsShadow = true;  ///< false (`no_shadow`): shadow rays pass through the object
};

struct CameraDesc {
    Vec3 eye{0.0, 0.0, -5.0};
    Vec3 lookAt{0.0};
    Vec3 up{0.0, 1.0, 0.0};
    double fovDegrees = 40.0;  ///< vertical field of view, in (0, 180)
    /// A thin lens (aperture > 0) and a shutter (each sample sees the scene at its own time in
    /// it: motion blur of `move`/`spin`). The defaults are the pinhole camera at one instant.
    double aperture = 0.0;       ///< lens diameter; 0 is a pinhole
    double focusDistance = 0.0;  ///< 0: the distance from eye to lookAt
    double shutterOpen = 0.0;    ///< shutter interval in scene time; equal ends: one instant
    double shutterClose = 0.0;
};

/// Homogeneous mist, the cheap special case; a heterogeneous medium (a density grid) is
/// Scene::medium (scene/medium.h).
struct Mist {
    bool enabled = false;
    Vec3 color{0.0};
    double distance = 1.0;  ///< colour blends to the mist colour by exp(-d / distance)
};

/// A section plane through `point`: the solids are cut by it, the side `normal` points to
/// removed. render/section_cut.h renders the cut (`kerf render --section` adds more).
struct SectionPlane {
    Vec3 point{0.0};
    Vec3 normal{0.0, 0.0, 1.0};   ///< unit length
    Vec3 color{0.85, 0.2, 0.15};  ///< the caps' colour (the cut faces), lit as a diffuse material
};

struct RenderSettings {
    int width = 640;
    int height = 480;
    int spp = 1;                                  ///< samples per pixel, exactly
    SamplerKind sampler = SamplerKind::Jittered;  ///< how they are placed (scene/sampling.h)
    FilterKind filter = FilterKind::Box;          ///< how they are weighed into pixels
    /// Adaptive sampling: a pixel stops once the standard error of its mean (luminance) is
    /// below this, after at least kMinAdaptiveSamples samples; 0: always spp samples.
    double noise = 0.0;
    /// Bounces of reflection and refraction. High by default: paths end when their weight
    /// falls below kMinRayWeight (render/whitted_integrator.h) long before, so a closed glass body
    /// is not darkened by running out of bounces (POV-Ray's max_trace_level 5 darkens its pixels).
    int maxDepth = 64;
};

struct Scene {
    CameraDesc camera;
    std::vector<Light> lights;
    /// materials[0] is the default (grey, diffuse) that objects without a material get.
    std::vector<Material> materials{Material{}};
    Mist mist;
    /// A heterogeneous medium (scene/medium.h); disabled (no density) by default.
    Medium medium;
    Vec3 background{0.0};  ///< the sky's colour where `sky.gradient` is false
    Sky sky;
    std::vector<SectionPlane> sections;
    RenderSettings settings;
    /// Each object's tree already holds its transforms and materials; objects are separate
    /// (overlapping objects are not merged), the nearest surface of any of them is seen.
    std::vector<NodePtr> objects;
    /// objectFlags[i] for objects[i]; empty (or shorter) means the defaults.
    std::vector<ObjectFlags> objectFlags;
};

}  // namespace kerf
