// The torus: ray spans against a long-double reference (recursive isolation of the quartic by
// its derivatives' roots, then bisection of the distance form), plus the hard cases.
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "csg/tree/solids.h"
#include "util/oracles.h"

using namespace kerf;
using kerf::test::gaussianUnit;

namespace {

using LD = long double;

LD evalPoly(const std::vector<LD>& c, LD t) {
    LD v = 0;
    for (size_t i = c.size(); i-- > 0;) v = v * t + c[i];
    return v;
}

/// Bisection to the last bit of a sign change of f on [a, b].
template <typename F>
LD bisect(F f, LD a, LD b) {
    const bool negA = f(a) < 0;
    for (int i = 0; i < 200; ++i) {
        const LD m = (a + b) / 2;
        if (m <= a || m >= b) break;
        if ((f(m) < 0) == negA)
            a = m;
        else
            b = m;
    }
    return (a + b) / 2;
}

/// All sign changes of the polynomial c (ascending coefficients) in [lo, hi]: the roots of its
/// derivative cut it into monotone pieces, each with at most one. Critical points also go to
/// `critical` (for the tangency test).
std::vector<LD> polyRoots(const std::vector<LD>& c, LD lo, LD hi, std::vector<LD>* critical) {
    std::vector<LD> d;
    for (size_t i = 1; i < c.size(); ++i) d.push_back(c[i] * LD(i));
    std::vector<LD> pts{lo};
    if (d.size() >= 2) {
        for (LD r : polyRoots(d, lo, hi, nullptr)) {
            pts.push_back(r);
            if (critical) critical->push_back(r);
        }
    }
    pts.push_back(hi);
    std::vector<LD> roots;
    auto f = [&](LD t) { return evalPoly(c, t); };
    for (size_t i = 0; i + 1 < pts.size(); ++i)
        if ((f(pts[i]) < 0) != (f(pts[i + 1]) < 0)) roots.push_back(bisect(f, pts[i], pts[i + 1]));
    return roots;
}

struct Reference {
    std::vector<LD> roots;  ///< sign changes for t in (0, tmax)
    bool nearTangent =
        false;  ///< a critical point lies within the reference's uncertainty of the surface
};

Reference referenceRoots(const Ray& ray, double R, double r) {
    const LD ox = ray.origin.x, oy = ray.origin.y, oz = ray.origin.z;
    const LD dx = ray.dir.x, dy = ray.dir.y, dz = ray.dir.z, RR = R, rr = r;
    const LD dd = dx * dx + dy * dy + dz * dz, od = ox * dx + oy * dy + oz * dz,
             oo = ox * ox + oy * oy + oz * oz;
    const LD k = oo + RR * RR - rr * rr;
    const LD A2 = dx * dx + dz * dz, A1 = 2 * (ox * dx + oz * dz), A0 = ox * ox + oz * oz;
    // (dd t² + 2 od t + k)² − 4R²(A2 t² + A1 t + A0)
    const std::vector<LD> c{k * k - 4 * RR * RR * A0, 4 * od * k - 4 * RR * RR * A1,
                            4 * od * od + 2 * dd * k - 4 * RR * RR * A2, 4 * dd * od, dd * dd};
    auto h = [&](LD t) {
        const LD x = ox + t * dx, y = oy + t * dy, z = oz + t * dz;
        const LD e = std::sqrt(x * x + z * z) - RR;
        return e * e + y * y - rr * rr;
    };
    Reference ref;
    std::vector<LD> critical;
    const LD tmax = (std::sqrt(oo) + 2 * (RR + rr)) / std::sqrt(dd);
    for (LD t : polyRoots(c, 0, tmax, &critical)) {
        // Refine on the distance form, better conditioned than the quartic.
        const LD w = 1e-12L * (std::fabs(t) + 1e-300L);
        ref.roots.push_back((h(t - w) < 0) != (h(t + w) < 0) ? bisect(h, t - w, t + w) : t);
    }
    for (LD t : critical) {
        const LD x = ox + t * dx, y = oy + t * dy, z = oz + t * dz;
        const LD dist =
            std::sqrt((std::sqrt(x * x + z * z) - RR) * (std::sqrt(x * x + z * z) - RR) + y * y);
        if (std::fabs(dist - rr) < 1e-8L * (RR + rr)) ref.nearTangent = true;
    }
    return ref;
}

/// Span boundaries in order: in, out, in, out, …
std::vector<Boundary> flatten(const SpanList& s) {
    std::vector<Boundary> b;
    for (const Span& sp : s) {
        b.push_back(sp.in);
        b.push_back(sp.out);
    }
    return b;
}

}  // namespace

