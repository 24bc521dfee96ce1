// The per-op conformance suite of the tape family (after Fidget's eval/test suites): one row
// per Op, and for each row every evaluator on random inputs.
// - interval, interval-with-choices, along-ray interval: the enclosure holds the point values
//   (and the point slopes) at points sampled inside the region (the section tape's slopes:
//   tests/slice/section_conformance_test.cpp, on the same rows);
// - interval4 (scalar and, where the CPU has it, AVX2): every lane is evalInterval's bits;
// - the lean along-ray path is the general one's bits; evalAlongRay's and evalGradient's values
//   are eval's bits; a simplified tape gives eval's bits inside its box;
// - gradient and along-ray slopes: within kSlopeTolerance of a long-double central difference
//   of evalExtended (points next to a kink or jump, where the one-sided differences disagree,
//   are skipped).
// A failure names the op, the inputs and the output.
#include "csg/tape/scalar_field.h"
#include "csg/tape/tape.h"
#include "util/interval_checks.h"
#include "util/tape_conformance_rows.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <random>
#include <sstream>
#include <string>

using namespace kerf;
using kerf::test::describe;
using kerf::test::sameBits;
using namespace kerf::test;

namespace {

std::string where(const Row& row, const Vec3& p) {
    std::ostringstream s;
    s.precision(17);
    s << "op " << row.name << " at (" << p.x << ", " << p.y << ", " << p.z << ")";
    return s.str();
}

std::string where(const Row& row, const Interval box[3]) {
    return std::string("op ") + row.name + " over " + describe(box[0]) + " × " + describe(box[1]) +
           " × " + describe(box[2]);
}

/// The long-double central difference of f along `dir` at p, or NaN next to a kink or jump
/// (where the forward and backward differences disagree).
long double centralDifference(const Tape& tape, const Vec3& p, const Vec3& dir) {
    using LV = glm::tvec3<long double>;
    const long double h = 1e-6L;
    const LV q(p), d(dir);
    const long double f0 = tape.evalExtended(q);
    const long double fp = tape.evalExtended(q + h * d), fm = tape.evalExtended(q - h * d);
    const long double forward = (fp - f0) / h, backward = (f0 - fm) / h;
    const long double central = (fp - fm) / (2 * h);
    if (std::fabs(forward - backward) > 1e-3L * (1 + std::fabs(central))) return NAN;
    return central;
}

bool slopeAgrees(double slope, long double reference) {
    if (std::isnan(reference)) return true;  // by a kink: no reference
    return std::fabs(slope - reference) <= kSlopeTolerance * (1 + std::fabs(reference));
}

}  // namespace

TEST_CASE("tape conformance: every op has a row") {
    for (int k = 0; k < kOpCount; ++k) {
        INFO("Op number " << k << " has no row in kRows");
        CHECK(rowOf(static_cast<Op>(k)) != nullptr);
    }
    CHECK(sizeof(kRows) / sizeof(kRows[0]) == static_cast<size_t>(kOpCount));
}

