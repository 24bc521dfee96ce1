// Expression graphs and tapes: evaluation against the same formula written in C++, interval
// containment, gradients against analytic and finite-difference oracles, hash-consing.
#include "csg/tape/tape.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "csg/tape/expr.h"

using namespace kerf;

namespace {

/// A formula using every operation, written once for doubles and long doubles.
template <typename T>
T everyOp(T x, T y, T z) {
    using std::abs;
    using std::acos;
    using std::asin;
    using std::atan;
    using std::atan2;
    using std::ceil;
    using std::cos;
    using std::exp;
    using std::floor;
    using std::log;
    using std::pow;
    using std::sin;
    using std::sqrt;
    using std::tan;
    const T half = T(1) / T(2);
    return sin(x) * cos(y) + sqrt(x * x + z * z + T(1)) - exp(-z) / (T(1) + y * y) + atan2(y, x) +
           x * x * x + pow(abs(x) + T(1), y) + std::min(x, y) - std::max(y * z, half) + floor(z) +
           ceil(y) + tan(half * atan(x)) + asin(half * sin(z)) + acos(half * cos(x)) +
           log(T(2) + cos(y)) + T(1) / (x * x + T(1));
}

/// The same formula as an expression graph.
ExprId buildEveryOp(ExprGraph& g) {
    const ExprId x = g.x(), y = g.y(), z = g.z(), one = g.constant(1.0), half = g.constant(0.5);
    auto add = [&](ExprId a, ExprId b) { return g.binary(Op::Add, a, b); };
    auto mul = [&](ExprId a, ExprId b) { return g.binary(Op::Mul, a, b); };
    ExprId f = mul(g.unary(Op::Sin, x), g.unary(Op::Cos, y));
    f = add(f, g.unary(Op::Sqrt, add(add(mul(x, x), mul(z, z)), one)));
    f = g.binary(Op::Sub, f,
                 g.binary(Op::Div, g.unary(Op::Exp, g.unary(Op::Neg, z)), add(one, mul(y, y))));
    f = add(f, g.binary(Op::Atan2, y, x));
    f = add(f, g.powInt(x, 3));
    f = add(f, g.binary(Op::Pow, add(g.unary(Op::Abs, x), one), y));
    f = add(f, g.binary(Op::Min, x, y));
    f = g.binary(Op::Sub, f, g.binary(Op::Max, mul(y, z), half));
    f = add(f, g.unary(Op::Floor, z));
    f = add(f, g.unary(Op::Ceil, y));
    f = add(f, g.unary(Op::Tan, mul(half, g.unary(Op::Atan, x))));
    f = add(f, g.unary(Op::Asin, mul(half, g.unary(Op::Sin, z))));
    f = add(f, g.unary(Op::Acos, mul(half, g.unary(Op::Cos, x))));
    f = add(f, g.unary(Op::Log, add(g.constant(2.0), g.unary(Op::Cos, y))));
    f = add(f, g.binary(Op::Div, one, add(g.unary(Op::Square, x), one)));
    return f;
}

/// A smooth function and its hand-derived gradient: f = x²y + sin(z)·x + exp(y·z)/(1 + x²).
template <typename T>
T smooth(T x, T y, T z) {
    return x * x * y + std::sin(z) * x + std::exp(y * z) / (T(1) + x * x);
}
Vec3 smoothGradient(double x, double y, double z) {
    const double e = std::exp(y * z), q = 1.0 + x * x;
    return {2 * x * y + std::sin(z) - e * 2 * x / (q * q), x * x + z * e / q,
            x * std::cos(z) + y * e / q};
}
ExprId buildSmooth(ExprGraph& g) {
    const ExprId x = g.x(), y = g.y(), z = g.z();
    auto add = [&](ExprId a, ExprId b) { return g.binary(Op::Add, a, b); };
    auto mul = [&](ExprId a, ExprId b) { return g.binary(Op::Mul, a, b); };
    const ExprId q = add(g.constant(1.0), mul(x, x));
    return add(add(mul(mul(x, x), y), mul(g.unary(Op::Sin, z), x)),
               g.binary(Op::Div, g.unary(Op::Exp, mul(y, z)), q));
}

Vec3 randomPoint(std::mt19937_64& rng, double scale) {
    std::uniform_real_distribution<double> u(-scale, scale);
    return {u(rng), u(rng), u(rng)};
}

}  // namespace

