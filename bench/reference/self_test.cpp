/// @file bench/reference/self_test.cpp
#include "self_test.h"

#include "ref_spans.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace kerf::bench {

namespace {

/// Counts and prints failed expectations.
class Checker {
public:
    void near(const char* what, Real got, Real want, Real relative) {
        if (std::fabs(got - want) <= relative * std::fabs(want)) return;
        std::fprintf(stderr, "self-test: %s: got %.21Lg, want %.21Lg\n", what, got, want);
        ++mFailures;
    }

    void spans(const char* what, const RefSpans& got, const RefSpans& want) {
        if (got.size() != want.size()) {
            std::fprintf(stderr, "self-test: %s: %zu spans, want %zu\n", what, got.size(),
                         want.size());
            ++mFailures;
            return;
        }
        for (size_t i = 0; i < got.size(); ++i) {
            near(what, got[i].first, want[i].first, 1e-17L);
            near(what, got[i].second, want[i].second, 1e-17L);
        }
    }

    void count(const char* what, int got, int want) {
        if (got == want) return;
        std::fprintf(stderr, "self-test: %s: %d, want %d\n", what, got, want);
        ++mFailures;
    }

    int failures() const { return mFailures; }

private:
    int mFailures = 0;
};

RefNode leaf(RefNode::Kind kind, V3 a, V3 b, Real r1, Real r2 = 0) {
    RefNode n;
    n.kind = kind, n.a = a, n.b = b, n.r1 = r1, n.r2 = r2;
    return n;
}

}  // namespace

int runSelfTest() {
    Checker check;
    using K = RefNode::Kind;
    const V3 o{0, 0, -10}, z{0, 0, 1};

    // (s - 1)(s - 2)(s - 3)(s - 4) = s^4 - 10 s^3 + 35 s^2 - 50 s + 24.
    const Real quartic[5] = {24, -50, 35, -10, 1};
    Real roots[4];
    const int n = polynomialRoots(quartic, 4, 0, 5, roots);
    check.count("quartic roots", n, 4);
    for (int i = 0; i < n; ++i) check.near("quartic root", roots[i], i + 1, 1e-17L);

    const RefNode sphere = leaf(K::Sphere, {0, 0, 0}, {}, 1);
    check.spans("sphere", spansOf(sphere, o, z), {{9, 11}});
    const RefNode box = leaf(K::Box, {-1, -1, -1}, {1, 1, 1}, 0);
    check.spans("box", spansOf(box, o, z), {{9, 11}});
    check.spans("box, grazing a face", spansOf(box, {1, 0, -10}, z), {{9, 11}});
    const RefNode cylinder = leaf(K::Cylinder, {0, -1, 0}, {0, 1, 0}, 0.5L);
    check.spans("cylinder side", spansOf(cylinder, o, z), {{9.5L, 10.5L}});
    check.spans("cylinder caps", spansOf(cylinder, {0.25L, -5, 0}, {0, 1, 0}), {{4, 6}});
    const RefNode torus = leaf(K::Torus, {}, {}, 1, 0.25L);
    check.spans("torus", spansOf(torus, o, z), {{8.75L, 9.25L}, {10.75L, 11.25L}});

    // A box minus a sphere sharing the box's front face: a clean dimple, no sliver.
    RefNode dimple;
    dimple.kind = K::Difference;
    dimple.children = {box, leaf(K::Sphere, {0, 0, -1}, {}, 0.5L)};
    check.spans("difference", spansOf(dimple, o, z), {{9.5L, 11}});
    RefNode moved;
    moved.kind = K::Transform;
    moved.offset = {0, 0, 3};
    moved.children = {sphere};
    check.spans("translate", spansOf(moved, o, z), {{12, 14}});

    // bench/scenes/tori.ref, pixel (548, 382) of 800 x 600: the small tilted torus
    // (R 0.45, r 0.12, rotate <0,0,90> rotate <0,40,0> translate <-1.2,0.57,-2.2>), whose
    // nearest root mpmath finds at 7.600654719270893 with 50 digits.
    RefNode tilted = leaf(K::Torus, {}, {}, 0.45L, 0.12L);
    for (const V3 angles : {V3{0, 0, 90}, V3{0, 40, 0}}) {
        RefNode r;
        r.kind = K::Transform;
        const Real c = std::cos(angles.y * 3.141592653589793238462643383279502884L / 180);
        const Real s = std::sin(angles.y * 3.141592653589793238462643383279502884L / 180);
        if (angles.z == 90) {  // inverse of rotate z 90: (x, y) -> (y, -x)
            r.localFromWorld.m[0][0] = 0, r.localFromWorld.m[0][1] = 1;
            r.localFromWorld.m[1][0] = -1, r.localFromWorld.m[1][1] = 0;
        } else {  // inverse of rotate y: transpose of [[c, 0, s], [0, 1, 0], [-s, 0, c]]
            r.localFromWorld.m[0][0] = c, r.localFromWorld.m[0][2] = -s;
            r.localFromWorld.m[2][0] = s, r.localFromWorld.m[2][2] = c;
        }
        r.children = {tilted};
        tilted = r;
    }
    RefNode placed;
    placed.kind = K::Transform;
    placed.offset = {-1.2L, 0.57L, -2.2L};
    placed.children = {tilted};
    const V3 eye{0, 4.5L, -9};
    const V3 f = normalize(V3{0, 0.8L, 0.5L} - eye);
    const V3 r = normalize(cross(f, {0, 1, 0}));
    const V3 u = cross(r, f);
    const Real tanHalf = std::tan(20 * 3.141592653589793238462643383279502884L / 180);
    const Real sx = (548 + 0.5L) / 800 * 2 - 1, sy = 1 - (382 + 0.5L) / 600 * 2;
    const V3 d = normalize(f + (sx * tanHalf * 800 / 600) * r + (sy * tanHalf) * u);
    check.near("tori.ref pixel (548, 382)", nearestHit({placed}, eye, d).first, 7.600654719270893L,
               1e-15L);
    return check.failures();
}

}  // namespace kerf::bench
