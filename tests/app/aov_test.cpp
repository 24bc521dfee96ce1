// End-to-end test of `--aov depth=` and `--aov normal=` against the closed form: a single
// sphere seen by the pinhole camera of the issue, every pixel-centre ray intersected in long
// double.
#include "kerf_runner.h"

#include "io/image.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace kerf::test;

namespace {

using Real = long double;
struct V3 {
    Real x, y, z;
};
V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 operator*(Real s, V3 a) { return {s * a.x, s * a.y, s * a.z}; }
Real dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(V3 a, V3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
V3 normalize(V3 a) { return (1 / std::sqrt(dot(a, a))) * a; }

// The scene, in the model below and here.
const V3 kEye{0.5L, 0.4L, -6};
const V3 kLookAt{0, 0, 0};
const V3 kUp{0, 1, 0};
const Real kFovDegrees = 30;
const V3 kCenter{0.3L, -0.2L, 1};
const Real kRadius = 1.2L;
const int kWidth = 40, kHeight = 30;

const char* kModel = R"(object sphere { center <0.3, -0.2, 1> radius 1.2 };
camera { eye <0.5, 0.4, -6> look_at <0, 0, 0> up <0, 1, 0> fov 30 }
light point { at <-3, 4, -5> color <1, 1, 1> power 400 }
render { width 40 height 30 spp 1 }
)";

/// The pixel-centre ray direction of pixel (i, j), as the issue defines it.
V3 pixelDirection(int i, int j) {
    const V3 f = normalize(kLookAt - kEye);
    const V3 r = normalize(cross(f, kUp));
    const V3 u = cross(r, f);
    const Real pi = 3.14159265358979323846264338327950288L;
    const Real h = std::tan(kFovDegrees * pi / 360);
    const Real sx = ((i + 0.5L) / kWidth * 2 - 1) * h * Real(kWidth) / kHeight;
    const Real sy = (1 - (j + 0.5L) / kHeight * 2) * h;
    return normalize(f + sx * r + sy * u);
}

/// Runs the render and reads back the two AOVs.
void renderAovs(TempDir& dir, const std::string& spp, kerf::Image& depth, kerf::Image& normal) {
    dir.write("ball.kerf", kModel);
    const KerfRun run = runKerf(dir, {"render", "ball.kerf", "-o", "ball.png", "--spp", spp,
                                      "--aov", "depth=depth.exr", "--aov", "normal=normal.exr"});
    INFO("stderr:\n" << run.err);
    REQUIRE(run.exitCode == 0);
    depth = kerf::readImage(dir.file("depth.exr"));
    normal = kerf::readImage(dir.file("normal.exr"));
    REQUIRE(depth.width == kWidth);
    REQUIRE(depth.height == kHeight);
    REQUIRE(depth.channels == 1);
    REQUIRE(normal.width == kWidth);
    REQUIRE(normal.height == kHeight);
    REQUIRE(normal.channels == 3);
}

}  // namespace

TEST_CASE("kerf render --aov depth/normal: closed-form sphere") {
    TempDir dir;
    kerf::Image depth, normal;
    renderAovs(dir, "1", depth, normal);

    int hits = 0, misses = 0;
    for (int j = 0; j < kHeight; ++j) {
        for (int i = 0; i < kWidth; ++i) {
            const V3 d = pixelDirection(i, j);
            const V3 oc = kEye - kCenter;
            const Real b = dot(oc, d);
            const Real disc = b * b - (dot(oc, oc) - kRadius * kRadius);
            INFO("pixel " << i << ", " << j);
            // Rays that graze the silhouette may be classified either way in double.
            if (std::fabs(disc) < 1e-6L * kRadius * kRadius) continue;
            const float stored = depth.at(i, j, 0);
            if (disc < 0) {
                CHECK(std::isinf(stored));
                CHECK(stored > 0);
                ++misses;
                continue;
            }
            ++hits;
            const Real t = -b - std::sqrt(disc);
            // The renderer's distance must be within 1e-9 relative of t; the EXR stores it
            // as a 32-bit float, which adds at most half an ulp (2^-24 relative).
            const Real allowed = t * (1e-9L + std::ldexp(1.0L, -24));
            CHECK(std::fabs(Real(stored) - t) <= allowed);

            const V3 p = kEye + t * d;
            const V3 n = (1 / kRadius) * (p - kCenter);
            CHECK(std::fabs(normal.at(i, j, 0) - n.x) <= 1e-6L);
            CHECK(std::fabs(normal.at(i, j, 1) - n.y) <= 1e-6L);
            CHECK(std::fabs(normal.at(i, j, 2) - n.z) <= 1e-6L);
        }
    }
    // The sphere fills a good part of the frame and does not fill all of it.
    CHECK(hits > kWidth * kHeight / 10);
    CHECK(misses > kWidth * kHeight / 10);

    SECTION("antialiasing does not change the AOVs: they use the pixel-centre ray") {
        TempDir dir4;
        kerf::Image depth4, normal4;
        renderAovs(dir4, "4", depth4, normal4);
        CHECK(depth4.pixels == depth.pixels);
        CHECK(normal4.pixels == normal.pixels);
    }
}
