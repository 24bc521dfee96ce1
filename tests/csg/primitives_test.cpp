// Sphere, box and half-space spans against closed forms evaluated independently in long double,
// and the implicit forms of every closed-form primitive against their spans and intervals.
#include "csg/tree/solids.h"
#include "util/oracles.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <random>
#include <sstream>
#include <vector>

using namespace kerf;
using namespace kerf::test;

namespace {

/// A span with its normals made unit, in long double for comparing.
struct RefSpan {
    LD tin, tout;
    LVec3 nin, nout;
};

LVec3 unit(const LVec3& v) { return v / std::sqrt(glm::dot(v, v)); }

/// |got − ref|/|ref|; 0 when equal (also for the ±inf ends of unbounded spans).
LD relError(LD got, LD ref) { return got == ref ? 0 : std::fabs(got - ref) / std::fabs(ref); }

/// Distance between the unit normals; 0 at infinite ends, which carry no surface.
LD normalError(LD t, const LVec3& got, const LVec3& ref) {
    return std::isinf(t) ? 0 : glm::length(unit(got) - unit(ref));
}

/// Our spans, zero-width ones dropped (the callers drop them too).
std::vector<RefSpan> ours(const Node& node, const Ray& ray) {
    TraceContext ctx;
    SpanList out;
    node.spans(ray, -kInf, kInf, ctx, out);
    std::vector<RefSpan> r;
    for (const Span& s : out) {
        REQUIRE(s.in.t <= s.out.t);
        if (s.in.t < s.out.t) r.push_back({s.in.t, s.out.t, ld(s.in.normal), ld(s.out.normal)});
    }
    return r;
}

/// Each test case reseeds, so its rays do not depend on which other cases ran.
Random gRnd;

/// A ray from 3–8 sizes away aimed at a random point within 1.3 sizes of `center`, with a
/// direction of random length (transforms do not renormalise): about half of them hit.
Ray randomRay(const Vec3& center, double size) {
    Ray r;
    r.origin = center + size * gRnd.uniform(3.0, 8.0) * gRnd.unitVector();
    const Vec3 target = center + 1.3 * size * gRnd.inBall();
    r.dir = (target - r.origin) * std::exp(gRnd.uniform(-3.0, 3.0));
    return r;
}

/// Compares our spans with a reference; skips rays where the reference itself is
/// ill-conditioned (nudging the origin by 1e-15 of its distance moves a t by more than
/// 1e-13 relative: grazing rays, which have their own tests). Tracks the worst errors.
struct Comparison {
    LD worstT = 0, worstN = 0;
    int compared = 0, hits = 0, skipped = 0;

    void check(const std::function<std::vector<RefSpan>(const Ray&)>& reference, const Node& node,
               const Ray& ray, double size) {
        const std::vector<RefSpan> ref = reference(ray);
        Ray nudged = ray;
        nudged.origin += 1e-15 * glm::length(ray.origin) * gRnd.unitVector();
        nudged.origin += 1e-15 * size * gRnd.unitVector();
        const std::vector<RefSpan> ref2 = reference(nudged);
        bool wellConditioned = ref.size() == ref2.size();
        for (size_t i = 0; wellConditioned && i < ref.size(); ++i)
            wellConditioned = relError(ref2[i].tin, ref[i].tin) <= 1e-13L &&
                              relError(ref2[i].tout, ref[i].tout) <= 1e-13L;
        if (!wellConditioned) {
            ++skipped;
            return;
        }
        const std::vector<RefSpan> got = ours(node, ray);
        CAPTURE(ray.origin.x, ray.origin.y, ray.origin.z, ray.dir.x, ray.dir.y, ray.dir.z);
        REQUIRE(got.size() == ref.size());
        ++compared;
        hits += ref.empty() ? 0 : 1;
        for (size_t i = 0; i < ref.size(); ++i) {
            const LD eIn = relError(got[i].tin, ref[i].tin);
            const LD eOut = relError(got[i].tout, ref[i].tout);
            const LD nIn = normalError(ref[i].tin, got[i].nin, ref[i].nin);
            const LD nOut = normalError(ref[i].tout, got[i].nout, ref[i].nout);
            worstT = std::max({worstT, eIn, eOut});
            worstN = std::max({worstN, nIn, nOut});
            CAPTURE(double(ref[i].tin), double(ref[i].tout), double(got[i].tin),
                    double(got[i].tout));
            REQUIRE(eIn <= 1e-12L);
            REQUIRE(eOut <= 1e-12L);
            REQUIRE(nIn <= 1e-12L);
            REQUIRE(nOut <= 1e-12L);
        }
    }