TEST_CASE("Torus::spans against a long-double reference") {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    uint64_t rays = 0, skipped = 0;
    TraceContext ctx;
    double worstError = 0.0;
    for (double ratio : {1.01, 1.5, 3.0, 10.0, 100.0, 1000.0}) {
        for (double tolerance : {1e-9, 1e-12}) {
            ctx.relTolerance = tolerance;
            const double r = 0.7, R = ratio * r, S = R + r;
            const NodePtr torus = makeTorus(R, r);
            for (int i = 0; i < 1500; ++i) {
                Ray ray;
                ray.origin = gaussianUnit(rng) * (S * (1.5 + 3.0 * unit(rng)));
                // Aim at a random point of the box, near the tube, or anywhere.
                Vec3 target =
                    Vec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5) * 2.0 * Vec3(S, r, S);
                if (i % 3 == 0) {
                    const double phi = 6.283185307179586 * unit(rng);
                    target = Vec3(R * std::cos(phi), 0.0, R * std::sin(phi)) +
                             gaussianUnit(rng) * (r * 1.2 * unit(rng));
                }
                ray.dir = (target - ray.origin) * (0.1 + 10.0 * unit(rng));
                if (i % 7 == 0) ray.dir[i % 3] = -0.0;  // axis-parallel rays with −0 components
                SpanList spans;
                torus->spans(ray, 0.0, kInf, ctx, spans);
                ++rays;
                const Reference ref = referenceRoots(ray, R, r);
                const std::vector<Boundary> got = flatten(spans);
                INFO("R/r " << ratio << " ray o=(" << ray.origin.x << "," << ray.origin.y << ","
                            << ray.origin.z << ") d=(" << ray.dir.x << "," << ray.dir.y << ","
                            << ray.dir.z << ")");
                if (got.size() != ref.roots.size()) {
                    if (ref.nearTangent) {
                        ++skipped;
                        continue;
                    }
                    FAIL_CHECK("got " << got.size() << " boundaries, reference "
                                      << ref.roots.size());
                    continue;
                }
                for (size_t k = 0; k < got.size(); ++k) {
                    const double err = double(std::fabs(got[k].t - ref.roots[k]) / ref.roots[k]);
                    worstError = std::max(worstError, err);
                    CHECK(err <= tolerance);
                    CHECK(got[k].primitive != 0);
                }
            }
        }
    }
    std::printf("torus: %llu rays, %llu near-tangent skipped, worst relative error %.3g\n",
                static_cast<unsigned long long>(rays), static_cast<unsigned long long>(skipped),
                worstError);
    CHECK(skipped * 100 < rays);
}

