/// @file render/bsdf.cpp
/// @brief kerf's material lobes behind evaluate / sample / pdf (see bsdf.h).
#include "render/bsdf.h"

#include "render/light_sample.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace kerf {
namespace {

constexpr double kPi = glm::pi<double>();

double maxOf(const Vec3& v) { return std::max({v.x, v.y, v.z}); }

/// Schlick's approximation of the Fresnel reflectance between media n1 and n2, with cosine
/// `cosine` taken on the side of the lower index.
double schlick(double n1, double n2, double cosine) {
    const double r0 = (n1 - n2) / (n1 + n2);
    const double f0 = r0 * r0;
    const double m = 1.0 - cosine;
    return f0 + (1.0 - f0) * (m * m) * (m * m) * m;
}

/// A direction about the unit axis whose cosine to it is cosTheta, at angle phi.
Vec3 aboutAxis(const Vec3& axis, double cosTheta, double phi) {
    const Vec3 t = perpendicularTo(axis);
    const Vec3 b = glm::cross(axis, t);
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    return glm::normalize(cosTheta * axis + sinTheta * (std::cos(phi) * t + std::sin(phi) * b));
}

/// The Phong lobe's axis for wo: wo mirrored about n.
Vec3 phongAxis(const Vec3& wo, const Vec3& n) { return 2.0 * glm::dot(wo, n) * n - wo; }

}  // namespace

double coneAbovePdf(const Vec3& axis, const Vec3& side, double halfAngleDegrees, const Vec3& wi) {
    if (glm::dot(wi, side) <= 0.0) return 0.0;
    const double alpha = halfAngleDegrees * kPi / 180.0;
    const double oneMinusCosMax = 2.0 * std::pow(std::sin(0.5 * alpha), 2.0);
    if (!(oneMinusCosMax > 0.0)) return 0.0;  // a delta
    const double density = 1.0 / (2.0 * kPi * oneMinusCosMax);
    const Vec3 a = glm::normalize(axis);
    const double cosMax = 1.0 - oneMinusCosMax;
    // Directions that fell below the surface were mirrored up (sampleConeAbove).
    const Vec3 folded = wi - 2.0 * glm::dot(wi, side) * side;
    return density *
           ((glm::dot(wi, a) >= cosMax ? 1.0 : 0.0) + (glm::dot(folded, a) >= cosMax ? 1.0 : 0.0));
}

Bsdf::Bsdf(const Material& m, const Vec3& albedo, const Vec3& n, bool entering)
    : mMaterial(m), mAlbedo(albedo), mNormal(n), mEntering(entering) {}

SpecularLobes Bsdf::specular(const Vec3& wo) const {
    const Material& m = mMaterial;
    const Vec3& n = mNormal;
    const Vec3 d = -wo;                    // the incoming ray's direction
    const double cosIn = -glm::dot(d, n);  // ≥ 0 with the face-forward normal
    SpecularLobes s;
    s.reflectDir = d + 2.0 * cosIn * n;
    s.reflectWeight = Vec3(m.reflect);
    if (!(m.transmit > 0)) return s;
    const double n1 = mEntering ? 1.0 : m.ior;
    const double n2 = mEntering ? m.ior : 1.0;
    const double eta = n1 / n2;
    const double k = 1.0 - eta * eta * (1.0 - cosIn * cosIn);
    if (k < 0) {
        s.reflectWeight += Vec3(m.transmit);  // total internal reflection
        return s;
    }
    const double cosOut = std::sqrt(k);
    const double f = schlick(n1, n2, n1 <= n2 ? cosIn : cosOut);
    s.reflectWeight += Vec3(m.transmit * f);
    s.refractWeight = m.transmit * (1.0 - f) * mAlbedo;
    s.refractDir = glm::normalize(eta * d + (eta * cosIn - cosOut) * n);
    return s;
}

Vec3 Bsdf::evaluate(const Vec3& wo, const Vec3& wi, uint32_t lobes) const {
    const Material& m = mMaterial;
    const double cosL = glm::dot(mNormal, wi);
    Vec3 term(0.0);
    if (cosL > 0 && (lobes & kLobeDiffuse)) term = (1.0 - m.transmit) * m.diffuse * cosL * mAlbedo;
    if (cosL > 0 && (lobes & kLobePhong) && m.specular > 0) {
        const Vec3 r = 2.0 * cosL * mNormal - wi;  // wi mirrored about n
        const double cosR = std::max(0.0, glm::dot(r, wo));
        term += Vec3(m.specular * std::pow(cosR, m.shininess));
    }
    if ((lobes & (kLobeMirror | kLobeRefraction)) && (m.glossy > 0.0 || m.translucent > 0.0)) {
        const SpecularLobes s = specular(wo);
        if ((lobes & kLobeMirror) && m.glossy > 0.0)
            term += s.reflectWeight * coneAbovePdf(s.reflectDir, mNormal, m.glossy, wi);
        if ((lobes & kLobeRefraction) && m.translucent > 0.0 && maxOf(s.refractWeight) > 0.0)
            term += s.refractWeight * coneAbovePdf(s.refractDir, -mNormal, m.translucent, wi);
    }
    return term;
}

