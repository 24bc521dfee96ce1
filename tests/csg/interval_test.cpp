// Interval arithmetic: containment properties against long double, and hand-checked cases.
#include "csg/interval/interval.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <random>
#include <sstream>

using namespace kerf;

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr int kIntervals = 3000;
constexpr int kPointsPerInterval = 12;

/// Random intervals of every awkward kind: around 0, touching 0, huge, tiny, unbounded, points.
class IntervalSource {
public:
    explicit IntervalSource(uint64_t seed, double domainScale = 0.0)
        : mRng(seed), mScale(domainScale) {}

    Interval next() {
        if (mScale > 0.0) {  // a fixed domain such as [−1.5, 1.5] for asin
            double a = uniform(-mScale, mScale), b = uniform(-mScale, mScale);
            return {std::min(a, b), std::max(a, b)};
        }
        switch (std::uniform_int_distribution<int>(0, 8)(mRng)) {
            case 0: return ordered(uniform(-10, 10), uniform(-10, 10));
            case 1: return {-magnitude(-3, 3), magnitude(-3, 3)};  // holds 0
            case 2:
                return coin() ? Interval{0.0, magnitude(-3, 3)} : Interval{-magnitude(-3, 3), 0.0};
            case 3: return ordered(signedMagnitude(100, 300), signedMagnitude(100, 300));
            case 4: return ordered(signedMagnitude(-300, -100), signedMagnitude(-300, -100));
            case 5: {
                const double v = signedMagnitude(-5, 5);
                return coin() ? Interval{v, kInfinity} : Interval{-kInfinity, v};
            }
            case 6: return {-kInfinity, kInfinity};
            case 7: {
                const double v = signedMagnitude(-20, 20);
                return {v, v};
            }
            default: {
                const double c = signedMagnitude(-8, 8), w = magnitude(-12, 1) * std::fabs(c);
                return {c - w, c + w};
            }
        }
    }

    /// A point inside a (finite even when a's ends are not); the ends themselves often.
    double pointIn(const Interval& a) {
        const int kind = std::uniform_int_distribution<int>(0, 5)(mRng);
        if (kind == 0 && std::isfinite(a.lo)) return a.lo;
        if (kind == 1 && std::isfinite(a.hi)) return a.hi;
        double lo = a.lo, hi = a.hi;
        if (!std::isfinite(lo) && !std::isfinite(hi)) return signedMagnitude(-10, 300);
        if (!std::isfinite(lo)) return hi - magnitude(-10, 300);
        if (!std::isfinite(hi)) return lo + magnitude(-10, 300);
        const double v = lo + uniform(0.0, 1.0) * (hi - lo);
        return std::isfinite(v) ? std::min(std::max(v, lo), hi) : (coin() ? lo : hi);
    }

    std::mt19937_64& rng() { return mRng; }

private:
    double uniform(double a, double b) {
        return std::uniform_real_distribution<double>(a, b)(mRng);
    }
    bool coin() { return std::uniform_int_distribution<int>(0, 1)(mRng) == 1; }
    double magnitude(double e0, double e1) { return std::pow(10.0, uniform(e0, e1)); }
    double signedMagnitude(double e0, double e1) {
        return coin() ? magnitude(e0, e1) : -magnitude(e0, e1);
    }
    static Interval ordered(double a, double b) { return {std::min(a, b), std::max(a, b)}; }

    std::mt19937_64 mRng;
    double mScale;
};

std::string describe(const Interval& a) {
    std::ostringstream s;
    s.precision(17);
    s << "[" << a.lo << ", " << a.hi << (a.maybeNan ? "] nan?" : "]");
    return s.str();
}

bool holds(const Interval& r, long double v) {
    return static_cast<long double>(r.lo) <= v && v <= static_cast<long double>(r.hi);
}

/// For every sampled (x in A): exact(x), when defined (not NaN), lies in op(A).
void checkUnary(const char* name, const std::function<Interval(const Interval&)>& op,
                const std::function<long double(long double)>& exact, uint64_t seed,
                double domainScale = 0.0) {
    IntervalSource src(seed, domainScale);
    int failures = 0;
    for (int i = 0; i < kIntervals && failures < 10; ++i) {
        const Interval a = src.next();
        const Interval r = op(a);
        for (int k = 0; k < kPointsPerInterval; ++k) {
            const double x = src.pointIn(a);
            const long double v = exact(x);
            if (std::isnan(v) || holds(r, v)) continue;
            std::ostringstream msg;
            msg.precision(21);
            msg << name << " of " << describe(a) << " = " << describe(r) << " misses " << name
                << "(" << x << ") = " << v;
            FAIL_CHECK(msg.str());
            ++failures;
        }
    }
    CHECK(failures == 0);
}

