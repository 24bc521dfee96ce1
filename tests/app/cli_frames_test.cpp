// `kerf render --frames`: the files a sequence writes, each equal bit for bit to a single
// render of a model with that frame's `frame` and `time` written in as numbers; a farm's part
// (--sequence) equal to the same frame of the whole; bad ranges and names refused with exit 2
// before anything is written.
#include "app/kerf_runner.h"

#include <catch2/catch.hpp>

using namespace kerf::test;

namespace {

/// A sphere whose radius and colour follow `frame` and `time` (written in by `withValues`).
std::string model(const std::string& frame, const std::string& time) {
    return "let f = " + frame + "; let t = " + time +
           ";\n"
           "material m { color <0.2 + t, 0.5, 0.9 - 0.1 * f> }\n"
           "object sphere { center <0, 0, 0> radius 0.5 + 0.2 * f + t } material m;\n"
           "camera { eye <0, 0, -6> look_at <0, 0, 0> up <0, 1, 0> fov 40 }\n"
           "light point { at <3, 4, -5> power 60 }\n"
           "render { width 24 height 16 spp 2 }\n";
}

}  // namespace

TEST_CASE("kerf render --frames 2-3 writes two files, each a single render of its frame") {
    TempDir dir;
    dir.write("seq.kerf", model("frame", "time"));
    const KerfRun run =
        runKerf(dir, {"render", "seq.kerf", "--frames", "2-3", "-o", "out_%03d.png", "-q"});
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    CHECK(dir.listing() == std::vector<std::string>{"out_002.png", "out_003.png", "seq.kerf"});

    // Frames 2 and 3 of the sequence 2-3: time 0 and 0.5.
    dir.write("f2.kerf", model("2", "0"));
    dir.write("f3.kerf", model("3", "0.5"));
    REQUIRE(runKerf(dir, {"render", "f2.kerf", "-o", "single2.png", "-q"}).exitCode == 0);
    REQUIRE(runKerf(dir, {"render", "f3.kerf", "-o", "single3.png", "-q"}).exitCode == 0);
    const std::string frame2 = readFile(dir.file("out_002.png"));
    const std::string frame3 = readFile(dir.file("out_003.png"));
    REQUIRE(!frame2.empty());
    CHECK(frame2 != frame3);  // the frames differ, so the comparisons below can fail
    CHECK(frame2 == readFile(dir.file("single2.png")));
    CHECK(frame3 == readFile(dir.file("single3.png")));
}

TEST_CASE("kerf render --frames N --sequence A-B is the same frame as in the whole sequence") {
    TempDir dir;
    dir.write("seq.kerf", model("frame", "time"));
    REQUIRE(runKerf(dir, {"render", "seq.kerf", "--frames", "0-3", "-o", "all_%d.png", "-q"})
                .exitCode == 0);
    // A farm job with one frame of the four: the same `time` (0.5), the same bits.
    const KerfRun part = runKerf(dir, {"render", "seq.kerf", "--frames", "2", "--sequence", "0-3",
                                       "-o", "part_%d.png", "-q"});
    INFO(part.err);
    REQUIRE(part.exitCode == 0);
    CHECK(readFile(dir.file("part_2.png")) == readFile(dir.file("all_2.png")));
    CHECK(!fs::exists(dir.file("part_3.png")));
    // Without --sequence the one frame is a sequence of its own: time 0, a different image.
    REQUIRE(runKerf(dir, {"render", "seq.kerf", "--frames", "2", "-o", "alone_%d.png", "-q"})
                .exitCode == 0);
    CHECK(readFile(dir.file("alone_2.png")) != readFile(dir.file("all_2.png")));
}

