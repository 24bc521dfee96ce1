/// @file app/frame_sequence.cpp
#include "app/frame_sequence.h"

#include "app/exit_codes.h"
#include "app/numbered_names.h"
#include "app/output_paths.h"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>

namespace kerf::app {

namespace {

/// Each frame's names are made and checked before the first is rendered; this bounds that list.
constexpr int64_t kMaxFramesPerRun = 100000;

/// The default name of a sequence's images: the model's base name, `_%04d.png`, here (a
/// percent sign in the model's name is doubled so it stays literal).
std::string defaultFramePattern(const std::string& model) {
    const std::string single = defaultOutputPath(model);  // "stem.png"
    std::string stem = std::filesystem::path(single).stem().string();
    std::string escaped;
    for (char c : stem) escaped += c == '%' ? std::string("%%") : std::string(1, c);
    return escaped + "_%04d.png";
}

/// "depth=out/d_%04d.exr" with the number filled in: "depth=out/d_0007.exr".
std::string expandAovSpec(const std::string& spec, int64_t n) {
    const size_t eq = spec.find('=');
    return spec.substr(0, eq + 1) + expandNumberPattern(spec.substr(eq + 1), n);
}

}  // namespace

void addFrameOptions(CLI::App& render, RenderCommandLine& line) {
    line.framesOption =
        render
            .add_option("--frames", line.frames,
                        "Render a sequence: frames A to B (or the one frame N), each compiled with "
                        "the model's "
                        "`frame` = its number and `time` = (frame - first) / count; -o and each "
                        "--aov file need "
                        "a %04d-style number (default: the model's name with _%04d.png)")
            ->type_name("A-B|N");
    line.sequenceOption = render
                              .add_option("--sequence", line.sequence,
                                          "With --frames: the whole sequence `time` runs across "
                                          "(default: the --frames range); a "
                                          "farm that splits 1-240 into jobs gives each its "
                                          "--frames part and --sequence 1-240")
                              ->type_name("A-B");
}

bool wantsFrameSequence(const RenderCommandLine& line) {
    if (line.frame) return false;  // already one frame of a sequence
    const bool frames = line.framesOption && line.framesOption->count() > 0;
    if (!frames && line.sequenceOption && line.sequenceOption->count() > 0)
        throw UsageError("--sequence goes with --frames (it says which frames `time` runs across)");
    return frames;
}

SequenceFrame sequenceFrame(int64_t n, int64_t first, int64_t count) {
    SequenceFrame f;
    f.frame = n;
    f.time = double(n - first) / double(count);
    return f;
}

int renderFrames(const RenderCommandLine& line,
                 const std::function<int(const RenderCommandLine&)>& renderOne) {
    const NumberRange frames = parseNumberRange(line.frames, "--frames");
    if (frames.count() > kMaxFramesPerRun)
        throw UsageError("--frames " + line.frames + ": at most " +
                         std::to_string(kMaxFramesPerRun) +
                         " frames in one run; split the range into jobs (see --sequence)");
    NumberRange sequence = frames;
    if (line.sequenceOption && line.sequenceOption->count() > 0) {
        sequence = parseNumberRange(line.sequence, "--sequence");
        if (!sequence.contains(frames.first) || !sequence.contains(frames.last))
            throw UsageError("--frames " + line.frames + " is not inside --sequence " +
                             line.sequence);
    }
    const bool outputGiven = line.outputOption && line.outputOption->count() > 0;
    const std::string pattern = outputGiven ? line.output : defaultFramePattern(line.model);
    checkNumberPattern(pattern, "-o");
    for (const std::string& spec : line.aovs) {
        const AovRequest aov = parseAovSpec(spec);  // names --aov for a bad kind or file
        checkNumberPattern(aov.path, "--aov");
    }

    // Every frame's outputs are checked before the first is rendered: a sequence that cannot
    // be kept is refused before any work, as a single image is.
    std::vector<RenderCommandLine> lines;
    lines.reserve(size_t(frames.count()));
    for (int64_t n = frames.first; n <= frames.last; ++n) {
        RenderCommandLine one = line;
        one.frame = sequenceFrame(n, sequence.first, sequence.count());
        one.output = expandNumberPattern(pattern, n);
        one.aovs.clear();
        OutputPlan plan;
        plan.color = one.output;
        for (const std::string& spec : line.aovs) {
            one.aovs.push_back(expandAovSpec(spec, n));
            plan.aovs.push_back(parseAovSpec(one.aovs.back()));
        }
        checkOutputPlan(plan, line.model);
        checkOutputsWritable(plan);
        lines.push_back(std::move(one));
    }

    for (size_t i = 0; i < lines.size(); ++i) {
        const RenderCommandLine& one = lines[i];
        if (!line.quiet || line.stats)
            std::cerr << "kerf: frame " << one.frame->frame << " (" << i + 1 << " of "
                      << lines.size() << ", time " << one.frame->time << "): " << one.output
                      << "\n";
        const int code = renderOne(one);
        if (code != kExitSuccess) {
            std::cerr << "kerf: error: frame " << one.frame->frame << " failed";
            if (i > 0)
                std::cerr << "; frames " << frames.first << " to " << one.frame->frame - 1
                          << " were written";
            std::cerr << "\n";
            return code;
        }
    }
    return kExitSuccess;
}

}  // namespace kerf::app
