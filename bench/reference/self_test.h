/// @file bench/reference/self_test.h
/// @brief Checks of the oracle itself against hand-computed values and against an independent
/// 50-digit computation (mpmath), run by `depth_reference --self-test` before every benchmark.
#pragma once

namespace kerf::bench {

/// Prints each failed check to stderr; returns the number of failures.
int runSelfTest();

}  // namespace kerf::bench