TEST_CASE("kerf render --frames names every frame's AOV files and the default name") {
    TempDir dir;
    dir.write("seq.kerf", model("frame", "time"));
    const KerfRun run =
        runKerf(dir, {"render", "seq.kerf", "--frames", "7-8", "--aov", "depth=d_%02d.exr", "-q"});
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    CHECK(dir.listing() == std::vector<std::string>{"d_07.exr", "d_08.exr", "seq.kerf",
                                                    "seq_0007.png", "seq_0008.png"});
    // %% is a literal percent sign; %0Nd pads to N digits, and a longer number is not cut.
    dir.write("tiny.kerf", kTinySphereModel);
    REQUIRE(runKerf(dir, {"render", "tiny.kerf", "--frames", "1", "-o", "p%%_%02d.png", "-q"})
                .exitCode == 0);
    REQUIRE(runKerf(dir, {"render", "tiny.kerf", "--frames", "123", "-o", "q_%02d.png", "-q"})
                .exitCode == 0);
    CHECK(fs::exists(dir.file("p%_01.png")));
    CHECK(fs::exists(dir.file("q_123.png")));
}

TEST_CASE("kerf render --frames refuses bad ranges and names with exit code 2, writing nothing") {
    TempDir dir;
    dir.write("seq.kerf", model("frame", "time"));
    struct Case {
        std::vector<std::string> args;
        std::string says;
    };
    const std::vector<Case> cases = {
        {{"--frames", "3-2", "-o", "o_%d.png"}, "--frames: the range 3-2 is empty"},
        {{"--frames", "-1", "-o", "o_%d.png"}, "--frames expects A-B or N"},
        {{"--frames", "1-x", "-o", "o_%d.png"}, "--frames expects A-B or N"},
        {{"--frames", "", "-o", "o_%d.png"}, "--frames expects A-B or N"},
        {{"--frames", "0-200000", "-o", "o_%d.png"}, "at most 100000 frames"},
        {{"--frames", "1-2", "-o", "o.png"}, "-o: the name needs exactly one %d"},
        {{"--frames", "1-2", "-o", "o_%d_%d.png"}, "-o: the name needs exactly one %d"},
        {{"--frames", "1-2", "-o", "o_%4d.png"}, "-o: the name needs exactly one %d"},
        {{"--frames", "1-2", "-o", "o_%s.png"}, "-o: the name needs exactly one %d"},
        {{"--frames", "1-2", "-o", "o_%d.txt"}, "cannot write 'o_1.txt' (use .png"},
        {{"--frames", "1-2", "-o", "o_%d.png", "--aov", "depth=d.exr"},
         "--aov: the name needs exactly one %d"},
        {{"--frames", "1-5", "--sequence", "2-9", "-o", "o_%d.png"},
         "is not inside --sequence 2-9"},
        {{"--sequence", "1-9", "-o", "o.png"}, "--sequence goes with --frames"},
    };
    for (const Case& c : cases) {
        std::vector<std::string> args{"render", "seq.kerf"};
        args.insert(args.end(), c.args.begin(), c.args.end());
        const KerfRun run = runKerf(dir, args);
        INFO(c.args[0] << " " << c.args[1] << "\nstderr: " << run.err);
        CHECK(run.exitCode == 2);
        CHECK(run.err.find(c.says) != std::string::npos);
        CHECK(dir.listing() == std::vector<std::string>{"seq.kerf"});
    }
}

TEST_CASE(
    "kerf render --frames with a model that fails at one frame stops there with exit code 2") {
    TempDir dir;
    // The radius is 1 − frame: positive at frame 0, zero (an error) at frame 1.
    dir.write("seq.kerf",
              "object sphere { radius 1 - frame };\n"
              "camera { eye <0, 0, -5> look_at <0, 0, 0> up <0, 1, 0> fov 40 }\n"
              "render { width 8 height 8 spp 1 }\n");
    const KerfRun run =
        runKerf(dir, {"render", "seq.kerf", "--frames", "0-2", "-o", "o_%d.png", "-q"});
    INFO(run.err);
    CHECK(run.exitCode == 2);
    CHECK(run.err.find("seq.kerf:1:") != std::string::npos);
    CHECK(run.err.find("frame 1 failed") != std::string::npos);
    CHECK(dir.listing() == std::vector<std::string>{"o_0.png", "seq.kerf"});
}