    /// The worst errors and the counts, for INFO and WARN lines.
    std::string summary(const char* name) const {
        std::ostringstream out;
        out << name << ": worst relative t error " << double(worstT) << ", worst normal error "
            << double(worstN) << ", " << hits << " hits of " << compared << " (" << skipped
            << " grazing skipped)";
        return out.str();
    }
};

/// The sphere from its geometry: the chord through the point of the line nearest the centre.
std::vector<RefSpan> sphereReference(const Vec3& center, double radius, const Ray& ray) {
    const LVec3 f = ld(ray.origin) - ld(center), d = ld(ray.dir);
    const LD a = glm::dot(d, d);
    const LD tc = -glm::dot(f, d) / a;
    const LVec3 l = f + tc * d;
    const LD r = radius, gap = r * r - glm::dot(l, l);
    if (gap <= 0) return {};
    const LD w = std::sqrt(gap / a);
    return {{tc - w, tc + w, l - w * d, l + w * d}};
}

/// The box from its six faces: every face plane the ray crosses inside the face's rectangle.
std::vector<RefSpan> boxReference(const Vec3& lo, const Vec3& hi, const Ray& ray) {
    LD tin = kInf, tout = -kInf;
    LVec3 nin(0), nout(0);
    for (int a = 0; a < 3; ++a) {
        if (ray.dir[a] == 0.0) continue;
        for (int side = 0; side < 2; ++side) {
            const LD plane = side ? hi[a] : lo[a];
            const LD t = (plane - ray.origin[a]) / LD(ray.dir[a]);
            bool onFace = true;
            for (int b = 0; b < 3; ++b) {
                if (b == a) continue;
                const LD p = LD(ray.origin[b]) + t * LD(ray.dir[b]);
                onFace = onFace && p >= lo[b] && p <= hi[b];
            }
            if (!onFace) continue;
            LVec3 n(0);
            n[a] = side ? 1 : -1;
            if (t < tin) {
                tin = t;
                nin = n;
            }
            if (t > tout) {
                tout = t;
                nout = n;
            }
        }
    }
    if (!(tin < tout)) return {};
    return {{tin, tout, nin, nout}};
}

std::vector<RefSpan> halfSpaceReference(const Vec3& n, double offset, const Ray& ray) {
    const LD nd = glm::dot(ld(n), ld(ray.dir));
    const LD g = glm::dot(ld(n), ld(ray.origin)) - offset;
    const LD t = -g / nd;
    if (nd > 0) return {{-kInf, t, LVec3(0), ld(n)}};
    return {{t, kInf, ld(n), LVec3(0)}};
}

/// The slab between the caps of an axis from a to b, as a span with cap normals; false if
/// the ray runs parallel to the caps outside them.
bool capSlab(const LVec3& a, const LVec3& u, LD len, const Ray& ray, RefSpan& slab) {
    const LD fz = glm::dot(ld(ray.origin) - a, u), dz = glm::dot(ld(ray.dir), u);
    slab = {-kInf, kInf, -u, u};
    if (dz == 0) return fz >= 0 && fz <= len;
    const LD t0 = -fz / dz, t1 = (len - fz) / dz;
    if (dz > 0)
        slab = {t0, t1, -u, u};
    else
        slab = {t1, t0, u, -u};
    return true;
}

/// The capped cylinder from its geometry: the chord of the ray's projection across the axis,
/// through the projected point nearest the axis, cut by the slab between the caps.
std::vector<RefSpan> cylinderReference(const Vec3& a, const Vec3& b, double radius,
                                       const Ray& ray) {
    const LVec3 axis = ld(b) - ld(a);
    const LD len = glm::length(axis);
    const LVec3 u = axis / len;
    RefSpan s;
    if (!capSlab(ld(a), u, len, ray, s)) return {};
    const LVec3 f = ld(ray.origin) - ld(a), d = ld(ray.dir);
    const LVec3 fp = f - glm::dot(f, u) * u, dp = d - glm::dot(d, u) * u;
    const LD a2 = glm::dot(dp, dp), r = radius;
    if (a2 == 0) {
        if (glm::dot(fp, fp) > r * r) return {};
    } else {
        const LD tc = -glm::dot(fp, dp) / a2;
        const LVec3 l = fp + tc * dp;
        const LD gap = r * r - glm::dot(l, l);
        if (gap <= 0) return {};
        const LD w = std::sqrt(gap / a2);
        if (tc - w > s.tin) s.tin = tc - w, s.nin = l - w * dp;
        if (tc + w < s.tout) s.tout = tc + w, s.nout = l + w * dp;
    }
    if (!(s.tin < s.tout)) return {};
    return {s};
}

/// The frustum from its geometry: |p⊥|² = (r1 + k·z)² along the ray in long double (the
/// plain discriminant: 11 more bits than the code under test), both nappes, cut by the slab.
std::vector<RefSpan> coneReference(const Vec3& a, const Vec3& b, double r1, double r2,
                                   const Ray& ray) {
    const LVec3 axis = ld(b) - ld(a);
    const LD len = glm::length(axis);
    const LVec3 u = axis / len;
    const LD k = (LD(r2) - r1) / len;
    RefSpan slab;
    if (!capSlab(ld(a), u, len, ray, slab)) return {};
    const LVec3 f = ld(ray.origin) - ld(a), d = ld(ray.dir);
    const LD fz = glm::dot(f, u), dz = glm::dot(d, u);
    const LVec3 fp = f - fz * u, dp = d - dz * u;
    const LD w0 = r1 + k * fz, w1 = k * dz;
    const LD A = glm::dot(dp, dp) - w1 * w1, B = glm::dot(fp, dp) - w0 * w1;
    const LD C = glm::dot(fp, fp) - w0 * w0, disc = B * B - A * C;
    std::vector<std::pair<LD, LD>> inside;  // where the quadric is ≤ 0
    if (A != 0 && disc > 0) {
        const LD q = -(B + std::copysign(std::sqrt(disc), B));
        const LD t0 = std::min(q / A, C / q), t1 = std::max(q / A, C / q);
        if (A > 0)
            inside = {{t0, t1}};
        else
            inside = {{-kInf, t0}, {t1, kInf}};
    } else if (A < 0 || (A == 0 && B == 0 && C <= 0)) {
        inside = {{-kInf, kInf}};
    } else if (A == 0 && B != 0) {
        const LD t = -C / (2 * B);
        inside = {B > 0 ? std::make_pair(LD(-kInf), t) : std::make_pair(t, LD(kInf))};
    }
    const auto sideNormal = [&](LD t) {
        const LVec3 p = fp + t * dp;
        return unit(p) - k * u;
    };
    std::vector<RefSpan> result;
    for (const auto& [lo, hi] : inside) {
        RefSpan s = slab;
        if (lo > s.tin) s.tin = lo, s.nin = sideNormal(lo);
        if (hi < s.tout) s.tout = hi, s.nout = sideNormal(hi);
        if (s.tin < s.tout) result.push_back(s);
    }
    return result;
}

}  // namespace

