// Failed writes for real: a full disk (ENOSPC) and a signal in the middle of a write, made by
// the fault-injection shim (tests/fault/write_fault.cpp) loaded into a kerf subprocess. After
// each, the earlier output must be byte-identical, no temporary file may remain, and the
// message must name the file and say why.
#include "child_process.h"

#include <catch2/catch.hpp>

#include <signal.h>

using namespace kerf::test;

namespace {

/// Renders `output` once without faults: the earlier good file a failed run must keep.
std::string renderEarlier(const TempDir& dir, const std::vector<std::string>& extraArgs) {
    std::vector<std::string> args = {"render", "tiny.kerf", "-q"};
    args.insert(args.end(), extraArgs.begin(), extraArgs.end());
    const KerfRun run = runKerf(dir, args);
    INFO("stderr:\n" << run.err);
    REQUIRE(run.exitCode == 0);
    return run.err;
}

}  // namespace

TEST_CASE("kerf render on a full disk keeps the earlier image, for every format") {
    for (const std::string ext : {"png", "jpg", "exr", "tif"}) {
        DYNAMIC_SECTION(ext) {
            TempDir dir;
            dir.write("tiny.kerf", kTinySphereModel);
            const std::string name = "out." + ext;
            renderEarlier(dir, {"-o", name});
            const std::string earlier = readFile(dir.file(name));
            REQUIRE(!earlier.empty());

            // A different image, so a truncated or new file could not pass for the old one.
            Environment env = faultEnvironment(name);
            env.push_back({"KERF_FAULT_AFTER", "64"});  // the disk fills mid-file
            KerfChild child(dir, {"render", "tiny.kerf", "-q", "-o", name, "--width", "20"}, env);
            REQUIRE(child.wait());
            const std::string err = child.err();
            INFO("stderr:\n" << err);
            CHECK(child.exitCode() == 1);
            CHECK(err == "kerf: error: cannot write '" + name + "': No space left on device\n");
            CHECK(readFile(dir.file(name)) == earlier);
            CHECK(dir.listing() == std::vector<std::string>{name, "tiny.kerf"});
        }
    }
}

TEST_CASE("kerf render on a full disk: an AOV keeps its earlier file") {
    TempDir dir;
    dir.write("tiny.kerf", kTinySphereModel);
    renderEarlier(dir, {"-o", "out.png", "--aov", "depth=depth.exr"});
    const std::string earlier = readFile(dir.file("depth.exr"));

    Environment env = faultEnvironment("depth.exr");
    env.push_back({"KERF_FAULT_AFTER", "0"});  // no room at all
    KerfChild child(
        dir,
        {"render", "tiny.kerf", "-q", "-o", "out.png", "--aov", "depth=depth.exr", "--width", "20"},
        env);
    REQUIRE(child.wait());
    const std::string err = child.err();
    INFO("stderr:\n" << err);
    CHECK(child.exitCode() == 1);
    CHECK(err == "kerf: error: cannot write 'depth.exr': No space left on device\n");
    CHECK(readFile(dir.file("depth.exr")) == earlier);
    CHECK(dir.listing() == std::vector<std::string>{"depth.exr", "out.png", "tiny.kerf"});
}

TEST_CASE("failures the write calls do not show: at fsync, or bytes lost") {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"KERF_FAULT_FSYNC", "kerf: error: cannot write 'out.png': Input/output error\n"},
        {"KERF_FAULT_DROP",
         "kerf: error: cannot write 'out.png': the file holds 0 bytes instead of "}};
    for (const auto& [variable, message] : cases) {
        DYNAMIC_SECTION(variable) {
            TempDir dir;
            dir.write("tiny.kerf", kTinySphereModel);
            renderEarlier(dir, {"-o", "out.png"});
            const std::string earlier = readFile(dir.file("out.png"));

            Environment env = faultEnvironment("out.png");
            env.push_back({variable, "1"});
            KerfChild child(dir, {"render", "tiny.kerf", "-q", "-o", "out.png", "--width", "20"},
                            env);
            REQUIRE(child.wait());
            INFO("stderr:\n" << child.err());
            CHECK(child.exitCode() == 1);
            CHECK(child.err().rfind(message, 0) == 0);
            CHECK(readFile(dir.file("out.png")) == earlier);
            CHECK(dir.listing() == std::vector<std::string>{"out.png", "tiny.kerf"});
        }
    }
}

TEST_CASE("kerf bench accuracy on a full disk keeps the earlier CSV") {
    TempDir dir;
    fs::create_directory(dir.path() / "out");
    const std::string earlier = dir.write("out/accuracy.csv", "an earlier table\n");
    const std::string sceneDir = (fs::path(KERF_SOURCE_DIR) / "accuracy" / "scenes").string();

    Environment env = faultEnvironment("accuracy.csv");
    env.push_back({"KERF_FAULT_AFTER", "10"});
    KerfChild child(dir,
                    {"bench", "accuracy", "--quick", "--out", "out", "--scene-dir", sceneDir,
                     "--scenes", "sphere", "--methods", "closed", "--width", "8", "--height", "6"},
                    env);
    REQUIRE(child.wait());
    const std::string err = child.err();
    INFO("stderr:\n" << err);
    CHECK(child.exitCode() == 1);
    CHECK(err.find("kerf: error: cannot write 'out/accuracy.csv': No space left on device\n") !=
          std::string::npos);
    CHECK(readFile(earlier) == "an earlier table\n");
    std::vector<std::string> left;
    for (const auto& entry : fs::directory_iterator(dir.path() / "out"))
        left.push_back(entry.path().filename().string());
    CHECK(left == std::vector<std::string>{"accuracy.csv"});
}

TEST_CASE("a signal during the write removes the temporary and keeps the earlier image") {
    for (const int sig : {SIGTERM, SIGINT}) {
        DYNAMIC_SECTION((sig == SIGTERM ? "SIGTERM" : "SIGINT")) {
            TempDir dir;
            TempDir side;  // the shim's marker lives apart, out of the listing
            dir.write("tiny.kerf", kTinySphereModel);
            renderEarlier(dir, {"-o", "out.png"});
            const std::string earlier = readFile(dir.file("out.png"));

            const std::string marker = side.file("stalled");
            Environment env = faultEnvironment("out.png");
            env.push_back({"KERF_FAULT_STALL", marker});
            KerfChild child(dir, {"render", "tiny.kerf", "-q", "-o", "out.png", "--width", "20"},
                            env);
            // Wait (bounded) until kerf is inside the write of the temporary.
            for (int i = 0; i < 12000 && !fs::exists(marker); ++i) ::usleep(10000);
            REQUIRE(fs::exists(marker));
            ::kill(child.pid(), sig);
            REQUIRE(child.wait());
            INFO("stderr:\n" << child.err());
            CHECK(child.signal() == sig);  // it still dies of the signal, as without kerf's handler
            CHECK(readFile(dir.file("out.png")) == earlier);
            CHECK(dir.listing() == std::vector<std::string>{"out.png", "tiny.kerf"});
        }
    }
}