void checkBinary(const char* name,
                 const std::function<Interval(const Interval&, const Interval&)>& op,
                 const std::function<long double(long double, long double)>& exact, uint64_t seed) {
    IntervalSource src(seed);
    int failures = 0;
    for (int i = 0; i < kIntervals && failures < 10; ++i) {
        const Interval a = src.next(), b = src.next();
        const Interval r = op(a, b);
        for (int k = 0; k < kPointsPerInterval; ++k) {
            const double x = src.pointIn(a), y = src.pointIn(b);
            const long double v = exact(x, y);
            if (std::isnan(v) || holds(r, v)) continue;
            std::ostringstream msg;
            msg.precision(21);
            msg << name << " of " << describe(a) << ", " << describe(b) << " = " << describe(r)
                << " misses " << name << "(" << x << ", " << y << ") = " << v;
            FAIL_CHECK(msg.str());
            ++failures;
        }
    }
    CHECK(failures == 0);
}

}  // namespace

TEST_CASE("Interval arithmetic contains the exact result") {
    SECTION("add") {
        checkBinary(
            "+", [](auto a, auto b) { return a + b; },
            [](long double x, long double y) { return x + y; }, 1);
    }
    SECTION("sub") {
        checkBinary(
            "-", [](auto a, auto b) { return a - b; },
            [](long double x, long double y) { return x - y; }, 2);
    }
    SECTION("mul") {
        checkBinary(
            "*", [](auto a, auto b) { return a * b; },
            [](long double x, long double y) { return x * y; }, 3);
    }
    SECTION("div") {
        checkBinary(
            "/", [](auto a, auto b) { return a / b; },
            [](long double x, long double y) { return y == 0 ? NAN : x / y; }, 4);
    }
    SECTION("neg") {
        checkUnary(
            "neg", [](auto a) { return -a; }, [](long double x) { return -x; }, 5);
    }
    SECTION("min") {
        checkBinary(
            "min", [](auto a, auto b) { return min(a, b); },
            [](long double x, long double y) { return std::min(x, y); }, 6);
    }
    SECTION("max") {
        checkBinary(
            "max", [](auto a, auto b) { return max(a, b); },
            [](long double x, long double y) { return std::max(x, y); }, 7);
    }
    SECTION("hull") {
        checkBinary(
            "hull", [](auto a, auto b) { return hull(a, b); },
            [](long double x, long double) { return x; }, 8);
        checkBinary(
            "hull", [](auto a, auto b) { return hull(a, b); },
            [](long double, long double y) { return y; }, 9);
    }
    SECTION("atan2") {
        checkBinary(
            "atan2", [](auto a, auto b) { return atan2(a, b); },
            [](long double y, long double x) { return std::atan2(y, x); }, 10);
    }
    SECTION("pow") {
        checkBinary(
            "pow", [](auto a, auto b) { return pow(a, b); },
            [](long double x, long double y) { return x < 0 ? NAN : std::pow(x, y); }, 11);
    }
}

TEST_CASE("Interval functions contain the exact result") {
    SECTION("sqr") {
        checkUnary(
            "sqr", [](auto a) { return sqr(a); }, [](long double x) { return x * x; }, 20);
    }
    SECTION("powInt") {
        for (int n : {-5, -4, -3, -2, -1, 0, 1, 2, 3, 4, 5, 7, 8, 13}) {
            INFO("n = " << n);
            checkUnary(
                "powInt", [n](auto a) { return powInt(a, n); },
                [n](long double x) { return (x == 0 && n < 0) ? NAN : std::pow(x, n); }, 21 + n);
        }
    }
    SECTION("sqrt") {
        checkUnary(
            "sqrt", [](auto a) { return sqrt(a); }, [](long double x) { return std::sqrt(x); }, 40);
    }
    SECTION("abs") {
        checkUnary(
            "abs", [](auto a) { return abs(a); }, [](long double x) { return std::fabs(x); }, 41);
    }
    SECTION("exp") {
        checkUnary(
            "exp", [](auto a) { return exp(a); }, [](long double x) { return std::exp(x); }, 42);
    }
    SECTION("log") {
        checkUnary(
            "log", [](auto a) { return log(a); },
            [](long double x) { return x < 0 ? NAN : std::log(x); }, 43);
    }
    SECTION("sin") {
        checkUnary(
            "sin", [](auto a) { return sin(a); }, [](long double x) { return std::sin(x); }, 44);
    }
    SECTION("cos") {
        checkUnary(
            "cos", [](auto a) { return cos(a); }, [](long double x) { return std::cos(x); }, 45);
    }
    SECTION("tan") {
        checkUnary(
            "tan", [](auto a) { return tan(a); }, [](long double x) { return std::tan(x); }, 46);
    }
    SECTION("sin and cos on small domains") {
        checkUnary(
            "sin", [](auto a) { return sin(a); }, [](long double x) { return std::sin(x); }, 47,
            7.0);
        checkUnary(
            "cos", [](auto a) { return cos(a); }, [](long double x) { return std::cos(x); }, 48,
            7.0);
        checkUnary(
            "tan", [](auto a) { return tan(a); }, [](long double x) { return std::tan(x); }, 49,
            4.0);
    }
    SECTION("asin") {
        checkUnary(
            "asin", [](auto a) { return asin(a); }, [](long double x) { return std::asin(x); }, 50,
            1.5);
    }
    SECTION("acos") {
        checkUnary(
            "acos", [](auto a) { return acos(a); }, [](long double x) { return std::acos(x); }, 51,
            1.5);
    }
    SECTION("atan") {
        checkUnary(
            "atan", [](auto a) { return atan(a); }, [](long double x) { return std::atan(x); }, 52);
    }
    SECTION("floor") {
        checkUnary(
            "floor", [](auto a) { return floor(a); }, [](long double x) { return std::floor(x); },
            53);
    }
    SECTION("ceil") {
        checkUnary(
            "ceil", [](auto a) { return ceil(a); }, [](long double x) { return std::ceil(x); }, 54);
    }
}

