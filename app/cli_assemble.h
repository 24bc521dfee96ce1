/// @file app/cli_assemble.h
/// @brief `kerf assemble OUT PART…`: stitches the region images of `kerf render --region`
/// (EXR or TIFF files, each holding its place in the full image) into the full image, after
/// checking that they share one full image and cover it exactly once.
#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;
}  // namespace CLI

namespace kerf::app {

struct AssembleCommandLine {
    std::string output;
    std::vector<std::string> parts;
};

/// Adds the `assemble` subcommand to `parent`, parsing into `line` (which must outlive parsing).
CLI::App* addAssembleCommand(CLI::App& parent, AssembleCommandLine& line);

/// Runs the command; returns the exit code. Throws UsageError for a bad or unreadable part,
/// parts of different images, parts that overlap or leave a hole (naming the pair, or the
/// missing rectangles), and an output that is a part; FileWriteError when OUT cannot be
/// written.
int runAssemble(const AssembleCommandLine& line);

}  // namespace kerf::app
