/// @file csg/tape/tape_eval_interval4.h
/// @brief Internal to csg/: the AVX2 path of Tape::evalInterval4, in its own file
/// (csg/tape/tape_eval_interval4_avx2.cpp) so that only its functions are compiled for AVX2.
#pragma once

#include "csg/tape/tape.h"

namespace kerf::interval4 {

/// Tape::evalInterval4 with AVX2 instructions, the same bits as the scalar path. Call it only
/// when the CPU has AVX2. False (and `out` untouched) when the tape holds an op outside the
/// vectorised list (csg/tape/tape.h), for the caller's scalar path.
bool evalAvx2(const std::vector<TapeInstr>& instrs, const Interval x[4], const Interval y[4],
              const Interval z[4], Interval out[4]);

}  // namespace kerf::interval4