void Bsdf::lobeWeights(const SpecularLobes& s, double w[4]) const {
    const Material& m = mMaterial;
    w[0] = kPi * std::max(0.0, maxOf((1.0 - m.transmit) * m.diffuse * mAlbedo));
    w[1] = std::max(0.0, m.specular * 2.0 * kPi / (m.shininess + 1.0));
    w[2] = std::max(0.0, maxOf(s.reflectWeight));
    w[3] = std::max(0.0, maxOf(s.refractWeight));
    for (int i = 0; i < 4; ++i)
        if (!std::isfinite(w[i])) w[i] = 0.0;
}

double Bsdf::lobePdf(uint32_t lobe, const Vec3& wo, const Vec3& wi, const SpecularLobes& s) const {
    const Material& m = mMaterial;
    const double cosL = glm::dot(mNormal, wi);
    switch (lobe) {
        case kLobeDiffuse: return cosL > 0.0 ? cosL / kPi : 0.0;
        case kLobePhong: {
            if (!(cosL > 0.0)) return 0.0;
            const double c = std::max(0.0, glm::dot(wi, glm::normalize(phongAxis(wo, mNormal))));
            return (m.shininess + 1.0) / (2.0 * kPi) * std::pow(c, m.shininess);
        }
        case kLobeMirror:
            return m.glossy > 0.0 ? coneAbovePdf(s.reflectDir, mNormal, m.glossy, wi) : 0.0;
        case kLobeRefraction:
            return m.translucent > 0.0 ? coneAbovePdf(s.refractDir, -mNormal, m.translucent, wi)
                                       : 0.0;
        default: return 0.0;
    }
}

double Bsdf::pdf(const Vec3& wo, const Vec3& wi) const {
    const SpecularLobes s = specular(wo);
    double w[4];
    lobeWeights(s, w);
    const double total = w[0] + w[1] + w[2] + w[3];
    if (!(total > 0.0)) return 0.0;
    double p = 0.0;
    for (int i = 0; i < 4; ++i)
        if (w[i] > 0.0) p += w[i] / total * lobePdf(1u << i, wo, wi, s);
    return p;
}

std::optional<BsdfSample> Bsdf::sample(const Vec3& wo, double uLobe, const SubPixel& u) const {
    const Material& m = mMaterial;
    const SpecularLobes s = specular(wo);
    double w[4];
    lobeWeights(s, w);
    const double total = w[0] + w[1] + w[2] + w[3];
    if (!(total > 0.0)) return std::nullopt;
    int i = 0;
    for (double acc = w[0] / total; i < 3 && (uLobe >= acc || w[i] <= 0.0); acc += w[i] / total)
        ++i;
    while (w[i] <= 0.0) --i;  // rounding ran past the last lobe that scatters
    BsdfSample out;
    out.lobe = 1u << i;
    const double chosen = w[i] / total;
    switch (out.lobe) {
        case kLobeDiffuse:  // cosine-weighted about n
            out.wi = aboutAxis(mNormal, std::sqrt(1.0 - u.x), 2.0 * kPi * u.y);
            out.kind = kKindReflection | kKindDiffuse;
            break;
        case kLobePhong:
            out.wi = aboutAxis(glm::normalize(phongAxis(wo, mNormal)),
                               std::pow(u.x, 1.0 / (m.shininess + 1.0)), 2.0 * kPi * u.y);
            out.kind = kKindReflection | kKindGlossy;
            break;
        case kLobeMirror:
            if (!(m.glossy > 0.0)) {
                out.wi = glm::normalize(s.reflectDir);
                out.value = s.reflectWeight;
                out.pdf = chosen;
                out.kind = kKindReflection | kKindSpecular;
                return out;
            }
            out.wi = sampleConeAbove(s.reflectDir, mNormal, m.glossy, u);
            out.kind = kKindReflection | kKindGlossy;
            break;
        default:
            if (!(m.translucent > 0.0)) {
                out.wi = s.refractDir;
                out.value = s.refractWeight;
                out.pdf = chosen;
                out.kind = kKindTransmission | kKindSpecular;
                return out;
            }
            out.wi = sampleConeAbove(s.refractDir, -mNormal, m.translucent, u);
            out.kind = kKindTransmission | kKindGlossy;
            break;
    }
    // A mixture: the density and value of every non-delta lobe at the sampled direction.
    out.value = evaluate(wo, out.wi);
    out.pdf = pdf(wo, out.wi);
    return out;
}

}  // namespace kerf
