// End-to-end tests of the limits (scene/limits.h): models that are not regular files, flags
// above the model's own caps, and chains of named solids too deep to trace, each an error
// with exit code 2 instead of a hang or a crash; a chain at the depth limit renders.
#include "kerf_runner.h"

#include "scene/limits.h"

#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <algorithm>
#include <cstdlib>

using namespace kerf::test;

namespace {

const char* kScene =
    "camera { eye <0, 0, -5> look_at <0, 0, 0> }\nlight point { at <2, 3, -4> power 60 }\n";

/// s0 a sphere, s<i> = s<i-1> minus a small sphere, n definitions in file order or reversed,
/// then `object s<n-1>`. The definition of s<i> is on line lineOf(i).
struct Chain {
    int n;
    bool reversed;
    int lineOf(int i) const { return reversed ? n - i : i + 1; }
    std::string text() const {
        std::vector<std::string> lines{"solid s0 = sphere {};"};
        for (int i = 1; i < n; ++i)
            lines.push_back("solid s" + std::to_string(i) + " = difference { s" +
                            std::to_string(i - 1) + " sphere { center <" + std::to_string(i % 7) +
                            ", 0, -1> radius 0.05 } };");
        if (reversed) std::reverse(lines.begin(), lines.end());
        std::string t;
        for (const std::string& l : lines) t += l + "\n";
        return t + "object s" + std::to_string(n - 1) + ";\n" + kScene;
    }
};

}  // namespace

TEST_CASE("kerf check/render: a model that is not a regular file is refused unread") {
    TempDir dir;
    REQUIRE(::mkfifo(dir.file("pipe.kerf").c_str(), 0600) == 0);
    for (const char* command : {"check", "render"}) {
        for (const std::string& model : {std::string("/dev/zero"), std::string("pipe.kerf")}) {
            std::vector<std::string> args{command, model};
            if (std::string(command) == "render") args.insert(args.end(), {"-o", "x.png"});
            const KerfRun run = runKerf(dir, args);
            INFO(command << " " << model << "\nstderr:\n" << run.err);
            CHECK(run.exitCode == 2);
            CHECK(run.err.find("kerf: error: cannot read model file '" + model +
                               "': it is not a regular file") != std::string::npos);
        }
    }
}

TEST_CASE("kerf render: flags have the model's upper limits") {
    TempDir dir;
    dir.write("tiny.kerf", std::string("object sphere {};\n") + kScene);
    const auto refused = [&](const std::string& flag, const std::string& value) {
        const KerfRun run =
            runKerf(dir, {"render", "tiny.kerf", "-q", "-o", "out.png", flag, value});
        INFO(flag << " " << value << "\nstderr:\n" << run.err);
        CHECK(run.exitCode == 2);
        CHECK(run.err.find("kerf: error:") != std::string::npos);
        CHECK(run.err.find(flag) != std::string::npos);
        CHECK_FALSE(fs::exists(dir.path() / "out.png"));
    };
    refused("--spp", std::to_string(kerf::kMaxSamplesPerPixel + 1));
    refused("--spp", "2147483647");  // n·n overflowed an int on the way to 46341²
    refused("--width", std::to_string(kerf::kMaxImageSide + 1));
    refused("--height", std::to_string(kerf::kMaxImageSide + 1));
}

TEST_CASE(
    "kerf check/render: a chain of named solids too deep is an error at its line, in either "
    "order") {
    for (const bool reversed : {false, true}) {
        TempDir dir;
        const Chain chain{10000, reversed};
        dir.write("chain.kerf", chain.text());
        // s<kMaxNameDepth> is the first definition over the limit; its use of the previous
        // one is at column 28 ("solid s1000 = difference { " is 27 bytes).
        const std::string where =
            "chain.kerf:" + std::to_string(chain.lineOf(kerf::kMaxNameDepth)) + ":28: error:";
        for (const char* command : {"check", "render"}) {
            std::vector<std::string> args{command, "chain.kerf"};
            if (std::string(command) == "render")
                args.insert(args.end(), {"-q", "-o", "chain.png", "--width", "8"});
            const KerfRun run = runKerf(dir, args);
            INFO(command << " reversed " << reversed << "\nstderr:\n" << run.err);
            CHECK(run.exitCode == 2);
            CHECK(run.err.find(where) != std::string::npos);
            CHECK(run.err.find("nested too deeply") != std::string::npos);
        }
    }
}

TEST_CASE("kerf render: a chain at the depth limit renders") {
    for (const bool reversed : {false, true}) {
        TempDir dir;
        dir.write("chain.kerf", Chain{kerf::kMaxCsgDepth, reversed}.text());
        const KerfRun check = runKerf(dir, {"check", "chain.kerf"});
        INFO("stdout:\n" << check.out << "\nstderr:\n" << check.err);
        REQUIRE(check.exitCode == 0);
        CHECK(check.out.find("csg depth:   " + std::to_string(kerf::kMaxCsgDepth) + "\n") !=
              std::string::npos);
        // Several threads: tracing recurses once per level on each worker's own stack.
        // Sanitizer build: LeakSanitizer's own thread-stopping tracer dies of signal 11 at the
        // exit of this render when the test binary starts it (not a report about kerf; the same
        // command from a shell passes; not understood yet, docs/robustness.md). Leaks stay checked
        // by every other test; here only the leak scan is off.
        const char* asan = std::getenv("ASAN_OPTIONS");
        const std::string noLeakScan =
            "ASAN_OPTIONS=" +
            shellQuote((asan != nullptr ? std::string(asan) + ":" : "") + "detect_leaks=0");
        const KerfRun run = runKerf(dir,
                                    {"render", "chain.kerf", "-q", "-o", "chain.png", "--width",
                                     "16", "--height", "12", "--threads", "2"},
                                    noLeakScan);
        INFO("stderr:\n" << run.err);
        CHECK(run.exitCode == 0);
        CHECK(fs::exists(dir.path() / "chain.png"));
    }
}