TEST_CASE("Tape::eval") {
    ExprGraph g;
    const auto tape = Tape::compile(g, buildEveryOp(g));
    std::mt19937_64 rng(7);
    for (int i = 0; i < 2000; ++i) {
        const Vec3 p = randomPoint(rng, 3.0);
        const double expected = everyOp<double>(p.x, p.y, p.z);
        INFO("p = " << p.x << ", " << p.y << ", " << p.z);
        REQUIRE(tape->eval(p) == Approx(expected).epsilon(1e-14).margin(1e-14));
    }
}

TEST_CASE("Tape::evalInterval") {
    ExprGraph g;
    const auto tape = Tape::compile(g, buildEveryOp(g));
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int failures = 0;
    for (int i = 0; i < 2000 && failures < 5; ++i) {
        const Vec3 c = randomPoint(rng, 3.0);
        const Vec3 w = Vec3(std::pow(10.0, -6 * unit(rng)), std::pow(10.0, -6 * unit(rng)),
                            std::pow(10.0, -6 * unit(rng)));
        const Interval x(c.x - w.x, c.x + w.x), y(c.y - w.y, c.y + w.y), z(c.z - w.z, c.z + w.z);
        const Interval r = tape->evalInterval(x, y, z);
        for (int k = 0; k < 20; ++k) {
            const double px = x.lo + unit(rng) * (x.hi - x.lo),
                         py = y.lo + unit(rng) * (y.hi - y.lo),
                         pz = z.lo + unit(rng) * (z.hi - z.lo);
            const long double v = everyOp<long double>(px, py, pz);
            if (std::isnan(v) || (r.lo <= v && v <= r.hi)) continue;
            ++failures;
            FAIL_CHECK("f(" << px << ", " << py << ", " << pz << ") = " << double(v) << " not in ["
                            << r.lo << ", " << r.hi << "]");
        }
    }
    CHECK(failures == 0);
}

TEST_CASE("Tape::evalGradient") {
    ExprGraph g;
    const auto tape = Tape::compile(g, buildSmooth(g));
    std::mt19937_64 rng(9);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 p = randomPoint(rng, 2.0);
        Vec3 grad;
        const double v = tape->evalGradient(p, grad);
        INFO("p = " << p.x << ", " << p.y << ", " << p.z);
        CHECK(v == tape->eval(p));
        const Vec3 expected = smoothGradient(p.x, p.y, p.z);
        for (int a = 0; a < 3; ++a) {
            CHECK(grad[a] == Approx(expected[a]).epsilon(1e-13).margin(1e-13));
            // Central differences in long double: error O(h²) ≈ 1e-8 relative.
            const long double h = 1e-4L;
            long double q[3] = {p.x, p.y, p.z}, r[3] = {p.x, p.y, p.z};
            q[a] += h;
            r[a] -= h;
            const long double fd =
                (smooth<long double>(q[0], q[1], q[2]) - smooth<long double>(r[0], r[1], r[2])) /
                (2 * h);
            CHECK(grad[a] == Approx(double(fd)).epsilon(1e-6).margin(1e-7));
        }
    }
}

TEST_CASE("Tape::evalAlongRay") {
    // The value is eval's, bit for bit; the slope is the gradient's along the direction (the
    // analytic one for the smooth formula), up to rounding.
    ExprGraph g;
    const auto every = Tape::compile(g, buildEveryOp(g));
    const auto smoothTape = Tape::compile(g, buildSmooth(g));
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 1000; ++i) {
        const Ray ray{randomPoint(rng, 2.0), randomPoint(rng, 1.0)};
        const double t = 2.0 * unit(rng);
        const Vec3 p = ray.at(t);
        INFO("ray " << ray.origin.x << ", " << ray.origin.y << ", " << ray.origin.z << " dir "
                    << ray.dir.x << ", " << ray.dir.y << ", " << ray.dir.z << " t = " << t);
        double slope = 0.0;
        CHECK(every->evalAlongRay(ray, t, slope) == every->eval(p));
        Vec3 grad;
        every->evalGradient(p, grad);
        const double viaGradient = glm::dot(grad, ray.dir);
        if (std::isfinite(viaGradient))
            CHECK(slope == Approx(viaGradient).epsilon(1e-12).margin(1e-12));
        CHECK(smoothTape->evalAlongRay(ray, t, slope) == smoothTape->eval(p));
        const double expected = glm::dot(smoothGradient(p.x, p.y, p.z), ray.dir);
        CHECK(slope == Approx(expected).epsilon(1e-12).margin(1e-12));
    }
}

