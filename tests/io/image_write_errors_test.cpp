/// @file tests/io/image_write_errors_test.cpp
/// @brief An image the encoder refuses: libjpeg's own failure (a side above 65,500 pixels)
/// comes back as kerf's error, the process goes on (libjpeg's default handler would exit it
/// from inside the library), and the earlier file is kept.
#include "io/image.h"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace kerf;
namespace fs = std::filesystem;

TEST_CASE("a JPEG too large for the format is an error, not an exit") {
    std::string folder = (fs::temp_directory_path() / "kerf-jpeg-errors-XXXXXX").string();
    REQUIRE(mkdtemp(folder.data()) != nullptr);
    const std::string file = folder + "/wide.jpg";
    std::ofstream(file) << "an earlier image";

    const Image wide(65501, 1, 3);
    try {
        writeImage(wide, file);
        FAIL("no exception");
    } catch (const ImageWriteError& e) {
        CHECK(std::string(e.what()) ==
              "cannot write '" + file +
                  "': JPEG images are at most 65500 pixels wide and high (use .png, .exr or .tif)");
    }
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    CHECK(text.str() == "an earlier image");
    CHECK(std::distance(fs::directory_iterator(folder), fs::directory_iterator()) == 1);

    // The same process still writes JPEG afterwards.
    writeImage(Image(4, 3, 3), file);
    CHECK(fs::file_size(file) > 100);
    fs::remove_all(folder);
}