TEST_CASE("Interval division by intervals holding zero") {
    SECTION("by [0, 1]: positive numerators give [lo, inf]") {
        const Interval r = Interval(2.0, 3.0) / Interval(0.0, 1.0);
        CHECK(r.lo <= 2.0);
        CHECK(r.lo > 1.99);
        CHECK(r.hi == kInfinity);
        CHECK(r.maybeNan);
    }
    SECTION("by [-1, 0]: positive numerators give [-inf, hi]") {
        const Interval r = Interval(2.0, 3.0) / Interval(-1.0, 0.0);
        CHECK(r.lo == -kInfinity);
        CHECK(r.hi >= -2.0);
        CHECK(r.hi < -1.99);
        CHECK(r.maybeNan);
    }
    SECTION("negative numerators mirror") {
        const Interval r = Interval(-3.0, -2.0) / Interval(0.0, 1.0);
        CHECK(r.lo == -kInfinity);
        CHECK(r.hi >= -2.0);
        CHECK(r.hi < -1.99);
        const Interval s = Interval(-3.0, -2.0) / Interval(-1.0, 0.0);
        CHECK(s.lo <= 2.0);
        CHECK(s.hi == kInfinity);
    }
    SECTION("by [-1, 1] is entire") {
        const Interval r = Interval(2.0, 3.0) / Interval(-1.0, 1.0);
        CHECK(r.lo == -kInfinity);
        CHECK(r.hi == kInfinity);
        CHECK(r.maybeNan);
        CHECK(r.classify() == Classification::Ambiguous);
    }
    SECTION("0/0 possible is entire") {
        const Interval r = Interval(-1.0, 1.0) / Interval(0.0, 1.0);
        CHECK(r.lo == -kInfinity);
        CHECK(r.hi == kInfinity);
        CHECK(r.maybeNan);
    }
}

TEST_CASE("Interval sqrt, log and tan at their singular points") {
    SECTION("sqrt at 0 is exactly 0 below") {
        const Interval r = sqrt(Interval(0.0, 4.0));
        CHECK(r.lo == 0.0);
        CHECK(r.hi >= 2.0);
        CHECK(r.hi < 2.0 + 1e-15);
        CHECK_FALSE(r.maybeNan);
        const Interval s = sqrt(Interval(-1.0, 4.0));
        CHECK(s.lo == 0.0);
        CHECK(s.maybeNan);
    }
    SECTION("log(0) is -inf below") {
        const Interval r = log(Interval(0.0, 1.0));
        CHECK(r.lo == -kInfinity);
        CHECK(r.hi >= 0.0);
        CHECK(r.hi < 1e-15);
        CHECK_FALSE(r.maybeNan);
        CHECK(log(Interval(-1.0, 1.0)).maybeNan);
    }
    SECTION("tan across pi/2 is entire; just below it is finite and increasing") {
        const Interval across = tan(Interval(1.5, 1.6));
        CHECK(across.lo == -kInfinity);
        CHECK(across.hi == kInfinity);
        const Interval below = tan(Interval(1.4, 1.57));
        CHECK(below.lo <= std::tan(1.4));
        CHECK(below.hi >= 1255.7655915007897);  // tan(1.57)
        CHECK(below.hi < 1255.77);
        const Interval after = tan(Interval(1.58, 1.7));
        CHECK(after.lo <= -108.649);
        CHECK(after.hi < 0.0);
    }
    SECTION("NaN flag propagates") {
        const Interval n = sqrt(Interval(-1.0, 1.0));
        CHECK((n + 1.0).maybeNan);
        CHECK((n * 2.0).maybeNan);
        CHECK(sin(n).maybeNan);
        CHECK(max(n, Interval(5.0)).maybeNan);
        CHECK((n + 1.0).classify() == Classification::Ambiguous);
    }
}
