/// @file render/light_sample.cpp
/// @brief Sampling lights and cones (Shirley §13.4.2; the solid-angle sampling of a sphere).
#include "render/light_sample.h"

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace kerf {

Vec3 perpendicularTo(const Vec3& a) {
    // The axis a is least aligned with gives a well-conditioned cross product.
    const Vec3 other = std::fabs(a.x) < 0.57   ? Vec3(1.0, 0.0, 0.0)
                       : std::fabs(a.y) < 0.57 ? Vec3(0.0, 1.0, 0.0)
                                               : Vec3(0.0, 0.0, 1.0);
    return glm::normalize(glm::cross(a, other));
}

namespace {

/// A direction within the cone about `axis` whose cosine to it is cosTheta, at angle phi.
Vec3 coneDirection(const Vec3& axis, double cosTheta, double phi) {
    const Vec3 t = perpendicularTo(axis);
    const Vec3 b = glm::cross(axis, t);
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    return glm::normalize(cosTheta * axis + sinTheta * (std::cos(phi) * t + std::sin(phi) * b));
}

/// The distance from o along the unit direction l to the sphere (c, r), the nearer crossing;
/// where rounding leaves the ray just outside, the closest approach.
double distanceToSphere(const Vec3& o, const Vec3& l, const Vec3& c, double r) {
    const Vec3 oc = c - o;
    const double b = glm::dot(l, oc);
    const Vec3 perpendicular = oc - b * l;  // the miss vector: stable where b is large
    const double h2 = r * r - glm::dot(perpendicular, perpendicular);
    return h2 > 0.0 ? b - std::sqrt(h2) : b;
}

}  // namespace

Vec3 sampleCone(const Vec3& axis, double halfAngle, const SubPixel& u) {
    if (!(halfAngle > 0.0)) return axis;
    // Uniform in solid angle: cos θ uniform on [cos α, 1].
    const double oneMinusCosMax = 2.0 * std::pow(std::sin(0.5 * halfAngle), 2.0);
    const double cosTheta = 1.0 - u.x * oneMinusCosMax;
    return coneDirection(axis, cosTheta, 2.0 * glm::pi<double>() * u.y);
}

Vec3 sampleConeAbove(const Vec3& axis, const Vec3& side, double halfAngleDegrees,
                     const SubPixel& u) {
    Vec3 dir = sampleCone(glm::normalize(axis), halfAngleDegrees * glm::pi<double>() / 180.0, u);
    const double below = glm::dot(dir, side);
    if (below <= 0.0) dir -= 2.0 * below * side;
    return dir;
}

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

LightSample sampleLight(const Light& light, const Vec3& p, const Vec3& origin, const SubPixel& u) {
    const double pi = glm::pi<double>();
    LightSample s;
    switch (light.kind) {
        case Light::Kind::Point: {
            const Vec3 toLight = light.position - p;
            const double dist2 = glm::dot(toLight, toLight);
            s.direction = toLight / std::sqrt(dist2);
            s.radiance = light.color * (light.power / (4.0 * pi * dist2));
            s.distance = glm::length(light.position - origin);
            s.position = light.position;
            s.emitted = s.radiance;
            s.pdf = 1.0;
            return s;
        }
        case Light::Kind::Directional:
            s.direction = -glm::normalize(light.direction);
            s.radiance = light.color;
            s.distance = kInf;
            s.emitted = s.radiance;
            s.pdf = 1.0;
            return s;
        case Light::Kind::Area: {
            // Uniform over the parallelogram (density 1/A): L·cos θ_light·A/d², with the
            // radiance L = power/(2π·A) of a two-faced Lambertian emitter.
            const Vec3 q = light.position + u.x * light.edgeU + u.y * light.edgeV;
            const Vec3 w = q - p;
            const double dist2 = glm::dot(w, w);
            if (!(dist2 > 0.0)) return s;
            s.direction = w / std::sqrt(dist2);
            const Vec3 normal = glm::cross(light.edgeU, light.edgeV);
            const double area = glm::length(normal);
            if (!(area > 0.0)) return s;
            const double cosLight = std::fabs(glm::dot(normal, s.direction)) / area;
            s.radiance = light.color * (light.power * cosLight / (2.0 * pi * dist2));
            s.distance = glm::length(q - origin);
            s.position = q;
            s.normal = normal / area;
            s.emitted = light.color * (light.power / (2.0 * pi * area));
            s.pdf = 1.0 / area;
            s.measure = LightPdfMeasure::Area;
            return s;
        }
        case Light::Kind::Sphere: {
            // Uniform over the cone of directions the ball fills (density 1/Ω): L·Ω, with the
            // radiance L = power/(4π²r²) of a Lambertian sphere.
            const Vec3 c = light.position - p;
            const double dc = glm::length(c);
            const double r = light.radius;
            if (!(dc > r)) return s;  // the point is inside the light: no direction to it
            const Vec3 axis = c / dc;
            const double sinMax2 = (r / dc) * (r / dc);
            const double cosMax = std::sqrt(std::max(0.0, 1.0 - sinMax2));
            const double oneMinusCosMax = sinMax2 / (1.0 + cosMax);  // no cancellation
            const double cosTheta = 1.0 - u.x * oneMinusCosMax;
            s.direction = coneDirection(axis, cosTheta, 2.0 * pi * u.y);
            const double solidAngle = 2.0 * pi * oneMinusCosMax;
            s.radiance = light.color * (light.power / (4.0 * pi * pi * r * r) * solidAngle);
            s.distance = distanceToSphere(origin, s.direction, light.position, r);
            s.position = origin + s.distance * s.direction;
            s.normal = glm::normalize(s.position - light.position);
            s.emitted = light.color * (light.power / (4.0 * pi * pi * r * r));
            s.pdf = 1.0 / solidAngle;
            s.measure = LightPdfMeasure::SolidAngle;
            return s;
        }
    }
    return s;
}

double lightPdf(const Light& light, const Vec3& p, const Vec3& wi) {
    const double pi = glm::pi<double>();
    if (light.kind == Light::Kind::Area) {
        // Where the ray p + t·wi meets the light's plane, in the edges' coordinates.
        const Vec3 normal = glm::cross(light.edgeU, light.edgeV);
        const double area = glm::length(normal);
        const double denom = glm::dot(normal, wi);
        if (!(area > 0.0) || denom == 0.0) return 0.0;
        const double t = glm::dot(normal, light.position - p) / denom;
        if (!(t > 0.0)) return 0.0;
        const Vec3 rel = p + t * wi - light.position;
        const double a = glm::dot(glm::cross(rel, light.edgeV), normal) / (area * area);
        const double b = glm::dot(glm::cross(light.edgeU, rel), normal) / (area * area);
        if (a < 0.0 || a > 1.0 || b < 0.0 || b > 1.0) return 0.0;
        const double cosLight = std::fabs(denom) / area;
        return t * t / (area * cosLight);
    }
    if (light.kind == Light::Kind::Sphere) {
        const Vec3 c = light.position - p;
        const double dc = glm::length(c);
        const double r = light.radius;
        if (!(dc > r)) return 0.0;
        const double sinMax2 = (r / dc) * (r / dc);
        const double cosMax = std::sqrt(std::max(0.0, 1.0 - sinMax2));
        const double oneMinusCosMax = sinMax2 / (1.0 + cosMax);
        if (glm::dot(wi, c / dc) < cosMax) return 0.0;
        return 1.0 / (2.0 * pi * oneMinusCosMax);
    }
    return 0.0;
}

}  // namespace kerf
