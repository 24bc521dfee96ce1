// The BVH (binned SAH, float nodes) and the conservative box test with a precomputed
// reciprocal direction, against a brute-force slab test in long double: every box the exact
// segment meets must be reported, with an entry no later than the exact one, over random boxes
// and rays at every scale (float-overflowing and float-underflowing coordinates), with ±0 and
// subnormal direction components, and ranges that start below 0.
#include <catch2/catch.hpp>

#include "csg/bvh/bvh.h"

#include <cfloat>
#include <cmath>
#include <random>
#include <sstream>
#include <vector>

using namespace kerf;

namespace {

using LD = long double;

/// Whether o + t·d, tmin ≤ t ≤ tmax, meets the box, in long double (exact enough: its
/// rounding is 2^-64 against the test's 2^-50 margins); `enter` is the first such t.
bool meetsExactly(const Bounds3& b, const Ray& ray, double tmin, double tmax, LD& enter) {
    LD t0 = tmin, t1 = tmax;
    for (int a = 0; a < 3; ++a) {
        const LD o = ray.origin[a], d = ray.dir[a];
        if (d == 0) {
            if (o < b.lo[a] || o > b.hi[a]) return false;
            continue;
        }
        LD s0 = (LD(b.lo[a]) - o) / d, s1 = (LD(b.hi[a]) - o) / d;
        if (s0 > s1) std::swap(s0, s1);
        t0 = std::max(t0, s0);
        t1 = std::min(t1, s1);
    }
    enter = t0;
    // A meeting beyond the double range has no double parameter: no hit can be there.
    return t0 <= t1 && t0 <= LD(DBL_MAX);
}

/// Random numbers at a chosen spread of scales, and the special values rays must survive.
class Sampler {
public:
    explicit Sampler(uint64_t seed) : mRng(seed) {}

    /// ±m·2^e with e uniform in [eLo, eHi].
    double scaled(int eLo, int eHi) {
        const double m = std::uniform_real_distribution<double>(1.0, 2.0)(mRng);
        const int e = std::uniform_int_distribution<int>(eLo, eHi)(mRng);
        return (coin() ? -1.0 : 1.0) * std::ldexp(m, e);
    }
    /// A coordinate for the scale: mostly ordinary, sometimes 0.
    double coordinate(int eLo, int eHi) { return pick(10) == 0 ? 0.0 : scaled(eLo, eHi); }
    /// A direction component: ordinary, +0, −0, or subnormal.
    double direction() {
        switch (pick(8)) {
            case 0: return 0.0;
            case 1: return -0.0;
            case 2: return (coin() ? -1.0 : 1.0) * std::ldexp(1.5, -1060);  // subnormal
            default: return scaled(-3, 3);
        }
    }
    bool coin() { return pick(2) == 0; }
    int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(mRng); }

private:
    std::mt19937_64 mRng;
};

struct Scale {
    const char* name;
    int eLo, eHi;  ///< binary exponents of the coordinates
};

// Ordinary, tiny (below float's normal range: floats round to 0 or the smallest subnormals),
// huge (beyond float: boxes become unbounded in float) and mixed.
const Scale kScales[] = {
    {"ordinary", -4, 4}, {"tiny", -1000, -140}, {"huge", 130, 1000}, {"mixed", -300, 300}};

Bounds3 randomBox(Sampler& s, const Scale& sc) {
    Bounds3 b;
    for (int a = 0; a < 3; ++a) {
        double x = s.coordinate(sc.eLo, sc.eHi), y = s.coordinate(sc.eLo, sc.eHi);
        if (s.pick(4) == 0) y = x;  // flat boxes: a face the ray may just touch
        b.lo[a] = std::min(x, y);
        b.hi[a] = std::max(x, y);
    }
    if (s.pick(40) == 0) b.hi[s.pick(3)] = kInf;  // unbounded: kept out of the tree
    return b;
}

