/// @file tests/io/text_file_test.cpp
/// @brief writeTextFileAtomically: replaces a file whole, and fails naming the file.
#include "io/text_file.h"

#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace kerf {

TEST_CASE("writeTextFileAtomically") {
    const std::string path =
        (std::filesystem::temp_directory_path() / "kerf-accuracy-write-test.txt").string();
    writeTextFileAtomically(path, "first\n");
    writeTextFileAtomically(path, "second, longer\n");
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    CHECK(text.str() == "second, longer\n");
    std::remove(path.c_str());
    CHECK_THROWS_AS(writeTextFileAtomically("/nonexistent-folder/x.csv", "x"), TextWriteError);
}

}  // namespace kerf
