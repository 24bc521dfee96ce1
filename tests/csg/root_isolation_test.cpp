// Root isolation along a parameter: polynomials with known roots (simple, close, double,
// triple, near the start, many), checking every sign change is found and polished.
#include "csg/primitives/root_isolation.h"

#include <catch2/catch.hpp>
#include <vector>

using namespace kerf;

namespace {

/// p(t) = Π (t − rᵢ), with interval enclosures by the product form and the product rule.
struct RootProduct {
    std::vector<double> roots;

    void range(double a, double b, Interval& f, Interval& dfdt) const {
        const Interval t(a, b);
        f = Interval(1.0);
        dfdt = Interval(0.0);
        for (double r : roots) {
            const Interval factor = t - Interval(r);
            dfdt = dfdt * factor + f;  // (f·g)' = f'·g + f·g' with g' = 1
            f = f * factor;
        }
    }
    double value(double t) const {
        double f = 1.0;
        for (double r : roots) f *= t - r;
        return f;
    }
    double valueAndSlope(double t, double& dfdt) const {
        double f = 1.0;
        dfdt = 0.0;
        for (double r : roots) {
            dfdt = dfdt * (t - r) + f;
            f *= t - r;
        }
        return f;
    }
};

struct Crossing {
    double t;
    bool entering;
};

std::vector<Crossing> crossings(const RootProduct& p, double a, double b, TraceContext& ctx,
                                bool* insideAtStart = nullptr) {
    std::vector<Crossing> out;
    RootProduct q = p;
    const bool inside = isolateRoots(q, a, b, 0.0, ctx, [&](double t, bool entering) {
        out.push_back({t, entering});
    });
    if (insideAtStart) *insideAtStart = inside;
    return out;
}

}  // namespace

TEST_CASE("isolateRoots") {
    TraceContext ctx;
    ctx.relTolerance = 1e-9;

    SECTION("simple roots are found in order and polished to double precision") {
        bool inside = false;
        const auto c = crossings({{1.0, 2.0, 3.0}}, 0.0, 4.0, ctx, &inside);
        CHECK(inside);  // p(0) = −6
        REQUIRE(c.size() == 3);
        CHECK(c[0].t == Approx(1.0).epsilon(1e-15));
        CHECK_FALSE(c[0].entering);
        CHECK(c[1].t == Approx(2.0).epsilon(1e-15));
        CHECK(c[1].entering);
        CHECK(c[2].t == Approx(3.0).epsilon(1e-15));
        CHECK(ctx.stats.rootSteps > 0);
        CHECK(ctx.stats.intervalEvals > 0);
    }
    SECTION("roots closer than 1e-6 are told apart") {
        const auto c = crossings({{1.0, 1.0 + 1e-6}}, 0.0, 4.0, ctx);
        REQUIRE(c.size() == 2);
        CHECK(c[0].t == Approx(1.0).epsilon(1e-12));
        CHECK(c[1].t == Approx(1.0 + 1e-6).epsilon(1e-12));
    }
    SECTION("a double root is a touch: no crossing") {
        const auto c = crossings({{2.0, 2.0, 3.0}}, 0.0, 4.0, ctx);
        REQUIRE(c.size() == 1);
        CHECK(c[0].t == Approx(3.0).epsilon(1e-15));
    }
    SECTION("a triple root is one crossing within the tolerance") {
        const auto c = crossings({{2.0, 2.0, 2.0}}, 0.0, 4.0, ctx);
        REQUIRE(c.size() == 1);
        CHECK(std::fabs(c[0].t - 2.0) <= 2.0 * ctx.relTolerance * 2.0);
        CHECK(c[0].entering == false);  // (t − 2)³ goes from negative (inside) to positive
    }
    SECTION("a root next to the start stops at the depth cap") {
        const auto c = crossings({{1e-25}}, 0.0, 1.0, ctx);
        REQUIRE(c.size() == 1);
        CHECK(c[0].t == Approx(1e-25).epsilon(1e-9));
        CHECK(ctx.stats.rootSteps < 200);
    }
    SECTION("many roots") {
        RootProduct p;
        for (int i = 1; i <= 12; ++i) p.roots.push_back(0.25 * i);
        const auto c = crossings(p, 0.0, 4.0, ctx);
        REQUIRE(c.size() == 12);
        for (int i = 0; i < 12; ++i) {
            CHECK(c[i].t == Approx(0.25 * (i + 1)).epsilon(1e-13));
            CHECK(c[i].entering == (i % 2 == 0));  // 12 factors: p(0) > 0, outside at the start
        }
    }
}