Ray randomRay(Sampler& s, const Scale& sc, const std::vector<Bounds3>& boxes) {
    Ray r;
    for (int a = 0; a < 3; ++a) r.dir[a] = s.direction();
    if (r.dir == Vec3(0.0)) r.dir.x = 1.0;
    // Often aim at a box corner or its centre, so that hits, edges and faces are common.
    const Bounds3& target = boxes[s.pick(int(boxes.size()))];
    for (int a = 0; a < 3; ++a) r.origin[a] = s.coordinate(sc.eLo, sc.eHi);
    if (s.pick(3) != 0 && target.finite()) {
        const Vec3 p = s.coin() ? target.center() : (s.coin() ? target.lo : target.hi);
        for (int a = 0; a < 3; ++a)
            if (r.dir[a] == 0.0 && s.coin()) r.origin[a] = p[a];  // in the slab's plane
        if (s.coin()) {
            // Back off from p along d, so the ray passes through p at t ≈ 1.
            const Vec3 o = p - r.dir;
            if (std::isfinite(o.x) && std::isfinite(o.y) && std::isfinite(o.z)) r.origin = o;
        }
    }
    return r;
}

void ranges(Sampler& s, double& tmin, double& tmax) {
    switch (s.pick(4)) {
        case 0: tmin = 0.0, tmax = kInf; break;
        case 1: tmin = -kInf, tmax = kInf; break;
        case 2: tmin = -std::fabs(s.scaled(-10, 10)), tmax = std::fabs(s.scaled(-10, 10)); break;
        default:
            tmin = std::fabs(s.scaled(-20, 20)), tmax = tmin * (1.0 + std::fabs(s.scaled(-8, 8)));
            break;
    }
}

std::string describe(const Ray& r, double tmin, double tmax, const Bounds3& b) {
    std::ostringstream os;
    os.precision(17);
    os << "ray o=(" << r.origin.x << ", " << r.origin.y << ", " << r.origin.z << ") d=(" << r.dir.x
       << ", " << r.dir.y << ", " << r.dir.z << ") t in [" << tmin << ", " << tmax << "], box ("
       << b.lo.x << ", " << b.lo.y << ", " << b.lo.z << ")-(" << b.hi.x << ", " << b.hi.y << ", "
       << b.hi.z << ")";
    return os.str();
}

}  // namespace

TEST_CASE("Bvh::traverse reports every box the exact segment meets, at every scale") {
    const Bvh::Split split = GENERATE(Bvh::Split::Sah, Bvh::Split::Median);
    for (const Scale& sc : kScales) {
        Sampler s(0x5eed0000u + uint64_t(sc.eLo + 2000));
        int exactHits = 0, reported = 0, rays = 0, lost = 0, lateEntries = 0;
        std::string firstLost;
        for (int scene = 0; scene < 40; ++scene) {
            std::vector<Bounds3> boxes(1 + s.pick(200));
            for (Bounds3& b : boxes) b = randomBox(s, sc);
            const Bvh bvh(boxes, split);
            CHECK(bvh.itemCount() == int(boxes.size()));
            for (int k = 0; k < 250; ++k) {
                const Ray ray = randomRay(s, sc, boxes);
                double tmin, tmax;
                ranges(s, tmin, tmax);
                std::vector<char> seen(boxes.size(), 0);
                std::vector<double> entry(boxes.size(), kInf);
                TraceStats stats;
                bvh.traverse(ray, tmin, tmax, stats, [&](int i, double tEnter) {
                    seen[size_t(i)] = 1;
                    entry[size_t(i)] = tEnter;
                    return tmax;
                });
                ++rays;
                for (size_t i = 0; i < boxes.size(); ++i) {
                    LD enter;
                    if (!meetsExactly(boxes[i], ray, tmin, tmax, enter)) continue;
                    ++exactHits;
                    if (!seen[i]) {
                        if (lost++ == 0) firstLost = describe(ray, tmin, tmax, boxes[i]);
                        continue;
                    }
                    if (LD(entry[i]) > enter) ++lateEntries;
                }
                for (char c : seen) reported += c;
            }
        }
        INFO((split == Bvh::Split::Sah ? "SAH, " : "median, ")
             << sc.name << ": " << rays << " rays, " << exactHits << " exact box hits, " << reported
             << " reported; first lost: " << firstLost);
        CHECK(exactHits > 0);
        CHECK(lost == 0);
        CHECK(lateEntries == 0);
    }
}

