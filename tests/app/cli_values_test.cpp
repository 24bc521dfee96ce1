/// @file tests/app/cli_values_test.cpp
/// @brief The value policy end to end (docs/robustness.md, "Values"): the issue's models that
/// gave +inf pixels or never finished are refused with exit code 2 and no image, and a
/// mirror box the policy accepts renders at max_depth 1000 with its rays counted by --stats.
#include "kerf_runner.h"

#include <catch2/catch.hpp>

#include <regex>

using namespace kerf::test;

namespace {

std::string statsLine(const std::string& text, const std::string& label) {
    std::smatch match;
    if (!std::regex_search(text, match, std::regex("\\n\\s*" + label + "\\s+([^\\n]*)\\n")))
        return "<absent>";
    return match[1].str();
}

constexpr const char* kMirrorBox = R"(material m { color <1, 1, 1> reflect %R% }
camera { eye <0, 0, 0> look_at <0.3, 0.2, 1> }
light point { at <0, 0.5, 0> power 10 }
render { width 4 height 3 max_depth 1000 }
object difference { box { min <-2, -2, -2> max <2, 2, 2> } box { min <-1, -1, -1> max <1, 1, 1> } } material m;
)";

std::string mirrorBox(const std::string& reflect) {
    return std::regex_replace(kMirrorBox, std::regex("%R%"), reflect);
}

}  // namespace

TEST_CASE("kerf render: weights that add energy are refused at the property") {
    TempDir dir;
    dir.write("mirror.kerf", mirrorBox("2"));
    dir.write("glass.kerf",
              "material g { color <1, 1, 1> transmit 1 reflect 1 ior 1.5 }\n"
              "object sphere {} material g;\nrender { max_depth 1000 }\n");
    const KerfRun mirror = runKerf(dir, {"render", "mirror.kerf", "-o", "mirror.png"});
    INFO(mirror.err);
    CHECK(mirror.exitCode == 2);
    CHECK(mirror.err.find("mirror.kerf:1:38: error: material reflect must be at most 1, got 2") !=
          std::string::npos);
    const KerfRun glass = runKerf(dir, {"render", "glass.kerf", "-o", "glass.png"});
    INFO(glass.err);
    CHECK(glass.exitCode == 2);
    CHECK(glass.err.find("glass.kerf:1:49: error: material reflect + transmit must be at most 1") !=
          std::string::npos);
    CHECK_FALSE(fs::exists(dir.file("mirror.png")));
    CHECK_FALSE(fs::exists(dir.file("glass.png")));
}

TEST_CASE("kerf render --stats: a mirror box with reflect 1 at max_depth 1000") {
    TempDir dir;
    dir.write("mirror.kerf", mirrorBox("1"));
    const KerfRun run = runKerf(dir, {"render", "mirror.kerf", "-o", "mirror.exr", "--stats"});
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    CHECK(statsLine(run.err, "camera rays") == "12");
    CHECK(statsLine(run.err, "reflection rays") == "12000");  // every bounce, none cut
}