namespace {

/// At a point: eval against evalExtended, evalGradient's value (eval's bits) and gradient (the
/// central difference per axis), evalAlongRay's value (eval's bits) and slope.
void checkPoint(const Row& row, const Tape& tape, const Vec3& p, const Vec3& dir) {
    INFO(where(row, p));
    const double f = tape.eval(p);
    const long double exact = tape.evalExtended(glm::tvec3<long double>(p));
    INFO("eval " << f << ", evalExtended " << static_cast<double>(exact));
    CHECK(std::fabs(f - exact) <= 1e-12 * (1 + std::fabs(exact)));
    Vec3 grad;
    const double fg = tape.evalGradient(p, grad);
    INFO("gradient (" << grad.x << ", " << grad.y << ", " << grad.z << ")");
    CHECK(std::memcmp(&fg, &f, sizeof f) == 0);
    for (int axis = 0; axis < 3; ++axis) {
        Vec3 e(0.0);
        e[axis] = 1.0;
        const long double reference = centralDifference(tape, p, e);
        INFO("axis " << axis << ": central difference " << static_cast<double>(reference));
        CHECK(slopeAgrees(grad[axis], reference));
    }
    const Ray ray{p, dir};
    double dfdt = 0.0;
    const double fr = tape.evalAlongRay(ray, 0.0, dfdt);
    const long double reference = centralDifference(tape, p, dir);
    INFO("along (" << dir.x << ", " << dir.y << ", " << dir.z << "): df/dt " << dfdt
                   << ", central difference " << static_cast<double>(reference));
    CHECK(std::memcmp(&fr, &f, sizeof f) == 0);
    CHECK(slopeAgrees(dfdt, reference));
}

/// Over a box: evalInterval holds eval at sampled points; the interval with choices holds them
/// too, and the simplified tape gives eval's bits there.
void checkBox(const Row& row, const Tape& tape, const Interval box[3], std::mt19937_64& rng) {
    INFO(where(row, box));
    const Interval f = tape.evalInterval(box[0], box[1], box[2]);
    std::vector<Choice> choices;
    const Interval fc = tape.evalInterval(box[0], box[1], box[2], choices);
    const auto simpler = tape.simplified(choices);
    INFO("evalInterval " << describe(f) << ", with choices " << describe(fc));
    for (int k = 0; k < 8; ++k) {
        const Vec3 p(sampleIn(rng, box[0]), sampleIn(rng, box[1]), sampleIn(rng, box[2]));
        const double v = tape.eval(p), vs = simpler->eval(p);
        INFO("at (" << p.x << ", " << p.y << ", " << p.z << "): f = " << v << ", simplified "
                    << vs);
        CHECK(holds(f, v, 0.0));
        CHECK(holds(fc, v, 0.0));
        CHECK(std::memcmp(&v, &vs, sizeof v) == 0);
    }
}

/// interval4, scalar and AVX2, over four boxes: each lane is evalInterval's bits.
void checkLanes(const Row& row, const Tape& tape, const Interval boxes[4][3]) {
    Interval x[4], y[4], z[4];
    for (int k = 0; k < 4; ++k) x[k] = boxes[k][0], y[k] = boxes[k][1], z[k] = boxes[k][2];
    for (Tape::Lanes4 lanes : {Tape::Lanes4::Scalar, Tape::Lanes4::Avx2}) {
        if (lanes == Tape::Lanes4::Avx2 && !Tape::hasAvx2()) continue;
        Interval out[4];
        tape.evalInterval4(x, y, z, out, lanes);
        for (int k = 0; k < 4; ++k) {
            const Interval one = tape.evalInterval(x[k], y[k], z[k]);
            INFO(where(row, boxes[k])
                 << (lanes == Tape::Lanes4::Avx2 ? ", AVX2" : ", scalar") << ": lane "
                 << describe(out[k]) << ", evalInterval " << describe(one));
            CHECK(sameBits(out[k], one));
        }
    }
}

/// Along a ray over a t-range: f and df/dt hold the point values and slopes at sampled t, and
/// the lean path (where it runs) gives the general path's bits.
void checkRay(const Row& row, const Tape& tape, const Ray& ray, const Interval& t,
              std::mt19937_64& rng) {
    Interval f, dfdt, fRef, dfdtRef;
    tape.evalIntervalAlongRay(ray, t, f, dfdt);
    tape.evalIntervalAlongRayReference(ray, t, fRef, dfdtRef);
    INFO("op " << row.name << " along (" << ray.origin.x << ", " << ray.origin.y << ", "
               << ray.origin.z << ") + t·(" << ray.dir.x << ", " << ray.dir.y << ", " << ray.dir.z
               << ") for t in " << describe(t) << ": f " << describe(f) << ", df/dt "
               << describe(dfdt) << "; general path " << describe(fRef) << ", "
               << describe(dfdtRef));
    CHECK(sameBits(f, fRef));
    CHECK(sameBits(dfdt, dfdtRef));
    for (int k = 0; k < 8; ++k) {
        const double tk = sampleIn(rng, t);
        double slope = 0.0;
        const double v = tape.evalAlongRay(ray, tk, slope);
        INFO("at t = " << tk << ": f = " << v << ", df/dt = " << slope);
        CHECK(holds(f, v, 0.0));
        CHECK(holds(dfdt, slope, kEnclosureSlack));
    }
}

Vec3 randomDirection(std::mt19937_64& rng) {
    std::normal_distribution<double> n(0.0, 1.0);
    return glm::normalize(Vec3(n(rng), n(rng), n(rng)));
}

}  // namespace

TEST_CASE("tape conformance: every evaluator on every op") {
    std::mt19937_64 rng(20261201);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (const Row& row : kRows) {
        const auto tape = rowTape(row);
        for (int trial = 0; trial < 40; ++trial) {
            const Vec3 p(u(rng), u(rng), u(rng));
            checkPoint(row, *tape, p, randomDirection(rng));
            Interval boxes[4][3];
            for (auto& box : boxes)
                for (Interval& r : box) r = randomRange(rng);
            checkBox(row, *tape, boxes[0], rng);
            checkLanes(row, *tape, boxes);
            // A ray from inside [0.2, 0.8]³ for t in [0, 0.2] stays inside the unit cube.
            const Ray ray{Vec3(0.2 + 0.6 * u(rng), 0.2 + 0.6 * u(rng), 0.2 + 0.6 * u(rng)),
                          randomDirection(rng)};
            const double t0 = 0.2 * u(rng), width = std::pow(10.0, -6.0 * u(rng));
            checkRay(row, *tape, ray, Interval(t0 * (1 - width), t0 * (1 - width) + 0.2 * width),
                     rng);
        }
    }
}
