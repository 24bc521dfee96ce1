/// @file tests/io/atomic_file_test.cpp
/// @brief The one write path: exact bytes, no temporary left, and the reasons an output
/// cannot be written, in the words the user sees. (Full disks and signals are tested on the
/// kerf executable with a fault-injection shim: tests/app/write_fault_test.cpp.)
#include "io/atomic_file.h"

#include "util/scratch_folder.h"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace kerf;
using namespace kerf::test;
namespace fs = std::filesystem;

TEST_CASE("replaceFile writes exactly the bytes and leaves no temporary") {
    ScratchFolder dir;
    const std::string file = dir.file("data.bin");
    const std::string bytes("a\0b\nc", 5);
    CHECK(replaceFile(file, ".bin", bytes.data(), bytes.size()) == "");
    CHECK(slurp(file) == bytes);
    CHECK(replaceFile(file, ".bin", "xy", 2) == "");
    CHECK(slurp(file) == "xy");
    CHECK(dir.entries() == 1);
}

TEST_CASE("outputProblem names what is wrong") {
    ScratchFolder dir;
    std::ofstream(dir.file("plain.txt")) << "x";
    fs::create_directory(dir.path / "sub");
    CHECK(outputProblem(dir.file("ok.png"), true) == "");
    CHECK(outputProblem(dir.file("plain.txt"), true) == "");
    CHECK(outputProblem(dir.file("missing/x.png"), true) ==
          "folder '" + dir.file("missing") + "' does not exist");
    CHECK(outputProblem(dir.file("plain.txt/x.png"), true) ==
          "'" + dir.file("plain.txt") + "' is not a folder");
    CHECK(outputProblem(dir.file("sub"), true) == "it is a folder");
    CHECK(outputProblem(dir.file("sub/"), true) == "the file name is missing");
    CHECK(outputProblem("/dev/null", false) == "it exists and is not a regular file");
    CHECK(dir.entries() == 2);  // the probe left nothing
    CHECK_THROWS_WITH(checkOutputWritable(dir.file("missing/x.png")),
                      "cannot write '" + dir.file("missing/x.png") + "': folder '" +
                          dir.file("missing") + "' does not exist");
}

TEST_CASE("replaceFile refuses a folder in the way and keeps it") {
    ScratchFolder dir;
    fs::create_directory(dir.path / "taken");
    CHECK(replaceFile(dir.file("taken"), "", "x", 1) == "it is a folder");
    CHECK(fs::is_directory(dir.path / "taken"));
    CHECK(dir.entries() == 1);
}
