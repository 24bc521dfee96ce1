/// @file tests/io/image_io_test.cpp
/// @brief writeImage/readImage: round trips within the quantisation, format by extension,
/// and failures that leave no file behind and never clobber an existing one.
#include "io/image.h"
#include "io/srgb.h"

#include "util/scratch_folder.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <sys/stat.h>

using namespace kerf;
using namespace kerf::test;
namespace fs = std::filesystem;

namespace {

/// A test pattern: a ramp over [−0.25, 1.25] so clamping shows, with a NaN.
Image pattern(int w, int h, int c) {
    Image image(w, h, c);
    for (size_t k = 0; k < image.pixels.size(); ++k)
        image.pixels[k] = float(-0.25 + 1.5 * double(k) / double(image.pixels.size() - 1));
    image.pixels[3] = std::numeric_limits<float>::quiet_NaN();
    return image;
}

}  // namespace

TEST_CASE("srgbEncode / srgbDecode") {
    CHECK(srgbEncode(0.0) == 0.0);
    CHECK(srgbEncode(1.0) == Approx(1.0).epsilon(1e-15));
    CHECK(srgbEncode(0.0031308) == Approx(0.0031308 * 12.92));
    CHECK(srgbEncode(0.5) == Approx(0.735356983).epsilon(1e-8));  // IEC 61966-2-1
    for (double v : {0.001, 0.01, 0.2, 0.5, 0.9}) CHECK(srgbDecode(srgbEncode(v)) == Approx(v));
    CHECK(srgbByte(-1.0f) == 0);
    CHECK(srgbByte(std::numeric_limits<float>::quiet_NaN()) == 0);
    CHECK(srgbByte(2.0f) == 255);
    CHECK(srgbByte(0.5f) == 188);  // round(0.7354·255) = round(187.5) → 188
    // The table search gives the code the formula rounds to, for every float in a sweep.
    int mismatches = 0;
    for (int i = 0; i <= 200000; ++i) {
        const float v = float(i) / 200000.0f;
        const long expected = std::lround(srgbEncode(v) * 255.0);
        if (srgbByte(v) != expected) ++mismatches;
    }
    CHECK(mismatches == 0);
}

TEST_CASE("writeImage / readImage round trips") {
    ScratchFolder dir;

    SECTION("PNG: 8-bit sRGB codes, clamped and rounded") {
        const Image image = pattern(5, 3, 3);
        const std::string file = dir.file("ramp.png");
        writeImage(image, file);
        const Image back = readImage(file);
        REQUIRE(back.width == 5);
        REQUIRE(back.height == 3);
        REQUIRE(back.channels == 3);
        for (size_t k = 0; k < image.pixels.size(); ++k) {
            INFO("value " << k << " = " << image.pixels[k]);
            // Exactly the code srgbByte gives, decoded back to linear.
            const double code = srgbByte(image.pixels[k]);
            CHECK(back.pixels[k] == Approx(srgbDecode(code / 255.0)).margin(1e-6));
        }
        CHECK(dir.entries() == 1);  // no temporary left behind
    }

    SECTION("PNGs of 1 to 4 channels (libpng's, io/png_write.h), marked sRGB, read back exactly") {
        for (int channels = 1; channels <= 4; ++channels) {
            INFO(channels << " channels");
            const Image image = pattern(7, 4, channels);
            const std::string file = dir.file("c" + std::to_string(channels) + ".png");
            writeImage(image, file);
            const std::string bytes = slurp(file);
            CHECK(bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);
            CHECK(bytes.find("sRGB") != std::string::npos);
            CHECK(bytes.find("gAMA") != std::string::npos);
            const Image back = readImage(file);
            REQUIRE(back.width == 7);
            REQUIRE(back.height == 4);
            REQUIRE(back.channels == channels);
            for (size_t k = 0; k < image.pixels.size(); ++k) {
                const float v = image.pixels[k];
                // Alpha is straight and linear: its code is the coverage, not sRGB.
                const bool alpha = channels % 2 == 0 && int(k % size_t(channels)) == channels - 1;
                const double want =
                    alpha ? std::lround(std::clamp(std::isnan(v) ? 0.0f : v, 0.0f, 1.0f) * 255) /
                                255.0
                          : srgbDecode(srgbByte(v) / 255.0);
                CHECK(back.pixels[k] == Approx(want).margin(1e-6));
            }
        }
    }

    SECTION("a PNG that is a window of a larger image keeps its place (through the plug-in)") {
        const Image image = pattern(3, 2, 3);
        writeImage(image, dir.file("part.png"), ImageWindow{4, 5, 10, 9});
        ImageWindow window;
        const Image back = readImage(dir.file("part.png"), window);
        CHECK(back.width == 3);
        CHECK(window.x == 4);
        CHECK(window.y == 5);
    }

    SECTION("EXR and TIFF: float linear, exact, infinities kept") {
        Image depth = pattern(4, 3, 1);
        depth.pixels[2] = std::numeric_limits<float>::infinity();
        depth.pixels[3] = 1e30f;
        for (const char* name : {"depth.exr", "depth.tif", "DEPTH.TIFF"}) {
            INFO(name);
            writeImage(depth, dir.file(name));
            const Image back = readImage(dir.file(name));
            REQUIRE(back.channels == 1);
            REQUIRE(back.pixels.size() == depth.pixels.size());
            for (size_t k = 0; k < depth.pixels.size(); ++k)
                CHECK(back.pixels[k] == depth.pixels[k]);
        }
    }

    SECTION("JPEG: lossy, but a flat grey stays within two codes") {
        Image grey(16, 16, 3);
        for (float& v : grey.pixels) v = 0.2f;
        writeImage(grey, dir.file("grey.jpg"));
        const Image back = readImage(dir.file("grey.jpg"));
        REQUIRE(back.channels == 3);
        for (float v : back.pixels) CHECK(std::abs(srgbEncode(v) - srgbEncode(0.2)) * 255 <= 2.0);
    }

    SECTION("an existing file is replaced") {
        const std::string file = dir.file("out.exr");
        writeImage(pattern(2, 2, 3), file);
        Image second(3, 1, 3);
        second.pixels.assign(9, 0.75f);
        writeImage(second, file);
        const Image back = readImage(file);
        CHECK(back.width == 3);
        CHECK(back.pixels[4] == 0.75f);
        CHECK(dir.entries() == 1);
    }
}

