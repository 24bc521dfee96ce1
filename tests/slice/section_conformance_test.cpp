// The section tape's slopes (slice/section_tape.h) on the rows of the tape conformance suite
// (tests/util/tape_conformance_rows.h): over random cells, where evalIntervalSlopes concludes,
// its f holds eval and its ∂u, ∂v hold the gradient's x and y at sampled points (the tape's
// x, y as u, v at z = w). The ops the section has no rule for must conclude nothing.
#include "slice/section_tape.h"
#include "util/interval_checks.h"
#include "util/tape_conformance_rows.h"

#include <catch2/catch.hpp>

using namespace kerf;
using namespace kerf::test;

namespace {

/// The ops whose slopes the section leaves without a conclusion (slice/section_tape.cpp).
bool sectionConcludes(Op op) {
    return op != Op::Tan && op != Op::Asin && op != Op::Acos && op != Op::Atan2 && op != Op::Pow &&
           op != Op::Floor && op != Op::Ceil;
}

void checkSection(const Row& row, const Tape& tape, const Interval& u, const Interval& v, double w,
                  std::mt19937_64& rng) {
    std::vector<Interval> scratch;
    const IntervalSlopes s = evalIntervalSlopes(tape, u, v, w, scratch);
    INFO("op " << row.name << " over " << describe(u) << " × " << describe(v) << " at w = " << w
               << ": " << (s.ok ? describe(s.f) : "no conclusion"));
    CHECK(s.ok == sectionConcludes(row.op));
    if (!s.ok) return;
    for (int k = 0; k < 8; ++k) {
        const Vec3 p(sampleIn(rng, u), sampleIn(rng, v), w);
        Vec3 grad;
        const double f = tape.evalGradient(p, grad);
        INFO("at (" << p.x << ", " << p.y << "): f = " << f << ", ∂u " << grad.x << " in "
                    << describe(s.du) << ", ∂v " << grad.y << " in " << describe(s.dv));
        CHECK(holds(s.f, f, 0.0));
        CHECK(holds(s.du, grad.x, kEnclosureSlack));
        CHECK(holds(s.dv, grad.y, kEnclosureSlack));
    }
}

}  // namespace

TEST_CASE("section conformance: the slopes on every op") {
    std::mt19937_64 rng(1201);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const Row& row : kRows) {
        const auto tape = rowTape(row);
        for (int trial = 0; trial < 40; ++trial)
            checkSection(row, *tape, randomRange(rng), randomRange(rng), unit(rng), rng);
    }
}
