// Tapes near a lattice point and bracketed root finding for mesh vertices.
#include "volume/octree/surface_search.h"

#include <algorithm>
#include <cmath>

namespace kerf {

namespace {

bool inside(double f) { return f <= 0.0; }

}  // namespace

const Tape& tapeNear(const SampledField& field, const Vec3& index) {
    // The cell's lowest corner; the candidate blocks hold it or its +1 neighbour per axis.
    const std::array<int64_t, 3> c{int64_t(std::floor(index.x)), int64_t(std::floor(index.y)),
                                   int64_t(std::floor(index.z))};
    for (int k = 0; k < 8; ++k) {
        BoundaryBlock key;
        for (int a = 0; a < 3; ++a) {
            const int64_t i = c[a] + ((k >> a) & 1);
            key.block[a] = int32_t(i >= 0 ? i / kMeshBlock : -((-i + kMeshBlock - 1) / kMeshBlock));
        }
        const auto it = std::lower_bound(
            field.boundary.begin(), field.boundary.end(), key,
            [](const BoundaryBlock& a, const BoundaryBlock& b) { return a.block < b.block; });
        if (it == field.boundary.end() || it->block != key.block) continue;
        // The block's tape holds over its points widened by kMeshTapeMargin (3): cells from
        // c − 2 to c + 3 fit whenever c or c + 1 is one of its own points.
        return *it->tape;
    }
    return *field.tape;
}

double refineCrossing(const Tape& tape, const Vec3& from, const Vec3& dir, double ta, double fa,
                      double tb, double fb, double tolerance) {
    int side = 0;  // which end was kept last (Illinois halves the other end's value)
    for (int iter = 0; iter < 100 && std::fabs(tb - ta) > tolerance; ++iter) {
        double t = (ta * fb - tb * fa) / (fb - fa);
        if (!(t > std::min(ta, tb) && t < std::max(ta, tb))) t = 0.5 * (ta + tb);
        const double f = tape.eval(from + t * dir);
        if (inside(f) == inside(fa)) {
            ta = t;
            fa = f;
            if (side == -1) fb *= 0.5;
            side = -1;
        } else {
            tb = t;
            fb = f;
            if (side == 1) fa *= 0.5;
            side = 1;
        }
    }
    return std::fabs(fa) <= std::fabs(fb) ? ta : tb;
}

bool rootAlongGradient(const Tape& tape, const Vec3& p, double reach, double tolerance,
                       Vec3& surface) {
    Vec3 g;
    const double f0 = tape.evalGradient(p, g);
    if (f0 == 0.0) {
        surface = p;
        return true;
    }
    const double len = glm::length(g);
    if (!std::isfinite(f0) || !(len > 0.0) || !std::isfinite(len)) return false;
    // Move against the gradient where outside (f falls), along it where inside.
    const Vec3 dir = (f0 > 0.0 ? -1.0 : 1.0) * (g / len);
    const double newton = std::fabs(f0) / len;
    double steps[4] = {std::min(1.25 * newton, reach), 0.25 * reach, 0.5 * reach, reach};
    std::sort(steps, steps + 4);
    double ta = 0.0, fa = f0;
    for (const double t : steps) {
        if (!(t > ta)) continue;
        const double f = tape.eval(p + t * dir);
        if (inside(f) != inside(f0)) {
            surface = p + refineCrossing(tape, p, dir, ta, fa, t, f, tolerance) * dir;
            return true;
        }
        ta = t;
        fa = f;
    }
    return false;
}

double surfaceDistance(const Tape& tape, const Vec3& q, double reach, double tolerance,
                       bool& firstOrder) {
    Vec3 g;
    const double fq = tape.evalGradient(q, g);
    const double estimate = std::fabs(fq) / glm::length(g);
    firstOrder = false;
    if (fq == 0.0) return 0.0;
    double best = HUGE_VAL;
    Vec3 c = q;
    double fc = fq;
    for (int iter = 0; iter < 4; ++iter) {
        Vec3 s;
        if (rootAlongGradient(tape, c, reach, tolerance, s))
            best = std::min(best, glm::length(s - q));
        if (best <= 1.5 * estimate || iter == 3) break;
        const double g2 = glm::dot(g, g);
        if (!(g2 > 0.0) || !std::isfinite(fc)) break;
        c -= (fc / g2) * g;  // a Newton step toward f = 0
        if (!(glm::length(c - q) <= reach)) break;
        fc = tape.evalGradient(c, g);
        if (fc == 0.0) {
            best = std::min(best, glm::length(c - q));
            break;
        }
    }
    if (!(best <= 1.5 * estimate)) {
        // Near a crease neither gradient may point at the nearest surface: march along the 26
        // directions of a cube's faces, edges and corners, up to the best distance so far.
        const double range = std::min(best, reach);
        const bool in0 = inside(fq);
        for (int d = 0; d < 27; ++d) {
            if (d == 13) continue;  // (0, 0, 0)
            const Vec3 dir = glm::normalize(Vec3(d % 3 - 1, (d / 3) % 3 - 1, d / 9 - 1));
            double ta = 0.0, fa = fq;
            for (int k = 1; k <= 8; ++k) {
                const double t = range * k / 8.0;
                if (t >= best) break;
                const double f = tape.eval(q + t * dir);
                if (inside(f) != in0) {
                    best = std::min(best, refineCrossing(tape, q, dir, ta, fa, t, f, tolerance));
                    break;
                }
                ta = t;
                fa = f;
            }
        }
    }
    if (best < HUGE_VAL) return best;
    firstOrder = true;
    return std::isfinite(estimate) ? estimate : HUGE_VAL;
}

}  // namespace kerf
