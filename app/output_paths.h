/// @file app/output_paths.h
/// @brief Where `kerf render` writes: the colour image and the AOVs, resolved and checked
/// before any work so a run never writes over its input nor over one of its own outputs.
#pragma once

#include "scene/assets.h"

#include <string>
#include <vector>

namespace kerf::app {

/// An arbitrary output variable requested with `--aov KIND=FILE`.
struct AovRequest {
    enum class Kind { Depth, Normal };
    Kind kind = Kind::Depth;
    std::string path;
};

struct OutputPlan {
    std::string color;             ///< the colour image
    std::vector<AovRequest> aovs;  ///< in the order given
};

/// The default colour output: the model's base name with `.png`, in the current directory.
std::string defaultOutputPath(const std::string& modelPath);

/// Parses one `--aov` value (`depth=F.exr`, `normal=F.exr`). Throws UsageError naming
/// `--aov` for an unknown kind, a missing `=` or file, or a non-float format.
AovRequest parseAovSpec(const std::string& spec);

/// Throws UsageError when the colour output has an extension kerf cannot write or no name
/// before it (`-o .png`), when a kind is requested twice, or when any output is the model
/// file or another output (compared as canonical paths, and as the same file when both
/// exist).
void checkOutputPlan(const OutputPlan& plan, const std::string& modelPath);

/// Throws FileWriteError (exit 1, like a write that fails later) when any output cannot be
/// written: its folder is missing or not writable, or it is a folder. Called before the model
/// is compiled, so no work is done for a run whose result could not be kept.
void checkOutputsWritable(const OutputPlan& plan);

/// Throws UsageError when `output` (written through `option`, "-o") is a file the model read: a
/// mesh, level set, fog volume, texture or font (`inputs`, the asset provider's list). Called
/// after the compile, before any work, so a run never writes over what it reads.
void checkNotAnInput(const std::string& option, const std::string& output,
                     const std::vector<AssetFile>& inputs);
/// checkNotAnInput for the colour output and every AOV of the plan.
void checkPlanNotInputs(const OutputPlan& plan, const std::vector<AssetFile>& inputs);

/// "output 'F' has no file name before the extension" when the file name is only a known
/// image extension (".png"), else "".
std::string missingStem(const std::string& path);

/// The file's extension in lower case with its dot (".png"), or "" when it has none.
std::string lowerExtension(const std::string& path);

/// True when the two paths name the same file (existing or not).
bool samePath(const std::string& a, const std::string& b);

}  // namespace kerf::app