TEST_CASE("writeImage permissions") {
    // The temporary file is created private; the result must look like any new file.
    ScratchFolder dir;
    const mode_t mask = umask(022);
    umask(mask);
    const std::string file = dir.file("fresh.png");
    writeImage(pattern(2, 2, 3), file);
    CHECK((fs::status(file).permissions() & fs::perms::all) == fs::perms(0666 & ~mask));
    SECTION("a replaced file keeps its permissions") {
        fs::permissions(file, fs::perms(0640));
        writeImage(pattern(3, 3, 3), file);
        CHECK((fs::status(file).permissions() & fs::perms::all) == fs::perms(0640));
    }
}

TEST_CASE("writeImage failures") {
    ScratchFolder dir;
    const Image image = pattern(4, 4, 3);

    SECTION("an unknown extension throws, naming the file, and writes nothing") {
        for (const char* name : {"picture.bmpx", "noextension", "dir.png/file"}) {
            const std::string file = dir.file(name);
            INFO(name);
            try {
                writeImage(image, file);
                FAIL("no exception");
            } catch (const ImageWriteError& e) {
                CHECK(std::string(e.what()).find(file) != std::string::npos);
            }
        }
        CHECK(dir.entries() == 0);
    }

    SECTION("a failed write leaves an existing file untouched") {
        const std::string file = dir.file("keep.png");
        writeImage(image, file);
        const std::string before = slurp(file);
        Image broken(4, 4, 3);
        broken.pixels.resize(5);  // does not match its size
        CHECK_THROWS_AS(writeImage(broken, file), ImageWriteError);
        CHECK(slurp(file) == before);
        CHECK(dir.entries() == 1);
    }

    SECTION("a rename that fails removes the temporary and keeps what was there") {
        // The target is a non-empty directory: the image is written, the rename refused.
        const std::string target = dir.file("taken.png");
        fs::create_directory(target);
        std::ofstream(target + "/inside.txt") << "precious";
        CHECK_THROWS_AS(writeImage(image, target), ImageWriteError);
        CHECK(fs::is_directory(target));
        CHECK(slurp(target + "/inside.txt") == "precious");
        CHECK(dir.entries() == 1);
    }

    SECTION("a missing directory throws, naming the file") {
        const std::string file = dir.file("missing/sub/out.exr");
        try {
            writeImage(image, file);
            FAIL("no exception");
        } catch (const ImageWriteError& e) {
            CHECK(std::string(e.what()).find(file) != std::string::npos);
        }
        CHECK(dir.entries() == 0);
    }
}
