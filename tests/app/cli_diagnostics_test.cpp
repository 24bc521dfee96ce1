// End-to-end tests of how `kerf` reports a bad model: exit code 2, `FILE:LINE:COL: error:`
// diagnostics on stderr with the source line and a caret, several per run, no output file.
// (The language's own diagnostics are tested in depth in tests/lang/.)
#include "kerf_runner.h"

#include <catch2/catch.hpp>

#include <regex>

using namespace kerf::test;

namespace {

struct BadModel {
    const char* what;
    const char* text;
    const char* expected;  ///< a regular expression stderr must contain
};

const BadModel kBadModels[] = {
    {"undefined name", "material red { color <1, 0, 0> }\nobject teapot material red;\n",
     R"(bad\.kerf:2:8: error: )"},
    {"stray character", "let a = 1 $ 2;\n", R"(bad\.kerf:1:11: error: )"},
    {"unknown property", "object sphere { centre <0, 0, 0> radius 1 };\n",
     R"(bad\.kerf:1:17: error: [^\n]*centre)"},
    {"negative radius", "\nobject sphere { radius -1 };\n", R"(bad\.kerf:2:\d+: error: )"},
    {"division by zero", "let a = 1 / 0;\nobject sphere { radius a };\n",
     R"(bad\.kerf:\d+:\d+: error: )"},
    {"unterminated comment", "object sphere { radius 1 };\n/* never closed\n",
     R"(bad\.kerf:2:\d+: error: )"},
    {"missing include", "include \"nowhere.kerf\";\n",
     R"(bad\.kerf:1:\d+: error: [^\n]*nowhere\.kerf)"},
    {"a solid made of itself", "solid a = union { sphere { radius 1 } a };\nobject a;\n",
     R"(bad\.kerf:1:\d+: error: )"},
    {"binary garbage", "\x01\x02\xff\xfe object\x7f", R"(bad\.kerf:1:\d+: error: )"},
};

}  // namespace

TEST_CASE("kerf render/check: bad models exit 2 with FILE:LINE:COL diagnostics") {
    // Both commands share the loading code; `render` is run on a few to keep the test fast.
    int index = 0;
    for (const BadModel& bad : kBadModels) {
        const bool alsoRender = index++ % 3 == 0;
        for (const char* command : {"check", "render"}) {
            if (!alsoRender && std::string(command) == "render") continue;
            TempDir dir;
            dir.write("bad.kerf", bad.text);
            const KerfRun run = runKerf(dir, {command, "bad.kerf"});
            INFO(command << ": " << bad.what << "\nstderr:\n" << run.err);
            CHECK(run.exitCode == 2);
            CHECK(std::regex_search(run.err, std::regex(bad.expected)));
            CHECK(dir.listing() == std::vector<std::string>{"bad.kerf"});
        }
    }
}

TEST_CASE("kerf check: a diagnostic shows the source line and a caret under the column") {
    TempDir dir;
    dir.write("bad.kerf", "material red { color <1, 0, 0> }\nobject   teapot material red;\n");
    const KerfRun run = runKerf(dir, {"check", "bad.kerf"});
    INFO("stderr:\n" << run.err);
    REQUIRE(run.exitCode == 2);
    CHECK(std::regex_search(run.err, std::regex(R"(bad\.kerf:2:10: error: [^\n]*teapot)")));
    // The offending line, then a caret under column 10 (9 characters before it).
    CHECK(std::regex_search(run.err, std::regex(R"(object   teapot material red;\n\s{9}\^)")));
}

TEST_CASE("kerf check: several errors in one run") {
    TempDir dir;
    dir.write("bad.kerf", "object teapot;\nlet ok = 1;\nobject kettle;\n");
    const KerfRun run = runKerf(dir, {"check", "bad.kerf"});
    INFO("stderr:\n" << run.err);
    CHECK(run.exitCode == 2);
    CHECK(std::regex_search(run.err, std::regex(R"(bad\.kerf:1:8: error: [^\n]*teapot)")));
    CHECK(std::regex_search(run.err, std::regex(R"(bad\.kerf:3:8: error: [^\n]*kettle)")));
}

TEST_CASE("kerf render/check: an unreadable model file is named") {
    TempDir dir;
    fs::create_directory(dir.path() / "folder.kerf");
    for (const char* command : {"render", "check"}) {
        for (const char* model : {"absent.kerf", "folder.kerf"}) {
            const KerfRun run = runKerf(dir, {command, model});
            INFO(command << " " << model << "\nstderr:\n" << run.err);
            CHECK(run.exitCode == 2);
            CHECK(run.err.find(std::string("kerf: error: cannot read model file '") + model +
                               "'") != std::string::npos);
        }
    }
}
