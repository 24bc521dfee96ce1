/// @file tests/util/sampled_reference.h
/// @brief A brute-force long-double reference for any solid: the sign of Node::valueExtended
/// sampled densely along the ray, each sign change refined by bisection to a few long-double
/// ulps. It cannot see a crossing pair closer than one sample step: such features are reported
/// as unresolved, which is the reference's own uncertainty.
#pragma once

#include "util/oracles.h"

#include <vector>

namespace kerf::test {

struct SampledReference {
    std::vector<LD> crossings;  ///< sign changes of valueExtended in (t0, t1), refined
    bool startsInside = false;  ///< valueExtended(o + t0·d) ≤ 0
    LD step = 0;                ///< the sampling step: features thinner than this are unresolved
    bool firstHit(LD& t) const {
        if (crossings.empty()) return false;
        t = crossings.front();
        return true;
    }
};

/// f along the ray in long double (the ray's double values taken exactly).
inline LD valueAlong(const Node& node, const Ray& ray, LD t) {
    return node.valueExtended(ld(ray.origin) + t * ld(ray.dir));
}

/// Bisection of a sign change of f on [a, b] to the last long-double bit.
template <class F>
LD bisectLD(F f, LD a, LD b) {
    const bool negA = f(a) <= 0;
    for (int i = 0; i < 200; ++i) {
        const LD m = a + (b - a) / 2;
        if (m <= a || m >= b) break;
        if ((f(m) <= 0) == negA)
            a = m;
        else
            b = m;
    }
    return a + (b - a) / 2;
}

/// The sign changes of node.valueExtended along the ray on [t0, t1], from `samples` samples.
inline SampledReference sampledReference(const Node& node, const Ray& ray, LD t0, LD t1,
                                         int samples) {
    SampledReference r;
    r.step = (t1 - t0) / samples;
    auto f = [&](LD t) { return valueAlong(node, ray, t); };
    LD prevT = t0;
    bool prevIn = f(t0) <= 0;
    r.startsInside = prevIn;
    for (int k = 1; k <= samples; ++k) {
        const LD t = k == samples ? t1 : t0 + (t1 - t0) * LD(k) / samples;
        const bool in = f(t) <= 0;
        if (in != prevIn) r.crossings.push_back(bisectLD(f, prevT, t));
        prevT = t;
        prevIn = in;
    }
    return r;
}

/// The ray's parameter range inside the node's bounds, widened by a relative 1e-9 so that
/// faces on the bounds are bracketed; false if the ray misses the bounds.
inline bool boundsRange(const Node& node, const Ray& ray, LD& t0, LD& t1) {
    double a = 0.0, b = kInf;
    if (!node.bounds().clipRay(ray, a, b)) return false;
    const LD pad = 1e-9L * (std::fabs(LD(a)) + std::fabs(LD(b)));
    t0 = std::max<LD>(0, a - pad);
    t1 = b + pad;
    return true;
}

}  // namespace kerf::test
