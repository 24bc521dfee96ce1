// Every model in models/ renders: exit 0 and an image of the requested size that shows
// something (not one flat colour).
#include "kerf_runner.h"

#include "io/image.h"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace kerf::test;

TEST_CASE("models/*.kerf render at small size") {
    TempDir dir;
    int rendered = 0;
    for (const auto& entry : fs::directory_iterator(modelsDir())) {
        if (entry.path().extension() != ".kerf") continue;
        const std::string name = entry.path().stem().string();
        const std::string out = name + ".png";
        const KerfRun run = runKerf(dir, {"render", entry.path().string(), "--width", "64",
                                          "--height", "48", "--spp", "1", "-o", out});
        INFO(name << "\nstderr:\n" << run.err);
        REQUIRE(run.exitCode == 0);
        const kerf::Image image = kerf::readImage(dir.file(out));
        CHECK(image.width == 64);
        CHECK(image.height == 48);
        REQUIRE(image.channels >= 3);
        const auto [lo, hi] = std::minmax_element(image.pixels.begin(), image.pixels.end());
        CHECK(*hi - *lo > 0.2f);
        ++rendered;
    }
    // showcase, cup, gyroid_sphere, box_minus_spheres, tori_cones, glass at least.
    CHECK(rendered >= 6);
}