TEST_CASE("Sphere::spans") {
    gRnd.seed(102947);
    Comparison cmp;
    for (int scene = 0; scene < 40; ++scene) {
        const Vec3 center(gRnd.uniform(-5, 5), gRnd.uniform(-5, 5), gRnd.uniform(-5, 5));
        const double radius = std::exp(gRnd.uniform(-2, 2));
        const NodePtr sphere = makeSphere(center, radius);
        for (int i = 0; i < 500; ++i) {
            const Ray ray = randomRay(center, radius);
            cmp.check([&](const Ray& r) { return sphereReference(center, radius, r); }, *sphere,
                      ray, radius);
        }
    }
    INFO(cmp.summary("sphere"));
    CHECK(cmp.hits > 4000);
    CHECK(cmp.compared - cmp.hits > 4000);
    CHECK(cmp.skipped < 200);
    WARN(cmp.summary("sphere"));
}

TEST_CASE("Box::spans") {
    gRnd.seed(79190);
    Comparison cmp;
    for (int scene = 0; scene < 40; ++scene) {
        const Vec3 lo(gRnd.uniform(-5, 5), gRnd.uniform(-5, 5), gRnd.uniform(-5, 5));
        const Vec3 hi = lo + Vec3(std::exp(gRnd.uniform(-2, 2)), std::exp(gRnd.uniform(-2, 2)),
                                  std::exp(gRnd.uniform(-2, 2)));
        const NodePtr box = makeBox(lo, hi);
        const double size = glm::length(hi - lo) * 0.5;
        for (int i = 0; i < 500; ++i) {
            const Ray ray = randomRay(0.5 * (lo + hi), size);
            cmp.check([&](const Ray& r) { return boxReference(lo, hi, r); }, *box, ray, size);
        }
    }
    INFO(cmp.summary("box"));
    CHECK(cmp.hits > 4000);
    CHECK(cmp.compared - cmp.hits > 4000);
    WARN(cmp.summary("box"));
}

