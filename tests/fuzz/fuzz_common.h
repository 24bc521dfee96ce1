// Shared by the libFuzzer targets (tests/fuzz/README.md): the input as model text, with
// includes refused so a fuzzer never reads the file system.
#pragma once

#include "lang/eval_limits.h"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

namespace kerf::fuzz {

/// The model text of a fuzzer input, or false when the input must be skipped: the fuzzers do
/// no file I/O, so any input that mentions `include` (the only statement that reads a file) is
/// not run. Inputs are also capped in size (libFuzzer's -max_len does the same by default).
inline bool modelText(const uint8_t* data, size_t size, std::string& text) {
    if (size > 64 * 1024) return false;
    text.assign(reinterpret_cast<const char*>(data), size);
    return text.find("include") == std::string::npos;
}

/// The name the model is compiled under: a folder that does not exist, so even an include
/// that slipped through could not find a file relative to it.
inline const char* kModelName = "/nonexistent-kerf-fuzz/input.kerf";

/// Evaluation limits small enough that a 4 kB loop cannot pass -timeout or -rss_limit_mb under
/// the sanitizers (the real ones allow 4 million primitives and nodes); the limit checks themselves
/// are the same code.
inline EvalLimits limits() {
    EvalLimits l;
    l.iterations = 200'000;
    l.listLength = 100'000;
    l.primitives = 100'000;
    l.nodes = 100'000;
    return l;
}

}  // namespace kerf::fuzz
