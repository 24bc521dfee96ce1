/// @file tests/io/texture_test.cpp
/// @brief Image textures through the plug-in's TextureSystem, against the pixels written:
/// texel centres under a tiny footprint give the texel (8-bit codes decoded from sRGB), a
/// footprint over many texels gives the image's mean, and bad files are errors naming them.
#include "io/texture.h"
#include "io/image.h"
#include "io/srgb.h"

#include "util/scratch_folder.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>

using namespace kerf;
using namespace kerf::test;

namespace {

/// Texel (i, j) of a 16 × 8 image of distinct colours: ramps across and down, and a checker in
/// blue, so a swapped axis or a flipped row shows.
std::array<float, 3> texel(int i, int j) {
    return {float((i + 0.5) / 16.0), float((j + 0.5) / 8.0), float((i + j) % 2)};
}

Image colourImage() {
    Image image(16, 8, 3);
    for (int j = 0; j < 8; ++j)
        for (int i = 0; i < 16; ++i)
            for (int c = 0; c < 3; ++c) image.at(i, j, c) = texel(i, j)[size_t(c)];
    return image;
}

/// A linear value after an 8-bit sRGB PNG: its code, decoded.
double quantised(float v) { return srgbDecode(srgbByte(v) / 255.0); }

}  // namespace

TEST_CASE("Texture::lookup at texel centres with a tiny footprint gives the texel") {
    ScratchFolder folder;
    writeImage(colourImage(), folder.file("colours.png"));
    const auto texture = Texture::open(folder.file("colours.png"));
    REQUIRE(texture->width() == 16);
    REQUIRE(texture->height() == 8);
    for (int j = 0; j < 8; ++j)
        for (int i = 0; i < 16; ++i) {
            const double s = (i + 0.5) / 16.0, t = (j + 0.5) / 8.0;
            const auto rgb = texture->lookup(s, t, 1e-6, 0.0, 0.0, 1e-6);
            for (int c = 0; c < 3; ++c) {
                INFO("texel " << i << ", " << j << " channel " << c);
                CHECK(rgb[size_t(c)] == Approx(quantised(texel(i, j)[size_t(c)])).margin(1e-5));
            }
        }
    // A zero footprint is not a point sample: halfway between two texels is their mean
    // (the bilinear texel filter).
    const auto between = texture->lookup(2.0 / 16.0, 0.5 / 8.0, 0.0, 0.0, 0.0, 0.0);
    CHECK(between[0] ==
          Approx(0.5 * (quantised(texel(1, 0)[0]) + quantised(texel(2, 0)[0]))).margin(1e-5));
    // Periodic: one image width further is the same texel.
    const auto again = texture->lookup(3.5 / 16.0 + 5.0, 2.5 / 8.0 - 3.0, 1e-6, 0.0, 0.0, 1e-6);
    CHECK(again[1] == Approx(quantised(texel(3, 2)[1])).margin(1e-5));
}

TEST_CASE("Texture::lookup over a footprint of many texels gives the image's mean") {
    ScratchFolder folder;
    // A 64 × 64 checker of single texels, black and white: mean 0.5 in light.
    Image checker(64, 64, 1);
    for (int j = 0; j < 64; ++j)
        for (int i = 0; i < 64; ++i) checker.at(i, j, 0) = float((i + j) % 2);
    writeImage(checker, folder.file("checker.png"));
    const auto texture = Texture::open(folder.file("checker.png"));
    // Footprints 16 to 64 texels wide, square and stretched 4:1 (anisotropic), anywhere.
    for (const double w : {0.25, 0.5, 1.0})
        for (const double s : {0.1, 0.37, 0.8}) {
            const auto square = texture->lookup(s, 1.0 - s, w, 0.0, 0.0, w);
            const auto stretched = texture->lookup(s, s, w, w, -0.25 * w, 0.25 * w);
            INFO("width " << w << " at " << s);
            // Bound: the MIP levels of a one-texel checker are 0.5 by symmetry of the
            // down-sampling filter, so only rounding is left (measured: 0 here); 1e-3 is
            // far below the 0.21 that filtering codes instead of light would give.
            CHECK(std::fabs(square[0] - 0.5) < 1e-3);
            CHECK(std::fabs(stretched[0] - 0.5) < 1e-3);
            CHECK(square[1] == square[0]);  // grey in every channel
        }
    // Linear, not codes: the mean of codes 0 and 255 filtered as codes would be 0.21.
    // The colour image over its whole extent: the mean of its quantised texels.
    writeImage(colourImage(), folder.file("colours.png"));
    const auto colours = Texture::open(folder.file("colours.png"));
    double mean[3] = {0, 0, 0};
    for (int j = 0; j < 8; ++j)
        for (int i = 0; i < 16; ++i)
            for (int c = 0; c < 3; ++c) mean[c] += quantised(texel(i, j)[size_t(c)]) / 128.0;
    const auto whole = colours->lookup(0.5, 0.5, 1.0, 0.0, 0.0, 1.0);
    for (int c = 0; c < 3; ++c) {
        INFO("channel " << c << ": " << whole[size_t(c)] << " against " << mean[c]);
        // The coarsest MIP level is the mean of the finest (measured: within 5e-8).
        CHECK(std::fabs(whole[size_t(c)] - mean[c]) < 1e-3);
    }
}

TEST_CASE("Texture::open: missing files, folders and non-images are errors naming the file") {
    ScratchFolder folder;
    const auto reason = [](const std::string& path) {
        try {
            Texture::open(path);
        } catch (const TextureError& e) {
            CHECK(std::string(e.what()).find("'" + path + "'") != std::string::npos);
            return e.reason;
        }
        return std::string("opened");
    };
    CHECK(reason(folder.file("missing.png")) == "no such file");
    CHECK(reason(folder.path.string()) == "it is a folder, not an image");
    std::ofstream(folder.file("text.png")) << "not an image at all\n";
    const std::string notImage = reason(folder.file("text.png"));
    CHECK(notImage != "opened");
    CHECK_FALSE(notImage.empty());
}