TEST_CASE("Cylinder::spans") {
    gRnd.seed(118785);
    Comparison cmp;
    for (int scene = 0; scene < 60; ++scene) {
        const Vec3 a(gRnd.uniform(-5, 5), gRnd.uniform(-5, 5), gRnd.uniform(-5, 5));
        Vec3 u = gRnd.unitVector();
        if (scene % 3 == 0) u = Vec3(0), u[scene % 9 / 3] = scene % 2 ? 1.0 : -1.0;  // axis-aligned
        const double len = std::exp(gRnd.uniform(-1, 1.5)),
                     radius = std::exp(gRnd.uniform(-1.5, 1));
        const Vec3 b = a + len * u;
        const NodePtr cylinder = makeCylinder(a, b, radius);
        const double size = std::max(0.5 * len, radius);
        for (int i = 0; i < 400; ++i) {
            const Ray ray = randomRay(0.5 * (a + b), size);
            cmp.check([&](const Ray& r) { return cylinderReference(a, b, radius, r); }, *cylinder,
                      ray, size);
        }
    }
    INFO(cmp.summary("cylinder"));
    CHECK(cmp.hits > 6000);
    CHECK(cmp.compared - cmp.hits > 6000);
    CHECK(cmp.skipped < 300);
    WARN(cmp.summary("cylinder"));
}

TEST_CASE("Cone::spans") {
    gRnd.seed(87109);
    Comparison cmp;
    for (int scene = 0; scene < 80; ++scene) {
        const Vec3 a(gRnd.uniform(-5, 5), gRnd.uniform(-5, 5), gRnd.uniform(-5, 5));
        Vec3 u = gRnd.unitVector();
        if (scene % 3 == 0) u = Vec3(0), u[scene % 9 / 3] = scene % 2 ? 1.0 : -1.0;
        const double len = std::exp(gRnd.uniform(-1, 1.5));
        double r1 = std::exp(gRnd.uniform(-1.5, 1)), r2 = std::exp(gRnd.uniform(-1.5, 1));
        if (scene % 4 == 1) r2 = 0;   // apex at b
        if (scene % 4 == 2) r1 = 0;   // apex at a
        if (scene % 8 == 3) r2 = r1;  // a cylinder
        const Vec3 b = a + len * u;
        const NodePtr cone = makeCone(a, b, r1, r2);
        const double size = std::max({0.5 * len, r1, r2});
        for (int i = 0; i < 300; ++i) {
            const Ray ray = randomRay(0.5 * (a + b), size);
            cmp.check([&](const Ray& r) { return coneReference(a, b, r1, r2, r); }, *cone, ray,
                      size);
        }
    }
    INFO(cmp.summary("cone"));
    CHECK(cmp.hits > 6000);
    CHECK(cmp.compared - cmp.hits > 6000);
    CHECK(cmp.skipped < 300);
    WARN(cmp.summary("cone"));
}

