/// @file tests/render/model_test.cpp
/// @brief From model text to pixels: a compiled scene shades by the closed form, and every
/// model in models/ renders small to finite, thread-independent images.
#include "assets/asset_cache.h"
#include "lang/compile.h"
#include "render/camera.h"
#include "render_test_util.h"

#include <catch2/catch.hpp>

#include <cstring>
#include <filesystem>

using namespace kerf;
using namespace kerf::test;

TEST_CASE("render: a compiled model shades by the closed form") {
    const char* text = R"(
        material matte { color <0.9, 0.6, 0.3> ambient 0 diffuse 0.7 }
        object sphere { center <0.3, -0.2, 0.5> radius 1.1 } material matte;
        light directional { direction <-1, -2, 1.5> color <1, 0.8, 0.6> }
        camera { eye <0, 0, -5> look_at <0, 0, 0> up <0, 1, 0> fov 40 }
    )";
    DiagnosticSink sink;
    const std::optional<Scene> scene = compileString(text, "lambert.kerf", sink);
    INFO(sink.format());
    REQUIRE(scene);
    const int W = 24, H = 16;
    const RenderResult r = render(*scene, smallImage(W, H));
    const Camera camera(scene->camera, W, H);
    const Vec3 center(0.3, -0.2, 0.5), l = glm::normalize(Vec3(1, 2, -1.5));
    int hits = 0;
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            const Ray ray = camera.rayThrough(i + 0.5, j + 0.5);
            const auto t = raySphere(ray.origin, ray.dir, center, 1.1);
            if (!t) continue;
            ++hits;
            const Vec3 n = (ray.at(double(*t)) - center) / 1.1;
            const Vec3 expected =
                0.7 * Vec3(0.9, 0.6, 0.3) * Vec3(1, 0.8, 0.6) * std::max(0.0, glm::dot(n, l));
            INFO("pixel " << i << "," << j);
            for (int k = 0; k < 3; ++k)
                CHECK(r.color.at(i, j, k) == Approx(expected[k]).margin(1e-5));
        }
    CHECK(hits > 50);
}

TEST_CASE("render: every model renders small, finite and thread-independent") {
    const std::filesystem::path models = std::filesystem::path(KERF_SOURCE_DIR) / "models";
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(models)) {
        if (entry.path().extension() != ".kerf") continue;
        ++count;
        INFO(entry.path().string());
        DiagnosticSink sink;
        AssetCache assets;
        const std::optional<Scene> scene = compileFile(entry.path().string(), sink, assets);
        INFO(sink.format());
        REQUIRE(scene);
        RenderOptions options = smallImage(32, 24, 1);
        const RenderResult one = render(*scene, options);
        options.threads = 2;
        const RenderResult two = render(*scene, options);
        int nonFinite = 0, negative = 0;
        for (float v : one.color.pixels) {
            nonFinite += !std::isfinite(v);
            negative += v < 0;
        }
        CHECK(nonFinite == 0);
        CHECK(negative == 0);
        CHECK(std::memcmp(one.color.pixels.data(), two.color.pixels.data(),
                          one.color.pixels.size() * sizeof(float)) == 0);
    }
    CHECK(count >= 6);
}
