// The slicer's section tape over an implicit that calls external fields (Op::Field): its
// interval value and slopes in u and v enclose sampled values and gradients on axis and
// oblique planes, and its point values are the closed form's (the signed distances to a
// sphere and a box, csg/tape/scalar_field.h).
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "csg/tape/expr.h"
#include "csg/tree/solids.h"
#include "slice/section_tape.h"
#include "util/test_fields.h"

using namespace kerf;
using kerf::test::BoxField;
using kerf::test::SphereField;

TEST_CASE("sectionTape/a tape with fields: value and slopes enclose samples") {
    const auto sphere = std::make_shared<SphereField>(Vec3(0.2, -0.1, 0.3), 0.9);
    const auto box = std::make_shared<BoxField>(Vec3(-0.3, 0.4, 0.1), Vec3(0.5, 0.3, 0.7));
    ExprGraph g;
    const ExprId x = g.x(), y = g.y(), z = g.z();
    const ExprId f = g.binary(Op::Min, g.field(x, y, z, sphere), g.field(x, y, z, box));
    // The bound is far outside the sampled region, so the implicit's value is min(A, B) there.
    const NodePtr node = makeImplicit(Tape::compile(g, f), {Vec3(-4.0), Vec3(4.0)});
    const auto exact = [&](const Vec3& p) {
        const glm::tvec3<long double> q(p);
        return std::min(sphere->valueExtended(q), box->valueExtended(q));
    };

    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Interval> scratch;
    int cells = 0;
    for (const SlicePlane& plane :
         {SlicePlane::axisAligned(2, 0.3), SlicePlane::axisAligned(0, -0.2),
          SlicePlane::throughPoint(Vec3(0.1, 0.2, 0.05), Vec3(0.3, -0.5, 0.8))}) {
        const auto tape = sectionTape(*node, plane);
        REQUIRE(tape->fields().size() == 2);
        for (double size : {1e-6, 0.05, 0.5, 2.0}) {
            for (int i = 0; i < 100; ++i) {
                const double u0 = 4.0 * unit(rng) - 2.0, v0 = 4.0 * unit(rng) - 2.0;
                const Interval u(u0, u0 + size * unit(rng)), v(v0, v0 + size * unit(rng));
                const IntervalSlopes s = evalIntervalSlopes(*tape, u, v, plane.w, scratch);
                REQUIRE(s.ok);  // every op of the tape, the field included, has a slope rule
                ++cells;
                for (int k = 0; k < 30; ++k) {
                    const double pu = k == 0 ? u.lo : k == 1 ? u.hi : u.lo + u.width() * unit(rng);
                    const double pv = k == 0 ? v.lo : k == 1 ? v.hi : v.lo + v.width() * unit(rng);
                    Vec3 grad;
                    const double value = tape->evalGradient(Vec3(pu, pv, plane.w), grad);
                    INFO("plane w=" << plane.w << " u=" << pu << " v=" << pv);
                    CHECK(s.f.contains(value));
                    CHECK(s.du.contains(grad.x));
                    CHECK(s.dv.contains(grad.y));
                    CHECK(std::fabs(value - exact(plane.at(pu, pv))) <= 1e-14);
                }
            }
        }
    }
    CHECK(cells == 1200);
}