TEST_CASE("HalfSpace::spans") {
    gRnd.seed(126704);
    Comparison cmp;
    for (int scene = 0; scene < 40; ++scene) {
        const Vec3 n = gRnd.unitVector() * std::exp(gRnd.uniform(-3, 3));
        const double offset = gRnd.uniform(-5, 5);
        const NodePtr half = makeHalfSpace(n, offset);
        const Vec3 onPlane = n * (offset / glm::dot(n, n));
        for (int i = 0; i < 500; ++i) {
            const Ray ray = randomRay(onPlane, 1.0);
            cmp.check([&](const Ray& r) { return halfSpaceReference(n, offset, r); }, *half, ray,
                      1.0);
        }
    }
    // The compensated dot products make the crossing exact to a few ulps.
    CHECK(cmp.worstT <= 1e-15L);
    WARN(cmp.summary("halfspace"));
}

TEST_CASE("Node::bounds of the closed-form primitives") {
    SECTION("sphere and box") {
        const Bounds3 s = makeSphere(Vec3(1, 2, 3), 0.5)->bounds();
        CHECK(s.lo.x <= 0.5);
        CHECK(s.hi.z >= 3.5);
        CHECK(s.lo.y == Approx(1.5).epsilon(1e-15));
        const Bounds3 b = makeBox(Vec3(-1, 0, 2), Vec3(1, 3, 4))->bounds();
        CHECK(b.lo == Vec3(-1, 0, 2));
        CHECK(b.hi == Vec3(1, 3, 4));
    }
    SECTION("half-space: everything unless the normal is axis-aligned") {
        const Bounds3 floor = makeHalfSpace(Vec3(0, 1, 0), 0)->bounds();
        CHECK(floor.lo == Vec3(-kInf));
        CHECK(floor.hi == Vec3(kInf, 0, kInf));
        const Bounds3 wall = makeHalfSpace(Vec3(0, 0, -2), 1)->bounds();
        CHECK(wall.lo == Vec3(-kInf, -kInf, -0.5));
        CHECK(wall.hi == Vec3(kInf));
        const Bounds3 third = makeHalfSpace(Vec3(3, 0, 0), 1)->bounds();
        CHECK(LD(third.hi.x) * 3 >= 1.0L);  // rounded outward: never cuts the solid
        CHECK(third.hi.x == Approx(1.0 / 3.0).epsilon(1e-15));
        const Bounds3 slanted = makeHalfSpace(Vec3(1, 1, 0), 0)->bounds();
        CHECK(slanted.lo == Vec3(-kInf));
        CHECK(slanted.hi == Vec3(kInf));
    }
}

namespace {

/// Every closed-form primitive, for the tests of their implicit forms.
std::vector<std::pair<const char*, NodePtr>> closedFormSolids() {
    return {{"sphere", makeSphere(Vec3(0.3, -0.2, 0.1), 1.1)},
            {"box", makeBox(Vec3(-1, -0.5, -0.25), Vec3(0.5, 1, 0.75))},
            {"cylinder", makeCylinder(Vec3(-0.5, -0.7, 0.2), Vec3(0.6, 0.8, -0.1), 0.6)},
            {"cylinder y", makeCylinder(Vec3(0, -1, 0), Vec3(0, 1, 0), 0.8)},
            {"cone", makeCone(Vec3(0.5, -0.7, 0.2), Vec3(-0.6, 0.8, -0.1), 0.9, 0.3)},
            {"cone apex", makeCone(Vec3(0, -1, 0), Vec3(0.2, 1, 0.1), 1.0, 0.0)},
            {"cone r1 = r2", makeCone(Vec3(0, 0, -1), Vec3(0, 0, 1), 0.7, 0.7)},
            {"halfspace", makeHalfSpace(Vec3(0.3, -1.2, 0.5), 0.2)}};
}

}  // namespace

