/// @file lang/eval_limits.h
/// @brief The limits on evaluating a model (loops, calls, lists, primitives, nodes): the documented
/// numbers of scene/limits.h by default; tests and fuzzers pass smaller ones to reach them fast.
#pragma once

#include "scene/limits.h"

#include <cstdint>

namespace kerf {

struct EvalLimits {
    int callDepth = kMaxCallDepth;
    int64_t iterations = kMaxLoopIterations;
    int64_t listLength = kMaxListLength;
    int64_t primitives = kMaxPrimitives;
    int64_t nodes = kMaxNodes;
};

}  // namespace kerf