TEST_CASE("Torus::spans hard cases") {
    TraceContext ctx;
    const double R = 3.0, r = 1.0;
    const NodePtr torus = makeTorus(R, r);
    SpanList s;
    SECTION("a ray along the y axis passes through the hole") {
        torus->spans({Vec3(0.0, 10.0, 0.0), Vec3(-0.0, -1.0, -0.0)}, 0.0, kInf, ctx, s);
        CHECK(s.empty());
        torus->spans({Vec3(0.0, -10.0, 0.0), Vec3(0.0, 2.0, 0.0)}, -kInf, kInf, ctx, s);
        CHECK(s.empty());
    }
    SECTION("a ray along the x axis through the centre gives two spans at ±(R ± r)") {
        const double x0 = -10.0;
        torus->spans({Vec3(x0, 0.0, 0.0), Vec3(1.0, -0.0, 0.0)}, 0.0, kInf, ctx, s);
        REQUIRE(s.size() == 2);
        CHECK(s[0].in.t + x0 == Approx(-(R + r)).epsilon(1e-15));
        CHECK(s[0].out.t + x0 == Approx(-(R - r)).epsilon(1e-15));
        CHECK(s[1].in.t + x0 == Approx(R - r).epsilon(1e-15));
        CHECK(s[1].out.t + x0 == Approx(R + r).epsilon(1e-15));
        // Outward normals: −x at the far left, +x at the inner wall of the left tube, …
        CHECK(s[0].in.normal.x < 0.0);
        CHECK(s[0].out.normal.x > 0.0);
        CHECK(s[1].in.normal.x < 0.0);
        CHECK(s[1].out.normal.x > 0.0);
    }
    SECTION("a ray starting inside the tube begins with a clip") {
        torus->spans({Vec3(R, 0.0, 0.0), Vec3(0.0, 0.0, 1.0)}, 0.0, kInf, ctx, s);
        REQUIRE(s.size() == 1);
        CHECK(s[0].in.t == 0.0);
        CHECK(s[0].in.primitive == 0);
        // From (R, 0, 0) along z the tube is left where ρ = R + r: t = √((R + r)² − R²).
        CHECK(s[0].out.t == Approx(std::sqrt((R + r) * (R + r) - R * R)).epsilon(1e-15));
        CHECK(s[0].out.primitive != 0);
    }
    SECTION("grazing the top of the tube touches without a span") {
        for (double sign : {1.0, -1.0}) {
            torus->spans({Vec3(-10.0, sign * r, 0.0), Vec3(1.0, 0.0, 0.0)}, 0.0, kInf, ctx, s);
            for (const Span& sp : s) CHECK(sp.out.t - sp.in.t <= 1e-9 * sp.out.t);
        }
    }
    SECTION("just below grazing gives thin spans where the closed form says") {
        const double y = r * (1.0 - 1e-6);
        torus->spans({Vec3(-10.0, y, 0.0), Vec3(1.0, 0.0, 0.0)}, 0.0, kInf, ctx, s);
        REQUIRE(s.size() == 2);
        // On the line z = 0, y fixed: (|x| − R)² = r² − y².
        const double w = std::sqrt(r * r - y * y);
        CHECK(s[0].in.t - 10.0 == Approx(-(R + w)).epsilon(1e-12));
        CHECK(s[0].out.t - 10.0 == Approx(-(R - w)).epsilon(1e-12));
        CHECK(s[1].in.t - 10.0 == Approx(R - w).epsilon(1e-12));
        CHECK(s[1].out.t - 10.0 == Approx(R + w).epsilon(1e-12));
    }
}

TEST_CASE("Torus::value") {
    const NodePtr torus = makeTorus(3.0, 1.0);
    CHECK(torus->value(Vec3(3.0, 0.0, 0.0)) == -1.0);
    CHECK(torus->value(Vec3(0.0, 0.0, 5.0)) == 1.0);
    CHECK(torus->value(Vec3(0.0, 4.0, 0.0)) == Approx(5.0 - 1.0));
    const Interval v =
        torus->valueInterval({Interval(2.9, 3.1), Interval(-0.1, 0.1), Interval(-0.1, 0.1)});
    CHECK(v.lo <= -1.0 + 0.0);
    CHECK(v.hi >= torus->value(Vec3(2.9, 0.1, 0.1)));
    CHECK(v.hi < 0.0);
}

TEST_CASE("Torus::spans performance") {
    // Rays from a camera-like fan at a torus R/r = 4: most hit. Reports steps and time per ray.
    const NodePtr torus = makeTorus(2.0, 0.5);
    TraceContext ctx;
    ctx.relTolerance = 1e-9;
    SpanList s;
    const int n = 400;
    uint64_t hits = 0, offSurface = 0;
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const Vec3 dir(-3.0 + 6.0 * i / n, -2.0 + 4.0 * j / n, 6.0);
            torus->spans({Vec3(0.0, 1.5, -6.0), dir - Vec3(0.0, 1.5, 0.0)}, 0.0, kInf, ctx, s);
            if (s.empty()) continue;
            ++hits;
            // The first hit lies on the surface: the distance form vanishes there.
            const Ray ray{Vec3(0.0, 1.5, -6.0), dir - Vec3(0.0, 1.5, 0.0)};
            if (std::fabs(torus->value(ray.at(s[0].in.t))) > 1e-12) ++offSurface;
        }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double rays = double(n) * n;
    std::printf(
        "torus perf: %.0f ns/ray, %.2f root steps/ray, %.2f interval evals/ray, %.0f%% hit\n",
        1e9 * seconds / rays, ctx.stats.rootSteps / rays, ctx.stats.intervalEvals / rays,
        100.0 * hits / rays);
    CHECK(hits > rays / 10);
    CHECK(offSurface == 0);
}
