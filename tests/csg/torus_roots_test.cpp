// The torus' closed method (csg/primitives/torus_roots.h: convex pieces of the distance form,
// tangents decide, Newton locates) on the hard cases, against long-double references: closed-form
// chords where the geometry gives them, else tests/util/torus_reference.h (the quartic's sign
// changes isolated by its derivatives' roots, refined on the distance form).
#include "csg/primitives/torus_roots.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "csg/tree/solids.h"
#include "util/oracles.h"
#include "util/torus_reference.h"

using namespace kerf;
using namespace kerf::test;

namespace {

/// Every surface boundary of the spans, in order.
std::vector<double> boundaries(const Node& torus, const Ray& ray, double tolerance,
                               double tmin = 0.0) {
    TraceContext ctx;
    ctx.relTolerance = tolerance;
    SpanList spans;
    torus.spans(ray, tmin, kInf, ctx, spans);
    std::vector<double> t;
    for (const Span& s : spans) {
        if (s.in.isSurface()) t.push_back(s.in.t);
        if (s.out.isSurface()) t.push_back(s.out.t);
    }
    return t;
}

/// Checks the boundaries against reference crossings: same count, each within `bound`
/// relative error. Returns the worst relative error.
double checkAgainst(const std::vector<double>& got, const std::vector<LD>& ref, double bound) {
    REQUIRE(got.size() == ref.size());
    double worst = 0.0;
    for (size_t k = 0; k < got.size(); ++k) {
        const double err = double(std::fabs(got[k] - ref[k]) / std::fabs(ref[k]));
        INFO("crossing " << k << " got " << got[k] << " reference " << double(ref[k])
                         << " relative error " << err);
        CHECK(err <= bound);
        worst = std::max(worst, err);
    }
    return worst;
}

/// Crossings of the ray o + t·d (d along x) at height y, depth z with the torus: on that line
/// (|x| − R)²... solved in long double from ρ² = x² + z², (ρ − R)² + y² = r².
std::vector<LD> lineAlongX(LD ox, LD y, LD z, LD R, LD r) {
    std::vector<LD> xs;
    const LD w2 = r * r - y * y;  // (ρ − R)² = w²
    if (w2 < 0) return xs;
    const LD w = std::sqrt(w2);
    std::vector<LD> rhos{R - w, R + w};
    std::vector<LD> out;
    for (LD rho : rhos) {
        const LD x2 = rho * rho - z * z;
        if (rho < 0 || x2 < 0) continue;
        xs.push_back(-std::sqrt(x2));
        xs.push_back(std::sqrt(x2));
    }
    std::sort(xs.begin(), xs.end());
    for (LD x : xs) out.push_back(x - ox);
    return out;
}

/// torusReference made independent of the origin's distance: in units of S = R + r, along
/// the unit direction from 2 before the point nearest the centre (the quartic of a far origin
/// loses everything to cancellation, even in long double), each crossing refined by bisection
/// of the distance form in the smallest window around it where that changes sign; returned as
/// the ray's own t.
TorusReference centredReference(const Vec3& origin, const Vec3& dir, double R, double r) {
    const LD S = LD(R) + r;
    const LV3 o = LV3(origin.x, origin.y, origin.z) / S, d = LV3(dir.x, dir.y, dir.z) / S;
    const LD len = std::sqrt(glm::dot(d, d));
    const LV3 u = d / len;
    const LD before = -glm::dot(o, u) - 2;
    const LV3 start = o + before * u;
    const LD Rn = R / S, rn = r / S;
    TorusReference ref = torusReference(start, u, Rn, rn);
    const auto h = [&](LD a) {
        const LV3 p = start + a * u;
        const LD e = std::sqrt(p.x * p.x + p.z * p.z) - Rn;
        return e * e + p.y * p.y - rn * rn;
    };
    for (LD& a : ref.crossings) {
        // The smallest window around the quartic's root where h changes sign (the window
        // must stay inside the chord: a grazing chord can be narrower than the root's error).
        for (LD w = 1e-17L; w <= 1e-6L; w *= 4)
            if ((h(a - w) <= 0) != (h(a + w) <= 0)) {
                a = bisectLD(h, a - w, a + w);
                break;
            }
        a = (before + a) / len;
    }
    return ref;
}

}  // namespace

