// Input that never ends or nests without end: devices, FIFOs, folders and huge files are
// refused before they are read, and include chains deeper than kMaxIncludeDepth are an error
// at the include that goes too deep (scene/limits.h).
#include "lang_test_util.h"

#include "lang/source.h"

#include <sys/stat.h>
#include <unistd.h>
#include <atomic>
#include <filesystem>
#include <fstream>

using namespace kerf;
using namespace kerf::test;
namespace fs = std::filesystem;

namespace {

class TempDir {
public:
    TempDir() {
        static std::atomic<int> counter{0};
        mPath = fs::temp_directory_path() / ("kerf_limits_test_" + std::to_string(::getpid()) +
                                             "_" + std::to_string(counter++));
        fs::create_directories(mPath);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(mPath, ec);
    }
    std::string write(const std::string& relative, const std::string& text) const {
        const fs::path p = mPath / relative;
        std::ofstream(p, std::ios::binary) << text;
        return p.string();
    }
    std::string path(const std::string& relative) const { return (mPath / relative).string(); }

private:
    fs::path mPath;
};

/// Compiles `main` and requires exactly one error, whose message contains `message`, at
/// `line` of the file named `file`.
void requireOneFileError(const std::string& main, const std::string& file, int line,
                         const std::string& message) {
    DiagnosticSink sink;
    const auto scene = compileFile(main, sink);
    INFO(sink.format());
    REQUIRE_FALSE(scene.has_value());
    REQUIRE(sink.errorCount() == 1);
    const Diagnostic& d = sink.diagnostics().front();
    CHECK_THAT(d.message, Catch::Matchers::Contains(message));
    REQUIRE(d.loc.file);
    CHECK(*d.loc.file == file);
    CHECK(d.loc.line == line);
}

}  // namespace

TEST_CASE("includes and models that are not regular files are refused unread") {
    TempDir dir;
    SECTION("/dev/zero and /dev/urandom") {
        for (const char* device : {"/dev/zero", "/dev/urandom"}) {
            const std::string main =
                dir.write("main.kerf", std::string("let a = 1;\ninclude \"") + device + "\";\n");
            requireOneFileError(main, main, 2, "not a regular file");
            DiagnosticSink sink;
            CHECK_FALSE(compileFile(device, sink).has_value());
            CHECK_THAT(sink.format(), Catch::Matchers::Contains("not a regular file"));
        }
    }
    SECTION("a FIFO (nobody writes to it: opening it for reading would block)") {
        REQUIRE(::mkfifo(dir.path("pipe.kerf").c_str(), 0600) == 0);
        const std::string main = dir.write("main.kerf", "include \"pipe.kerf\";\n");
        requireOneFileError(main, main, 1, "not a regular file");
        DiagnosticSink sink;
        CHECK_FALSE(compileFile(dir.path("pipe.kerf"), sink).has_value());
        std::string why;
        CHECK_FALSE(readFileBytes(dir.path("pipe.kerf"), why).has_value());
        CHECK_THAT(why, Catch::Matchers::Contains("not a regular file"));
    }
    SECTION("a folder") {
        fs::create_directory(dir.path("parts"));
        const std::string main = dir.write("main.kerf", "\ninclude \"parts\";\n");
        requireOneFileError(main, main, 2, "it is a directory");
    }
}

TEST_CASE("files larger than the size limit are refused") {
    TempDir dir;
    SECTION("a sparse file just over kMaxSourceBytes, refused by its size without reading it") {
        const std::string big = dir.path("big.kerf");
        { std::ofstream(big) << "let a = 1;\n"; }
        REQUIRE(::truncate(big.c_str(), kMaxSourceBytes + 1) == 0);
        const std::string main = dir.write("main.kerf", "include \"big.kerf\";\n");
        requireOneFileError(main, main, 1, "larger than 256 MB");
        std::string why;
        CHECK_FALSE(readFileBytes(big, why).has_value());
        CHECK_THAT(why, Catch::Matchers::Contains("larger than 256 MB"));
    }
    SECTION("the limit is exact: at the limit is read, one byte more is not") {
        const std::string text(1000, ' ');
        const std::string path = dir.write("spaces.kerf", text);
        std::string why;
        CHECK(readFileBytes(path, why, 1000) == text);
        CHECK_FALSE(readFileBytes(path, why, 999).has_value());
        CHECK_THAT(why, Catch::Matchers::Contains("larger than"));
    }
}

TEST_CASE("an include chain deeper than kMaxIncludeDepth is one error at the include") {
    // Each file f<i> includes f<i+1>, the include statement first in the file or after a
    // let (both orders of statements). From f1 the chain is kMaxIncludeDepth files long; from
    // f0 one more. (13,000 files deep used to overflow the stack; one over the limit is
    // enough to show the limit holds.)
    for (const bool includeFirst : {true, false}) {
        TempDir dir;
        const int files = kMaxIncludeDepth + 1;
        for (int i = 0; i < files; ++i) {
            const std::string next = "include \"f" + std::to_string(i + 1) + ".kerf\";\n";
            const std::string let = "let a" + std::to_string(i) + " = 1;\n";
            std::string text = i + 1 < files ? (includeFirst ? next + let : let + next) : let;
            if (i <= 1) text += "object sphere {};\n";
            dir.write("f" + std::to_string(i) + ".kerf", text);
        }
        INFO("include first: " << includeFirst);
        {
            DiagnosticSink sink;
            const auto scene = compileFile(dir.path("f1.kerf"), sink);
            INFO(sink.format());
            CHECK(scene.has_value());
        }
        // kMaxIncludeDepth files are open when the last of them includes one more.
        const std::string deepest = dir.path("f" + std::to_string(kMaxIncludeDepth - 1) + ".kerf");
        requireOneFileError(dir.path("f0.kerf"), deepest, includeFirst ? 1 : 2,
                            "includes nested too deeply");
    }
}