TEST_CASE("Node::value agrees with the spans") {
    gRnd.seed(261327);
    for (const auto& [name, solid] : closedFormSolids()) {
        INFO(name);
        int inside = 0, outside = 0;
        for (int i = 0; i < 2000; ++i) {
            const Ray ray = randomRay(Vec3(0), 1.0);
            const std::vector<RefSpan> s = ours(*solid, ray);
            // Inside every span's middle third; outside beyond its ends (the solids are
            // convex, so nothing else of the line is inside).
            for (const RefSpan& span : s) {
                const double tin = double(span.tin), tout = double(span.tout);
                // Half-spaces: probe a unit either side of the finite end.
                const double w = std::isinf(tin) || std::isinf(tout) ? 1.0 : tout - tin;
                const double from = std::isinf(tin) ? tout - 2.0 : tin;
                for (double f : {1.0 / 3, 0.5, 2.0 / 3}) {
                    CHECK(solid->value(ray.at(from + f * w)) <= 0.0);
                    ++inside;
                }
                if (std::isfinite(tin)) {
                    CHECK(solid->value(ray.at(tin - 0.01 * w - 0.01)) > 0.0);
                    ++outside;
                }
                if (std::isfinite(tout)) {
                    CHECK(solid->value(ray.at(tout + 0.01 * w + 0.01)) > 0.0);
                    ++outside;
                }
            }
            if (s.empty()) {
                for (double t : {-1.0, 0.5, 1.0, 2.0}) CHECK(solid->value(ray.at(t)) > 0.0);
                outside += 4;
            }
        }
        CHECK(inside > 500);
        CHECK(outside > 500);
    }
}

TEST_CASE("Node::value is Lipschitz-1") {
    gRnd.seed(205894);
    for (const auto& [name, solid] : closedFormSolids()) {
        INFO(name);
        double worst = 0;
        for (int i = 0; i < 5000; ++i) {
            const Vec3 p = 3.0 * gRnd.inBall();
            const Vec3 q = p + std::exp(gRnd.uniform(-8, 0)) * gRnd.unitVector();
            worst =
                std::max(worst, std::fabs(solid->value(p) - solid->value(q)) / glm::length(p - q));
        }
        CHECK(worst <= 1.0 + 1e-9);
        CHECK(worst >= 0.5);  // and not needlessly flat
    }
}

TEST_CASE("Node::valueInterval holds value on random boxes") {
    gRnd.seed(372193);
    for (const auto& [name, solid] : closedFormSolids()) {
        INFO(name);
        int tight = 0;
        for (int i = 0; i < 3000; ++i) {
            const Vec3 c = 2.5 * gRnd.inBall();
            // Widths from 1e-12 to 4, and sometimes exactly 0 on an axis.
            Vec3 w;
            for (int a = 0; a < 3; ++a)
                w[a] = gRnd.uniform(0, 1) < 0.1 ? 0.0 : std::exp(gRnd.uniform(-28, 1.4));
            const IntervalVec3 box{
                {c.x - w.x, c.x + w.x}, {c.y - w.y, c.y + w.y}, {c.z - w.z, c.z + w.z}};
            const Interval v = solid->valueInterval(box);
            REQUIRE(v.lo <= v.hi);
            for (int k = 0; k < 20; ++k) {
                Vec3 p;
                for (int a = 0; a < 3; ++a) {
                    const Interval& iv = a == 0 ? box.x : a == 1 ? box.y : box.z;
                    // Corners and faces as well as the interior.
                    const double u = k < 8 ? double((k >> a) & 1) : gRnd.uniform(0, 1);
                    p[a] = std::min(iv.hi, iv.lo + u * (iv.hi - iv.lo));
                }
                const double f = solid->value(p);
                CAPTURE(p.x, p.y, p.z, f, v.lo, v.hi);
                REQUIRE(v.contains(f));
            }
            if (glm::length(w) < 1e-6 && v.width() <= 1e-5) ++tight;
        }
        CHECK(tight > 0);  // small boxes give small intervals
    }
}

TEST_CASE("Primitive::spans counts primitive tests") {
    for (const auto& [name, solid] : closedFormSolids()) {
        INFO(name);
        TraceContext ctx;
        SpanList out;
        out.push_back({});  // stale content must be cleared
        solid->spans(Ray{Vec3(100, 100, 100), Vec3(1, 0, 0)}, 0, kInf, ctx, out);
        solid->spans(Ray{Vec3(0, 0, -10), Vec3(0, 0, 1)}, 0, kInf, ctx, out);
        CHECK(ctx.stats.primitiveTests == 2);
        REQUIRE(out.size() == 1);  // every solid above holds the origin
        CHECK(out[0].in.t < 10.0);
        CHECK(out[0].out.t > 10.0);
        CHECK(solid->primitiveCount() == 1);
        CHECK(solid->depth() == 1);
    }
}