TEST_CASE("TorusLine::pieces cut h where it changes convexity") {
    // Along x at y = 0, z = 0.5: h'' = 2 − 2R·a2·ρm²/ρ³ with ρm = 0.5, R = 1, a2 = 1: concave
    // where ρ < ∛0.25, i.e. |x| < √(0.25^(2/3) − 0.25).
    const TorusLine line(Vec3(0.0, 0.0, 0.5), Vec3(1.0, 0.0, 0.0), 1.0, 0.2);
    double cuts[4];
    bool concave[3];
    REQUIRE(line.pieces(-2.0, 2.0, cuts, concave) == 3);
    const double w = std::sqrt(std::pow(0.25, 2.0 / 3.0) - 0.25);
    CHECK(cuts[1] == Approx(-w).epsilon(1e-14));
    CHECK(cuts[2] == Approx(w).epsilon(1e-14));
    CHECK_FALSE(concave[0]);
    CHECK(concave[1]);
    CHECK_FALSE(concave[2]);
    // h'' from finite differences of h has the sign each piece claims.
    for (int k = 0; k < 3; ++k) {
        const double s = 0.5 * (cuts[k] + cuts[k + 1]), e = 1e-4;
        const double second = line.value(s + e) - 2.0 * line.value(s) + line.value(s - e);
        CHECK((second < 0.0) == concave[k]);
    }
    // Through the axis: a kink, convex on both sides.
    const TorusLine axis(Vec3(0.0, 0.1, 0.0), Vec3(1.0, 0.0, 0.0), 1.0, 0.2);
    REQUIRE(axis.pieces(-2.0, 2.0, cuts, concave) == 2);
    CHECK(cuts[1] == 0.0);
    CHECK_FALSE(concave[0]);
    CHECK_FALSE(concave[1]);
}

TEST_CASE("Torus closed method: tangent rays (double roots) against closed-form chords") {
    // R = 2, r = 0.5 (exact). Rays along x over the top of the tube (y = r(1 − δ)), and in
    // the equatorial plane grazing the outer wall (z = (R + r)(1 − δ)) and the inner wall
    // from the hole (z = (R − r)(1 + δ)): chords of half-width ~√(2δ)·r. Where a chord is
    // wider than the tolerance it must be found, to the root's condition (~ε·r/√δ).
    const double R = 2.0, r = 0.5, x0 = -10.0;
    const NodePtr torus = makeTorus(R, r);
    int checked = 0;
    for (const double tolerance : {1e-9, 1e-12}) {
        for (int e = 2; e <= 15; ++e) {
            const double delta = std::pow(10.0, -e);
            struct Case {
                double y, z;
            };
            for (const Case c : {Case{r * (1 - delta), 0.0}, Case{0.0, (R + r) * (1 - delta)},
                                 Case{0.0, (R - r) * (1 + delta)}, Case{-r * (1 - delta), 0.0}}) {
                const Ray ray{Vec3(x0, c.y, c.z), Vec3(1.0, 0.0, 0.0)};
                const std::vector<LD> ref = lineAlongX(x0, c.y, c.z, R, r);
                const std::vector<double> got = boundaries(*torus, ray, tolerance);
                INFO("delta " << delta << " y " << c.y << " z " << c.z << " tolerance "
                              << tolerance);
                // Chords narrower than a few tolerances may be dropped as thin spans.
                bool thin = false;
                for (size_t k = 0; k + 1 < ref.size(); k += 2)
                    thin = thin || ref[k + 1] - ref[k] <= 4 * tolerance * std::fabs(ref[k + 1]);
                if (thin) continue;
                const double bound = 1e-12 + 1e-15 / std::sqrt(delta);
                checkAgainst(got, ref, bound);
                ++checked;
            }
        }
    }
    CHECK(checked > 40);
}

