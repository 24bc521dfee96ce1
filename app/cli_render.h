/// @file app/cli_render.h
/// @brief `kerf render FILE [-o OUT] [--width W] [--height H] [--spp N] [--threads T]
/// [--tolerance E] [--method M] [--aov KIND=FILE]… [--section PLANE]… [--stats] [--quiet]
/// [--frames A-B [--sequence F-L]]`.
#pragma once

#include "lang/sequence_frame.h"

#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace kerf::app {

/// The command line of `kerf render` as parsed; the option pointers tell which flags were
/// given (a flag that was not given leaves the model's `render { }` value in force).
struct RenderCommandLine {
    std::string model;
    std::string output;
    int width = 0;
    int height = 0;
    int spp = 0;
    int threads = 0;
    double tolerance = 0;
    std::string method = "closed";
    std::string accel = "auto";
    int accelDepth = 0;
    std::string beams = "auto";
    std::string sampler;  ///< empty: the model's render settings
    std::string filter;   ///< empty: the model's render settings
    double noise = -1.0;  ///< < 0: the model's render settings
    std::vector<std::string> aovs;
    std::string frames;  ///< --frames A-B or N: a sequence (app/frame_sequence.h); empty: one image
    std::string sequence;  ///< --sequence A-B: the frames `time` runs across; empty: --frames
    /// Set by the frame loop for each frame it hands to runRender: the model's `frame` and
    /// `time`, with `output` and `aovs` already that frame's file names.
    std::optional<SequenceFrame> frame;
    std::vector<std::string> sections;  ///< section planes added to the model's (x=V, …)
    std::string sectionColor;           ///< their caps' colour R,G,B; empty: the default
    bool stats = false;
    bool quiet = false;
    std::string region;  ///< --region X0,Y0,X1,Y1 (when regionOption was given)

    CLI::Option* outputOption = nullptr;
    CLI::Option* framesOption = nullptr;
    CLI::Option* sequenceOption = nullptr;
    CLI::Option* noiseOption = nullptr;
    CLI::Option* widthOption = nullptr;
    CLI::Option* heightOption = nullptr;
    CLI::Option* sppOption = nullptr;
    CLI::Option* threadsOption = nullptr;
    CLI::Option* toleranceOption = nullptr;
    CLI::Option* regionOption = nullptr;
};

/// Adds the `render` subcommand to `parent`, parsing into `line` (which must outlive parsing).
CLI::App* addRenderCommand(CLI::App& parent, RenderCommandLine& line);

/// Runs the command; returns the exit code. Throws UsageError for bad options and lets
/// FileWriteError (an output that cannot be written, found before tracing or when writing)
/// and other failures through to main().
int runRender(const RenderCommandLine& line);

}  // namespace kerf::app
