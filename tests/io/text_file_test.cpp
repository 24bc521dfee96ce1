/// @file tests/io/text_file_test.cpp
/// @brief writeTextFileAtomically: replaces a file whole, and fails naming the file.
#include "io/text_file.h"

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

namespace kerf {

TEST_CASE("writeTextFileAtomically") {
    // A fresh folder: test processes run in parallel, also from other checkouts.
    std::string folder =
        (std::filesystem::temp_directory_path() / "kerf-text-file-XXXXXX").string();
    REQUIRE(mkdtemp(folder.data()) != nullptr);
    const std::string path = folder + "/report.txt";
    writeTextFileAtomically(path, "first\n");
    writeTextFileAtomically(path, "second, longer\n");
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    CHECK(text.str() == "second, longer\n");
    CHECK(std::distance(std::filesystem::directory_iterator(folder),
                        std::filesystem::directory_iterator()) == 1);  // no temporary left
    std::filesystem::remove_all(folder);
    CHECK_THROWS_AS(writeTextFileAtomically("/nonexistent-folder/x.csv", "x"), TextWriteError);
    CHECK_THROWS_WITH(writeTextFileAtomically("/nonexistent-folder/x.csv", "x"),
                      Catch::Contains("'/nonexistent-folder/x.csv'"));
}

}  // namespace kerf
