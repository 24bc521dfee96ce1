// Small renders of some models against stored reference images (tests/data/*.exr, float
// linear RGB). The references were rendered by kerf and checked by eye. After a deliberate
// change to the renderer's output, regenerate them with scripts/update-test-references and
// look at the PNG copies it writes before committing.
#include "kerf_runner.h"

#include "io/image.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace kerf::test;

namespace {

struct ImageDifference {
    double rmse = 0;          ///< over every channel of every pixel, values clamped to [0, 1]
    double fractionOver = 0;  ///< pixels with some channel differing by more than 0.1
};

ImageDifference compare(const kerf::Image& a, const kerf::Image& b) {
    ImageDifference result;
    double sumSquares = 0;
    long over = 0;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            bool pixelOver = false;
            for (int c = 0; c < 3; ++c) {
                const double d = std::clamp(double(a.at(x, y, c)), 0.0, 1.0) -
                                 std::clamp(double(b.at(x, y, c)), 0.0, 1.0);
                sumSquares += d * d;
                pixelOver = pixelOver || std::fabs(d) > 0.1;
            }
            over += pixelOver ? 1 : 0;
        }
    }
    const double pixels = double(a.width) * a.height;
    result.rmse = std::sqrt(sumSquares / (3 * pixels));
    result.fractionOver = over / pixels;
    return result;
}

}  // namespace

TEST_CASE("small renders match the stored references") {
    TempDir dir;
    for (const char* name : {"cup", "glass", "tori_cones", "gyroid_sphere"}) {
        const fs::path reference = testDataDir() / (std::string(name) + "_80x60.exr");
        const std::string out = std::string(name) + ".exr";
        const KerfRun run =
            runKerf(dir, {"render", (modelsDir() / (std::string(name) + ".kerf")).string(),
                          "--width", "80", "--height", "60", "--spp", "1", "-o", out});
        INFO(name << "\nstderr:\n" << run.err);
        REQUIRE(run.exitCode == 0);
        const kerf::Image expected = kerf::readImage(reference.string());
        const kerf::Image actual = kerf::readImage(dir.file(out));
        REQUIRE(actual.width == expected.width);
        REQUIRE(actual.height == expected.height);
        REQUIRE(actual.channels >= 3);
        REQUIRE(expected.channels >= 3);
        const ImageDifference diff = compare(actual, expected);
        INFO("RMSE " << diff.rmse << ", pixels off by > 0.1: " << 100 * diff.fractionOver << " %");
        CHECK(diff.rmse <= 0.01);
        CHECK(diff.fractionOver <= 0.005);
    }
}

TEST_CASE("the image metric itself") {
    kerf::Image a(10, 10, 3), b(10, 10, 3);
    CHECK(compare(a, b).rmse == 0);
    b.at(3, 4, 1) = 0.5f;  // one channel of one pixel: RMSE sqrt(0.25 / 300)
    CHECK(compare(a, b).rmse == Approx(std::sqrt(0.25 / 300)));
    CHECK(compare(a, b).fractionOver == Approx(0.01));
    b.at(3, 4, 1) = 7.0f;  // values are clamped to [0, 1] first
    CHECK(compare(a, b).rmse == Approx(std::sqrt(1.0 / 300)));
}
