/// @file tests/render/render_test_util.h
/// @brief Small scenes and closed-form oracles shared by the render tests.
#pragma once

#include "csg/tree/solids.h"
#include "render/render.h"
#include "scene/scene.h"

#include <cmath>
#include <optional>

namespace kerf::test {

/// A material with every lighting term off; tests switch on what they check.
inline Material blackMaterial() {
    Material m;
    m.color = Vec3(1.0);
    m.ambient = 0;
    m.diffuse = 0;
    m.specular = 0;
    return m;
}

/// Adds a material to the scene and returns its index.
inline int32_t addMaterial(Scene& scene, const Material& m) {
    scene.materials.push_back(m);
    return int32_t(scene.materials.size() - 1);
}

inline void addObject(Scene& scene, NodePtr node, int32_t material) {
    scene.objects.push_back(makeMaterial(std::move(node), material));
}

/// The camera ray direction for film position (x, y) by the documented formula, evaluated in
/// long double independently of render/camera.cpp.
inline Vec3 referenceDirection(const CameraDesc& c, int width, int height, double x, double y) {
    using LD = long double;
    auto norm = [](LD v[3]) {
        const LD l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        for (int k = 0; k < 3; ++k) v[k] /= l;
    };
    LD f[3] = {LD(c.lookAt.x) - c.eye.x, LD(c.lookAt.y) - c.eye.y, LD(c.lookAt.z) - c.eye.z};
    norm(f);
    LD r[3] = {f[1] * c.up.z - f[2] * c.up.y, f[2] * c.up.x - f[0] * c.up.z,
               f[0] * c.up.y - f[1] * c.up.x};
    norm(r);
    const LD u[3] = {r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2],
                     r[0] * f[1] - r[1] * f[0]};
    const LD tanHalf = std::tan(LD(c.fovDegrees) * 3.14159265358979323846264338327950288L / 360);
    const LD sx = (LD(x) / width * 2 - 1) * tanHalf * (LD(width) / height);
    const LD sy = (1 - LD(y) / height * 2) * tanHalf;
    LD d[3];
    for (int k = 0; k < 3; ++k) d[k] = f[k] + sx * r[k] + sy * u[k];
    norm(d);
    return Vec3(double(d[0]), double(d[1]), double(d[2]));
}

/// The first t > 0 where origin + t·dir (dir unit) enters the sphere, in long double.
inline std::optional<long double> raySphere(const Vec3& origin, const Vec3& dir, const Vec3& center,
                                            double radius) {
    using LD = long double;
    const LD oc[3] = {LD(origin.x) - center.x, LD(origin.y) - center.y, LD(origin.z) - center.z};
    const LD b = oc[0] * dir.x + oc[1] * dir.y + oc[2] * dir.z;
    const LD c = oc[0] * oc[0] + oc[1] * oc[1] + oc[2] * oc[2] - LD(radius) * radius;
    const LD disc = b * b - c;
    if (disc < 0) return std::nullopt;
    const LD t = -b - std::sqrt(disc);
    if (t <= 0) return std::nullopt;
    return t;
}

/// Distance from point c to the segment a–b.
inline double distanceToSegment(const Vec3& c, const Vec3& a, const Vec3& b) {
    const Vec3 ab = b - a;
    const double s = glm::clamp(glm::dot(c - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
    return glm::length(a + s * ab - c);
}

inline Vec3 pixel(const Image& image, int i, int j) {
    return Vec3(image.at(i, j, 0), image.at(i, j, 1), image.at(i, j, 2));
}

inline RenderOptions smallImage(int width, int height, int threads = 1) {
    RenderOptions o;
    o.width = width;
    o.height = height;
    o.spp = 1;
    o.threads = threads;
    return o;
}

}  // namespace kerf::test