TEST_CASE("Bvh::traverse: a visit that narrows tmax ends the walk early, near boxes first") {
    // 64 unit boxes along x; a ray along +x from the left that stops at the first box.
    std::vector<Bounds3> boxes;
    for (int i = 0; i < 64; ++i) boxes.push_back({Vec3(2.0 * i, 0, 0), Vec3(2.0 * i + 1, 1, 1)});
    const Bvh bvh(boxes);
    const Ray ray{Vec3(-1, 0.5, 0.5), Vec3(1, 0, 0)};
    std::vector<int> visited;
    TraceStats stats;
    bvh.traverse(ray, 0.0, kInf, stats, [&](int i, double tEnter) {
        visited.push_back(i);
        return tEnter + 1.0;  // "hit" at the entry of the box
    });
    REQUIRE(!visited.empty());
    CHECK(visited.front() == 0);
    CHECK(visited.size() <= 4);  // the leaf holding box 0, nothing behind it
    CHECK(stats.boundsTests < 20);

    SECTION("the same along −x with a −0 component") {
        const Ray back{Vec3(200, 0.5, 0.5), Vec3(-1, -0.0, 0)};
        visited.clear();
        bvh.traverse(back, 0.0, kInf, stats, [&](int i, double tEnter) {
            visited.push_back(i);
            return tEnter + 1.0;
        });
        REQUIRE(!visited.empty());
        CHECK(visited.front() == 63);
        CHECK(visited.size() <= 4);
    }
}

TEST_CASE("Bvh: skewed inputs stay within the traversal stack") {
    // Boxes at exponentially growing positions make an SAH tree lopsided; the build falls back
    // to median splits before the depth could outgrow the fixed stack.
    std::vector<Bounds3> boxes;
    for (int i = 0; i < 3000; ++i) {
        const double x = std::ldexp(1.0, i % 1000 - 500) * (1 + i / 1000);
        boxes.push_back({Vec3(x, 0, 0), Vec3(x * 1.5, 1, 1)});
    }
    const Bvh bvh(boxes);
    CHECK(bvh.depth() <= 90);
    const Ray ray{Vec3(0, 0.5, 0.5), Vec3(1, 0, 0)};
    int count = 0;
    TraceStats stats;
    bvh.traverse(ray, 0.0, kInf, stats, [&](int, double) {
        ++count;
        return kInf;
    });
    CHECK(count == 3000);
}

TEST_CASE("Bounds3::clipRayConservative: zero directions and rays on slab planes") {
    const Bounds3 box{Vec3(0, 0, 0), Vec3(1, 1, 1)};
    auto clip = [&](const Vec3& o, const Vec3& d, double& t0, double& t1) {
        t0 = 0.0, t1 = kInf;
        return box.clipRayConservative(RayReciprocal(Ray{o, d}), t0, t1);
    };
    double t0, t1;
    // Parallel to x = 0 and lying in it (+0 and −0): inside the closed slab.
    CHECK(clip(Vec3(0, 0.5, -1), Vec3(0, 0, 1), t0, t1));
    CHECK(clip(Vec3(0, 0.5, -1), Vec3(-0.0, 0, 1), t0, t1));
    CHECK(clip(Vec3(1, 0.5, -1), Vec3(-0.0, 0, 1), t0, t1));
    CHECK(t0 <= 1.0);
    CHECK(t1 >= 2.0);
    // Parallel and outside: missed, either sign of zero.
    CHECK_FALSE(clip(Vec3(-1e-300, 0.5, -1), Vec3(0, 0, 1), t0, t1));
    CHECK_FALSE(clip(Vec3(-1e-300, 0.5, -1), Vec3(-0.0, 0, 1), t0, t1));
    CHECK_FALSE(clip(Vec3(1.0000000000000002, 0.5, -1), Vec3(-0.0, 0, 1), t0, t1));
    // A subnormal direction component: the dividing fallback, still exact about the slab.
    CHECK(clip(Vec3(0.5, 0.5, -1), Vec3(1e-310, 0, 1), t0, t1));
    CHECK_FALSE(clip(Vec3(2, 0.5, -1), Vec3(-1e-310, 0, 1), t0, t1));
    // Touching an edge exactly: a zero-width meeting is still reported.
    CHECK(clip(Vec3(-1, 0, 0.5), Vec3(1, 1, 0), t0, t1));
    CHECK(t0 <= 1.0);
    CHECK(t1 >= 1.0);
}
