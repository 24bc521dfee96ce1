/// @file tests/app/kerf_runner.h
/// @brief Helpers for the end-to-end tests: a temporary directory, and running the built
/// `kerf` binary in it with its exit code, stdout and stderr captured. Header-only because
/// the test build compiles only *_test.cpp files.
#pragma once

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <sys/wait.h>

namespace kerf::test {

/// A unit sphere at 16 × 12: the smallest model that renders, for tests about outputs.
inline const char* kTinySphereModel = R"(object sphere { center <0, 0, 0> radius 1 };
camera { eye <0, 0, -5> look_at <0, 0, 0> up <0, 1, 0> fov 40 }
render { width 16 height 12 spp 1 }
)";

namespace fs = std::filesystem;

/// A fresh directory under the system temp folder, removed with everything in it on scope exit.
class TempDir {
public:
    TempDir() {
        std::string pattern = (fs::temp_directory_path() / "kerf_app_test_XXXXXX").string();
        if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
        mPath = pattern;
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(mPath, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const fs::path& path() const { return mPath; }
    std::string file(const std::string& name) const { return (mPath / name).string(); }

    /// Writes `text` to `name` inside the directory; returns the full path.
    std::string write(const std::string& name, const std::string& text) const {
        const fs::path p = mPath / name;
        fs::create_directories(p.parent_path());
        std::ofstream(p, std::ios::binary) << text;
        return p.string();
    }

    /// The names of the entries directly inside the directory, sorted.
    std::vector<std::string> listing() const {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(mPath)) {
            names.push_back(entry.path().filename().string());
        }
        std::sort(names.begin(), names.end());
        return names;
    }

private:
    fs::path mPath;
};

inline std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// Quotes one argument for /bin/sh.
inline std::string shellQuote(const std::string& arg) {
    std::string quoted = "'";
    for (char c : arg) {
        if (c == '\'') {
            quoted += "'\\''";
        } else {
            quoted += c;
        }
    }
    return quoted + "'";
}

struct KerfRun {
    int exitCode = -1;
    std::string out;  ///< stdout
    std::string err;  ///< stderr
};

/// Runs the built kerf with `args` in the working directory `cwd`, stdin from /dev/null and
/// stdout/stderr redirected to files (so stderr is not a terminal: no progress bar).
/// `environment` ("NAME=value ...", already quoted) is put before the command.
inline KerfRun runKerf(const TempDir& cwd, const std::vector<std::string>& args,
                       const std::string& environment = "") {
    const std::string outPath = (cwd.path() / ".stdout").string();
    const std::string errPath = (cwd.path() / ".stderr").string();
    std::string command = "cd " + shellQuote(cwd.path().string()) + " && " + environment + " " +
                          shellQuote(KERF_BINARY);
    for (const std::string& arg : args) command += " " + shellQuote(arg);
    command += " </dev/null >" + shellQuote(outPath) + " 2>" + shellQuote(errPath);
    const int status = std::system(command.c_str());
    KerfRun run;
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.out = readFile(outPath);
    run.err = readFile(errPath);
    fs::remove(outPath);
    fs::remove(errPath);
    return run;
}

/// The folder of the repository's models.
inline fs::path modelsDir() { return fs::path(KERF_SOURCE_DIR) / "models"; }
/// The folder of stored reference images.
inline fs::path testDataDir() { return fs::path(KERF_SOURCE_DIR) / "tests" / "data"; }

}  // namespace kerf::test
