/// @file render/medium.cpp
/// @brief Majorant pieces and transmittance estimators (see medium.h).
#include "render/medium.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace kerf {
namespace {

/// An interval holding every point of the segment ray(t0)–ray(t1): the hull of the two
/// computed ends, widened by one ulp so their rounding cannot leave a true point outside.
void segmentBox(const Ray& ray, double t0, double t1, Interval box[3]) {
    const Vec3 a = ray.at(t0), b = ray.at(t1);
    for (int k = 0; k < 3; ++k)
        box[k] = Interval(std::nextafter(std::min(a[k], b[k]), -kInf),
                          std::nextafter(std::max(a[k], b[k]), kInf));
}

}  // namespace

MediumPath::MediumPath(const Medium& medium, const Ray& ray, double tmin, double tmax) {
    if (!medium.enabled()) return;
    double a = std::max(tmin, 0.0), b = tmax;
    if (!medium.bounds.clipRay(ray, a, b) || !(a < b) || !std::isfinite(b)) return;
    split(medium, ray, a, b, 0);
}

void MediumPath::split(const Medium& medium, const Ray& ray, double t0, double t1, int level) {
    Interval box[3];
    segmentBox(ray, t0, t1, box);
    const Interval r = medium.density->range(box[0], box[1], box[2]);
    ++mRangeCalls;
    // A NaN or unbounded range proves nothing: the piece cannot be tracked (its density is
    // read as 0 there, as negative density is). The language refuses such fields.
    const double hi = r.hi, lo = r.lo;
    if (!(hi > 0.0) || !std::isfinite(hi)) return;  // proved empty (or unusable): skipped
    const double majorant = medium.extinction * hi;
    const double control = medium.extinction * std::max(lo, 0.0);
    const double len = t1 - t0;
    if ((majorant - control) * len > kMaxResidualDepth && level < kMaxPieceLevels &&
        mCount + 2 <= kMaxPieces) {
        const double mid = 0.5 * (t0 + t1);
        split(medium, ray, t0, mid, level + 1);
        split(medium, ray, mid, t1, level + 1);
        return;
    }
    if (mCount < kMaxPieces) {
        mPieces[mCount++] = {t0, t1, control, majorant};
    } else {  // out of room (only after splits): widen the last piece to cover this one
        MediumPiece& last = mPieces[mCount - 1];
        last.t1 = t1;
        last.control = std::min(last.control, control);
        last.majorant = std::max(last.majorant, majorant);
    }
}

double MediumPath::majorantDepth() const {
    double tau = 0.0;
    for (int i = 0; i < mCount; ++i) tau += mPieces[i].majorant * (mPieces[i].t1 - mPieces[i].t0);
    return tau;
}

double extinctionAt(const Medium& medium, const Vec3& p) {
    if (!medium.bounds.contains(p)) return 0.0;
    const double d = medium.density->value(p);
    return d > 0.0 ? medium.extinction * d : 0.0;  // false for NaN too
}

double ratioTracking(const Medium& medium, const Ray& ray, const MediumPath& path, double tEnd,
                     MediumRandom& rng) {
    double T = 1.0;
    for (int i = 0; i < path.size() && T > 0.0; ++i) {
        const MediumPiece& p = path[i];
        if (p.t0 >= tEnd) break;
        const double end = std::min(p.t1, tEnd);
        T *= std::exp(-p.control * (end - p.t0));
        if (T < kRouletteThreshold) {
            if (rng.next() * kRouletteThreshold >= T) return 0.0;
            T = kRouletteThreshold;
        }
        if (!(p.majorant > p.control)) continue;  // a constant piece: exact
        // Any residual majorant above σt − σc is valid; one that gives at least
        // kMinRatioSteps points per piece trades a few lookups for much less variance.
        const double residual = std::max(p.majorant - p.control, kMinRatioSteps / (end - p.t0));
        for (double t = p.t0;;) {
            t -= std::log1p(-rng.next()) / residual;
            if (!(t < end)) break;
            const double sigma = std::clamp(extinctionAt(medium, ray.at(t)), p.control, p.majorant);
            T *= 1.0 - (sigma - p.control) / residual;
            if (!(T > 0.0)) return 0.0;
            // Russian roulette: an estimate this small goes on with probability T/threshold
            // as the threshold itself, so the mean stays T and thick media stop early.
            if (T < kRouletteThreshold) {
                if (rng.next() * kRouletteThreshold >= T) return 0.0;
                T = kRouletteThreshold;
            }
        }
    }
    return T;
}

