/// @file app/frame_sequence.h
/// @brief `kerf render … --frames A-B [--sequence F-L] [-o out/turntable_%04d.png]`: renders
/// each frame as an independent image through the single-image path (runRender with the
/// frame's values and output names), so every option of that path (sections, AOVs, regions)
/// applies to each frame, and a farm can split a sequence by giving each job its own range.
#pragma once

#include "app/cli_render.h"
#include "lang/sequence_frame.h"

#include <functional>

namespace CLI {
class App;
}  // namespace CLI

namespace kerf::app {

/// Adds --frames and --sequence to the `render` subcommand, parsing into `line`.
void addFrameOptions(CLI::App& render, RenderCommandLine& line);

/// True when `line` asks for a sequence and is not itself one frame of it. Throws UsageError
/// for --sequence without --frames.
bool wantsFrameSequence(const RenderCommandLine& line);

/// `frame` and `time` of frame `n` of the sequence first..last: time = (n − first) / count.
SequenceFrame sequenceFrame(int64_t n, int64_t first, int64_t count);

/// The frame loop. Checks the range, the output names (each needs one %d or %0Nd: the colour
/// output and every --aov file) and, for every frame, that its outputs can be written; then
/// for each frame calls `renderOne` with a copy of `line` holding the frame's values and
/// names, printing a line per frame (unless --quiet) and a header before each frame's --stats.
/// Stops at the first frame that fails and returns its exit code. Throws UsageError for bad
/// options.
int renderFrames(const RenderCommandLine& line,
                 const std::function<int(const RenderCommandLine&)>& renderOne);

}  // namespace kerf::app
