// Includes: relative to the including file, each file read once, cycles and missing files
// reported at the include statement.
#include "lang_test_util.h"

#include <unistd.h>
#include <atomic>
#include <filesystem>
#include <fstream>

using namespace kerf;
namespace fs = std::filesystem;

namespace {

/// A fresh folder under the system temp folder, removed at the end of the test.
class TempDir {
public:
    TempDir() {
        static std::atomic<int> counter{0};
        mPath = fs::temp_directory_path() /
                ("kerf_lang_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
        fs::create_directories(mPath);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(mPath, ec);
    }
    std::string write(const std::string& relative, const std::string& text) const {
        const fs::path p = mPath / relative;
        fs::create_directories(p.parent_path());
        std::ofstream(p, std::ios::binary) << text;
        return p.string();
    }
    std::string path(const std::string& relative) const {
        return (mPath / relative).lexically_normal().string();
    }

private:
    fs::path mPath;
};

}  // namespace

TEST_CASE("compileFile: includes") {
    TempDir dir;

    SECTION("relative to the including file, each file read once") {
        dir.write("parts/common.kerf", "let R = 2;\n");
        dir.write("parts/cup.kerf", "include \"common.kerf\";\nsolid cup = sphere { radius R };\n");
        dir.write("parts/lamp.kerf",
                  "include \"common.kerf\";\nsolid lamp = sphere { radius R / 2 };\n");
        const std::string main = dir.write("main.kerf",
                                           "include \"parts/cup.kerf\";\ninclude "
                                           "\"parts/lamp.kerf\";\nobject cup;\nobject lamp;\n");
        DiagnosticSink sink;
        const auto scene = compileFile(main, sink);
        INFO(sink.format());
        REQUIRE(scene.has_value());
        REQUIRE(scene->objects.size() == 2);
        CHECK(scene->objects[0]->bounds().hi.x == Approx(2));
        CHECK(scene->objects[1]->bounds().hi.x == Approx(1));
    }

    SECTION("an include cycle is an error at the include statement") {
        const std::string a = dir.write("a.kerf", "include \"b.kerf\";\nobject sphere {};\n");
        dir.write("b.kerf", "let one = 1;\n  include \"a.kerf\";\n");
        DiagnosticSink sink;
        REQUIRE_FALSE(compileFile(a, sink).has_value());
        REQUIRE(sink.errorCount() == 1);
        const Diagnostic& d = sink.diagnostics()[0];
        CHECK(d.message == "include cycle: " + a + " → " + dir.path("b.kerf") + " → " + a);
        CHECK(*d.loc.file == dir.path("b.kerf"));
        CHECK(d.loc.line == 2);
        CHECK(d.loc.col == 3);
    }

    SECTION("a file that includes itself") {
        const std::string a = dir.write("self.kerf", "include \"./self.kerf\";\n");
        DiagnosticSink sink;
        REQUIRE_FALSE(compileFile(a, sink).has_value());
        REQUIRE(sink.errorCount() == 1);
        CHECK(sink.diagnostics()[0].message == "include cycle: " + a + " → " + a);
        CHECK(sink.diagnostics()[0].loc.line == 1);
        CHECK(sink.diagnostics()[0].loc.col == 1);
    }

    SECTION("a missing include is an error at the include statement") {
        const std::string a = dir.write("m.kerf", "let a = 1;\n  include \"nope.kerf\";\n");
        DiagnosticSink sink;
        REQUIRE_FALSE(compileFile(a, sink).has_value());
        REQUIRE(sink.errorCount() == 1);
        const Diagnostic& d = sink.diagnostics()[0];
        CHECK(d.message == "cannot read included file 'nope.kerf': no such file");
        CHECK(d.loc.line == 2);
        CHECK(d.loc.col == 3);
        CHECK_THAT(d.hint, Catch::Matchers::Contains(dir.path("nope.kerf")));
    }

    SECTION("errors inside an included file name that file") {
        dir.write("bad.kerf", "let a = 1;\nlet b = a / 0;\n");
        const std::string main = dir.write("main2.kerf", "include \"bad.kerf\";\n");
        DiagnosticSink sink;
        REQUIRE_FALSE(compileFile(main, sink).has_value());
        REQUIRE(sink.errorCount() == 1);
        CHECK(*sink.diagnostics()[0].loc.file == dir.path("bad.kerf"));
        CHECK(sink.diagnostics()[0].loc.line == 2);
        CHECK(sink.diagnostics()[0].loc.col == 11);
        CHECK_THAT(sink.format(), Catch::Matchers::Contains("let b = a / 0;\n          ^\n"));
    }

    SECTION("a missing top-level file") {
        DiagnosticSink sink;
        const std::string missing = dir.path("absent.kerf");
        REQUIRE_FALSE(compileFile(missing, sink).has_value());
        CHECK(sink.format() == missing + ": error: cannot read '" + missing + "': no such file\n");
    }

    SECTION("binary garbage in a file") {
        const std::string bin = dir.write("bin.kerf", std::string("\x7f"
                                                                  "ELF\x02\x01\x01\0\0\0",
                                                                  10));
        DiagnosticSink sink;
        REQUIRE_FALSE(compileFile(bin, sink).has_value());
        REQUIRE(sink.errorCount() == 1);
        CHECK(sink.diagnostics()[0].message ==
              "file contains the control character 0x7F; is it a binary file?");
        CHECK(sink.diagnostics()[0].loc.line == 1);
        CHECK(sink.diagnostics()[0].loc.col == 1);
    }
}