TEST_CASE("Torus closed method: rays just outside a tangency miss") {
    const double R = 2.0, r = 0.5, x0 = -10.0;
    const NodePtr torus = makeTorus(R, r);
    for (int e = 2; e <= 15; ++e) {
        const double delta = std::pow(10.0, -e);
        for (const Vec3 o : {Vec3(x0, r * (1 + delta), 0.0), Vec3(x0, 0.0, (R + r) * (1 + delta)),
                             Vec3(x0, -r * (1 + delta), 0.0)}) {
            INFO("delta " << delta << " origin " << o.y << " " << o.z);
            CHECK(boundaries(*torus, {o, Vec3(1.0, 0.0, 0.0)}, 1e-12).empty());
        }
        // Just inside the inner wall's tangent line: four crossings, the middle two (out of
        // the near tube into the hole and back into the far tube) a near-double pair.
        const Ray hole{Vec3(x0, 0.0, (R - r) * (1 - delta)), Vec3(1.0, 0.0, 0.0)};
        const std::vector<LD> ref = lineAlongX(x0, 0.0, (R - r) * (1 - delta), R, r);
        INFO("inner wall, delta " << delta);
        checkAgainst(boundaries(*torus, hole, 1e-12), ref, 1e-12 + 1e-15 / std::sqrt(delta));
    }
}

TEST_CASE("Torus closed method: rays along and parallel to the axis") {
    const double R = 3.0, r = 1.0;
    const NodePtr torus = makeTorus(R, r);
    // Along the axis, with −0 components: through the hole.
    CHECK(boundaries(*torus, {Vec3(0.0, 10.0, 0.0), Vec3(-0.0, -1.0, -0.0)}, 1e-12).empty());
    CHECK(boundaries(*torus, {Vec3(-0.0, -10.0, 0.0), Vec3(0.0, 3.0, -0.0)}, 1e-12).empty());
    // Parallel to the axis through the tube at ρ = R + a: y = ±√(r² − a²).
    for (const double a : {0.0, 0.5, -0.75, 0.999999}) {
        const LD offset = LD(R + a) - R;  // the ray's own offset, after rounding R + a
        const LD half = std::sqrt(LD(r) * r - offset * offset);
        for (const double dirY : {1.0, 0.25}) {
            const Ray ray{Vec3(R + a, -5.0, 0.0), Vec3(-0.0, dirY, 0.0)};
            const std::vector<LD> ref{(5 - half) / dirY, (5 + half) / dirY};
            INFO("a " << a << " dirY " << dirY);
            checkAgainst(boundaries(*torus, ray, 1e-12), ref, 1e-14);
        }
    }
}

TEST_CASE("Torus closed method: thin and huge tori, far origins, against long double") {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double worst = 0.0;
    int compared = 0, skipped = 0;
    struct Shape {
        double R, r, originDistance;
    };
    for (const Shape shape :
         {Shape{1.0, 1e-6, 5.0}, Shape{1e6, 1.0, 3e6}, Shape{1.0, 1e-3, 1e8},
          Shape{1e200, 3e199, 1e201}, Shape{1e-200, 2e-201, 1e-199}, Shape{1.0, 0.999, 4.0}}) {
        const NodePtr torus = makeTorus(shape.R, shape.r);
        for (int i = 0; i < 400; ++i) {
            // Towards a point near the tube (most rays hit), from far away.
            const double phi = 6.283185307179586 * unit(rng);
            const Vec3 target = Vec3(shape.R * std::cos(phi), 0.0, shape.R * std::sin(phi)) +
                                gaussianUnit(rng) * (shape.r * 1.3 * unit(rng));
            const Vec3 origin = gaussianUnit(rng) * shape.originDistance;
            const Ray ray{origin, target - origin};
            const TorusReference ref = centredReference(origin, ray.dir, shape.R, shape.r);
            const std::vector<double> got = boundaries(*torus, ray, 1e-12);
            INFO("R " << shape.R << " r " << shape.r << " ray " << i);
            if (got.size() != ref.crossings.size() && ref.nearTangent) {
                ++skipped;
                continue;
            }
            worst = std::max(worst, checkAgainst(got, ref.crossings, 1e-12));
            ++compared;
        }
    }
    INFO("worst relative error " << worst);
    CHECK(compared > 2000);
    CHECK(skipped * 100 <= compared);
}