TEST_CASE("Tape::evalIntervalAlongRay") {
    ExprGraph g;
    const auto tape = Tape::compile(g, buildSmooth(g));
    std::mt19937_64 rng(10);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 500; ++i) {
        Ray ray{randomPoint(rng, 2.0), randomPoint(rng, 1.0)};
        const double t0 = unit(rng), t1 = t0 + std::pow(10.0, -4 * unit(rng));
        Interval f, dfdt;
        tape->evalIntervalAlongRay(ray, Interval(t0, t1), f, dfdt);
        for (int k = 0; k < 10; ++k) {
            const long double t = t0 + unit(rng) * (t1 - t0);
            const long double px = ray.origin.x + t * ray.dir.x, py = ray.origin.y + t * ray.dir.y,
                              pz = ray.origin.z + t * ray.dir.z;
            const long double v = smooth<long double>(px, py, pz);
            const Vec3 gr = smoothGradient(double(px), double(py), double(pz));
            const double slope = glm::dot(gr, ray.dir);
            INFO("t = " << double(t) << " f = " << double(v) << " in [" << f.lo << ", " << f.hi
                        << "], slope " << slope << " in [" << dfdt.lo << ", " << dfdt.hi << "]");
            CHECK((f.lo <= v && v <= f.hi));
            // The analytic slope is computed in double: allow its rounding.
            CHECK(dfdt.lo <= slope + 1e-12 * (1 + std::fabs(slope)));
            CHECK(slope - 1e-12 * (1 + std::fabs(slope)) <= dfdt.hi);
        }
    }
}

TEST_CASE("ExprGraph hash-consing") {
    ExprGraph g;
    const ExprId x = g.x(), y = g.y();
    SECTION("equal nodes share one id") {
        CHECK(g.x() == x);
        CHECK(g.constant(2.5) == g.constant(2.5));
        CHECK(g.constant(0.0) != g.constant(-0.0));
        const ExprId a = g.binary(Op::Mul, x, y);
        CHECK(g.binary(Op::Mul, x, y) == a);
        CHECK(g.binary(Op::Mul, y, x) == a);  // commutative: canonical order
        CHECK(g.binary(Op::Sub, x, y) != g.binary(Op::Sub, y, x));
        CHECK(g.powInt(x, 3) == g.powInt(x, 3));
        CHECK(g.powInt(x, 3) != g.powInt(x, 4));
        const size_t before = g.nodes().size();
        g.unary(Op::Sin, g.binary(Op::Mul, y, x));
        g.unary(Op::Sin, g.binary(Op::Mul, x, y));
        CHECK(g.nodes().size() == before + 1);
    }
    SECTION("operations on constants fold") {
        const ExprId five = g.binary(Op::Add, g.constant(2.0), g.constant(3.0));
        CHECK(g.nodes()[five].op == Op::Const);
        CHECK(g.nodes()[five].value == 5.0);
        CHECK(g.nodes()[g.unary(Op::Sqrt, g.constant(9.0))].value == 3.0);
        CHECK(g.nodes()[g.powInt(g.constant(2.0), 10)].value == 1024.0);
    }
    SECTION("a tape holds only what the root needs, each shared node once") {
        g.unary(Op::Sin, g.z());  // unrelated
        const ExprId s = g.binary(Op::Add, x, y);
        const ExprId root = g.binary(Op::Mul, s, g.binary(Op::Add, y, x));  // (x+y)·(x+y)
        const auto tape = Tape::compile(g, root);
        CHECK(tape->size() == 4);  // x, y, x+y, product
        CHECK(tape->eval(Vec3(1.0, 2.0, 3.0)) == 9.0);
    }
}
