/// @file app/output_paths.cpp
#include "app/output_paths.h"

#include "app/exit_codes.h"
#include "io/atomic_file.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>

namespace fs = std::filesystem;

namespace kerf::app {

std::string lowerExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

namespace {

bool isFloatFormat(const std::string& ext) {
    return ext == ".exr" || ext == ".tif" || ext == ".tiff";
}

bool isWritableFormat(const std::string& ext) {
    return isFloatFormat(ext) || ext == ".png" || ext == ".jpg" || ext == ".jpeg";
}

const char* kindName(AovRequest::Kind kind) {
    return kind == AovRequest::Kind::Depth ? "depth" : "normal";
}

/// A path made absolute and normalised, with symbolic links resolved as far as it exists.
fs::path canonicalForm(const std::string& p) {
    std::error_code ec;
    fs::path result = fs::weakly_canonical(fs::absolute(p), ec);
    if (ec) result = fs::absolute(p).lexically_normal();
    return result;
}

}  // namespace

std::string missingStem(const std::string& path) {
    // std::filesystem reads ".png" as a hidden file without extension; the user meant an
    // image and forgot its name.
    std::string name = fs::path(path).filename().string();
    std::transform(name.begin(), name.end(), name.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (!isWritableFormat(name)) return "";
    return "output '" + path + "' has no file name before the extension";
}

void checkOutputsWritable(const OutputPlan& plan) {
    checkOutputWritable(plan.color);
    for (const AovRequest& aov : plan.aovs) checkOutputWritable(aov.path);
}

std::string defaultOutputPath(const std::string& modelPath) {
    return fs::path(modelPath).stem().string() + ".png";
}

AovRequest parseAovSpec(const std::string& spec) {
    const auto eq = spec.find('=');
    if (eq == std::string::npos) {
        throw UsageError("--aov expects KIND=FILE (e.g. depth=depth.exr), got '" + spec + "'");
    }
    const std::string kind = spec.substr(0, eq);
    AovRequest request;
    request.path = spec.substr(eq + 1);
    if (kind == "depth") {
        request.kind = AovRequest::Kind::Depth;
    } else if (kind == "normal") {
        request.kind = AovRequest::Kind::Normal;
    } else {
        throw UsageError("--aov: unknown kind '" + kind + "' (known kinds: depth, normal)");
    }
    if (request.path.empty()) throw UsageError("--aov " + kind + ": the file name is missing");
    if (const std::string stem = missingStem(request.path); !stem.empty())
        throw UsageError("--aov " + kind + ": " + stem);
    if (!isFloatFormat(lowerExtension(request.path))) {
        throw UsageError("--aov " + kind + ": '" + request.path +
                         "' must be a float image (.exr, .tif or .tiff)");
    }
    return request;
}

bool samePath(const std::string& a, const std::string& b) {
    std::error_code ec;
    if (fs::exists(a, ec) && fs::exists(b, ec)) {
        const bool same = fs::equivalent(a, b, ec);
        if (!ec) return same;
    }
    return canonicalForm(a) == canonicalForm(b);
}

void checkOutputPlan(const OutputPlan& plan, const std::string& modelPath) {
    if (const std::string stem = missingStem(plan.color); !stem.empty())
        throw UsageError("-o: " + stem);
    if (!isWritableFormat(lowerExtension(plan.color))) {
        throw UsageError("-o: cannot write '" + plan.color +
                         "' (use .png, .jpg, .jpeg, .exr, .tif or .tiff)");
    }
    if (samePath(plan.color, modelPath)) {
        throw UsageError("-o: the output '" + plan.color + "' is the model file itself");
    }
    for (size_t i = 0; i < plan.aovs.size(); ++i) {
        const AovRequest& aov = plan.aovs[i];
        const std::string option = std::string("--aov ") + kindName(aov.kind);
        if (samePath(aov.path, modelPath)) {
            throw UsageError(option + ": the output '" + aov.path + "' is the model file itself");
        }
        if (samePath(aov.path, plan.color)) {
            throw UsageError(option + ": the output '" + aov.path +
                             "' is also the colour output (-o)");
        }
        for (size_t j = 0; j < i; ++j) {
            if (plan.aovs[j].kind == aov.kind) {
                throw UsageError(option + " is given more than once");
            }
            if (samePath(aov.path, plan.aovs[j].path)) {
                throw UsageError(option + ": the output '" + aov.path + "' is also the --aov " +
                                 kindName(plan.aovs[j].kind) + " output");
            }
        }
    }
}

void checkNotAnInput(const std::string& option, const std::string& output,
                     const std::vector<AssetFile>& inputs) {
    for (const AssetFile& input : inputs)
        if (samePath(output, input.path))
            throw UsageError(option + ": the output '" + output + "' is a file the model reads (" +
                             input.path + ")");
}

void checkPlanNotInputs(const OutputPlan& plan, const std::vector<AssetFile>& inputs) {
    checkNotAnInput("-o", plan.color, inputs);
    for (const AovRequest& aov : plan.aovs)
        checkNotAnInput(std::string("--aov ") + kindName(aov.kind), aov.path, inputs);
}

}  // namespace kerf::app
