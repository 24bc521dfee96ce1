/// @file tests/util/shell_reference.h
/// @brief Reference spans of shells (a sphere-like chord minus an inner one) with an error
/// bound per end, and the comparison of a solid's spans with them: every reference span wider
/// than twice the tolerance must be found, and nothing else.
#pragma once

#include "util/oracles.h"

#include <catch2/catch.hpp>

#include <vector>

namespace kerf::test {

/// A reference span with an allowed error at each end.
struct RefSpan {
    LD in, out, errIn, errOut;
};

/// Entry and exit of a sphere-like oracle as a span, with each end's bound: tolerance·t plus
/// the grazing condition term 8·ulp·r·|f|/(|d|²·w).
inline RefSpan chord(const SphereOracle& o, LD r, LD far, LD a, LD tolerance) {
    const LD cond = 8 * kUlp * r * far / (a * o.halfChord);
    return {o.tIn(), o.tOut(), tolerance * std::fabs(o.tIn()) + cond,
            tolerance * std::fabs(o.tOut()) + cond};
}

/// Outer chord minus inner chord: one or two spans.
inline std::vector<RefSpan> shellSpans(const RefSpan& outer, const SphereOracle& inner,
                                       const RefSpan& in) {
    if (!inner.hit()) return {outer};
    return {{outer.in, in.in, outer.errIn, in.errIn}, {in.out, outer.out, in.errOut, outer.errOut}};
}

struct ShellTally {
    int rays = 0, walls = 0, thinSkipped = 0;
    LD worst = 0;  ///< worst end error relative to its bound
};

/// Every reference span wider than 2·tolerance·t is found with both ends within bounds, and
/// every span found is one of the reference's.
inline void compare(const SpanList& got, const std::vector<RefSpan>& ref, double tolerance,
                    ShellTally& tally) {
    int next = 0;
    for (const RefSpan& r : ref) {
        const bool owed = r.out - r.in > 2 * tolerance * std::fabs(r.out);
        const Span* match = nullptr;
        for (int k = next; k < got.size(); ++k)
            if (std::fabs(got[k].in.t - r.in) <= r.errIn &&
                std::fabs(got[k].out.t - r.out) <= r.errOut) {
                match = &got[k];
                next = k + 1;
                break;
            }
        if (match) {
            ++tally.walls;
            tally.worst = std::max({tally.worst, std::fabs(match->in.t - r.in) / r.errIn,
                                    std::fabs(match->out.t - r.out) / r.errOut});
        } else if (owed) {
            FAIL_CHECK("missed a wall [" << double(r.in) << ", " << double(r.out) << "]");
        } else {
            ++tally.thinSkipped;
        }
    }
    CHECK(next == got.size());  // nothing found that the reference does not have
}

}  // namespace kerf::test