double deltaTracking(const Medium& medium, const Ray& ray, const MediumPath& path, double tEnd,
                     MediumRandom& rng) {
    for (int i = 0; i < path.size(); ++i) {
        const MediumPiece& p = path[i];
        if (p.t0 >= tEnd) break;
        const double end = std::min(p.t1, tEnd);
        if (!(p.majorant > 0.0)) continue;
        for (double t = p.t0;;) {
            t -= std::log1p(-rng.next()) / p.majorant;
            if (!(t < end)) break;
            if (rng.next() * p.majorant < extinctionAt(medium, ray.at(t))) return 0.0;
        }
    }
    return 1.0;
}

double marchStep(const Medium& medium) {
    return medium.step > 0.0 ? medium.step : glm::length(medium.bounds.extent()) / 128.0;
}

double marchTransmittance(const Medium& medium, const Ray& ray, const MediumPath& path, double tEnd,
                          double step, double* tauError) {
    double tau = 0.0, err = 0.0;
    for (int i = 0; i < path.size(); ++i) {
        const MediumPiece& p = path[i];
        if (p.t0 >= tEnd) break;
        const double end = std::min(p.t1, tEnd);
        const double len = end - p.t0;
        const int n = std::max(1, int(std::ceil(len / step)));
        const double h = len / n;
        for (int k = 0; k < n; ++k) {
            const double a = p.t0 + k * h;
            tau += extinctionAt(medium, ray.at(a + 0.5 * h)) * h;
            if (tau > kMarchOpaqueDepth && !tauError) return 0.0;
            if (tauError) {
                // The step's true depth and its midpoint estimate both lie in [lo, hi]·h.
                Interval box[3];
                segmentBox(ray, a, a + h, box);
                const Interval r = medium.density->range(box[0], box[1], box[2]);
                err += medium.extinction * (std::max(r.hi, 0.0) - std::max(r.lo, 0.0)) * h;
            }
        }
    }
    if (tauError) *tauError = err;
    return std::exp(-tau);
}

double mediumTransmittance(const Medium& medium, const Ray& ray, double tmax, MediumRandom& rng) {
    const MediumPath path(medium, ray, 0.0, tmax);
    if (path.empty()) return 1.0;
    switch (medium.method) {
        case MediumMethod::Ratio: return ratioTracking(medium, ray, path, tmax, rng);
        case MediumMethod::Delta: return deltaTracking(medium, ray, path, tmax, rng);
        case MediumMethod::March:
            return marchTransmittance(medium, ray, path, tmax, marchStep(medium));
    }
    return 1.0;
}

bool sampleMajorantDistance(const MediumPath& path, double u, double& t, double& pdf) {
    const double total = path.majorantDepth();
    if (!(total > 0.0)) return false;
    const double mass = -std::expm1(-total);  // P(a majorant collision within the path)
    double target = -std::log1p(-u * mass);   // the optical depth of the collision
    double before = 0.0;
    for (int i = 0; i < path.size(); ++i) {
        const MediumPiece& p = path[i];
        const double depth = p.majorant * (p.t1 - p.t0);
        if (target < depth || i + 1 == path.size()) {
            const double d = std::min(target, depth);
            t = std::min(p.t0 + d / p.majorant, p.t1);
            pdf = p.majorant * std::exp(-(before + d)) / mass;
            return p.majorant > 0.0;
        }
        target -= depth;
        before += depth;
    }
    return false;
}

double henyeyGreenstein(double cosTheta, double g) {
    const double denom = 1.0 + g * g - 2.0 * g * cosTheta;
    return (1.0 - g * g) / (4.0 * glm::pi<double>() * denom * std::sqrt(denom));
}

}  // namespace kerf
