/// @file tests/util/torus_reference.h
/// @brief Where a ray crosses the torus (√(x² + z²) − R)² + y² = r² (around y, at the origin),
/// in long double: the quartic's sign changes isolated by its derivatives' roots (each piece
/// between critical points is monotone), each refined by bisection on the distance form. Also
/// says whether a critical point lies within the reference's own doubt of the surface
/// (a tangency, where hit or miss is not decidable here).
#pragma once

#include "util/sampled_reference.h"

#include <vector>

namespace kerf::test {

inline LD evalPolyLD(const std::vector<LD>& c, LD t) {
    LD v = 0;
    for (size_t i = c.size(); i-- > 0;) v = v * t + c[i];
    return v;
}

/// Sign changes of the polynomial c (ascending coefficients) on [lo, hi]; critical points
/// are appended to `critical` when given.
inline std::vector<LD> polyRootsLD(const std::vector<LD>& c, LD lo, LD hi,
                                   std::vector<LD>* critical) {
    std::vector<LD> d;
    for (size_t i = 1; i < c.size(); ++i) d.push_back(c[i] * LD(i));
    std::vector<LD> pts{lo};
    if (d.size() >= 2)
        for (LD r : polyRootsLD(d, lo, hi, nullptr)) {
            pts.push_back(r);
            if (critical) critical->push_back(r);
        }
    pts.push_back(hi);
    std::vector<LD> roots;
    auto f = [&](LD t) { return evalPolyLD(c, t); };
    for (size_t i = 0; i + 1 < pts.size(); ++i)
        if ((f(pts[i]) <= 0) != (f(pts[i + 1]) <= 0))
            roots.push_back(bisectLD(f, pts[i], pts[i + 1]));
    return roots;
}

struct TorusReference {
    std::vector<LD> crossings;  ///< for t in (0, tmax), ascending
    bool nearTangent = false;
};

/// The torus crossings of the local ray o + t·d (given in long double).
inline TorusReference torusReference(const LV3& o, const LV3& d, LD R, LD r) {
    const LD dd = glm::dot(d, d), od = glm::dot(o, d), oo = glm::dot(o, o);
    const LD k = oo + R * R - r * r;
    const LD A2 = d.x * d.x + d.z * d.z, A1 = 2 * (o.x * d.x + o.z * d.z),
             A0 = o.x * o.x + o.z * o.z;
    const std::vector<LD> c{k * k - 4 * R * R * A0, 4 * od * k - 4 * R * R * A1,
                            4 * od * od + 2 * dd * k - 4 * R * R * A2, 4 * dd * od, dd * dd};
    auto h = [&](LD t) {
        const LV3 p = o + t * d;
        const LD e = std::sqrt(p.x * p.x + p.z * p.z) - R;
        return e * e + p.y * p.y - r * r;
    };
    TorusReference ref;
    std::vector<LD> critical;
    const LD tmax = (std::sqrt(oo) + 2 * (R + r)) / std::sqrt(dd);
    for (LD t : polyRootsLD(c, 0, tmax, &critical)) {
        const LD w = 1e-12L * (std::fabs(t) + 1e-300L);
        ref.crossings.push_back((h(t - w) <= 0) != (h(t + w) <= 0) ? bisectLD(h, t - w, t + w) : t);
    }
    for (LD t : critical) {
        const LV3 p = o + t * d;
        const LD e = std::sqrt(p.x * p.x + p.z * p.z) - R;
        if (std::fabs(std::sqrt(e * e + p.y * p.y) - r) < 1e-8L * r) ref.nearTangent = true;
    }
    return ref;
}

}  // namespace kerf::test
