// TraceContext::method: interval isolation of every primitive's implicit form agrees with the
// closed forms within the tolerance; sphere tracing agrees on easy rays and misses a grazing
// thin shell that the other two find (the point of the comparison).
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "csg/tape/expr.h"
#include "csg/tape/tape.h"
#include "csg/tree/solids.h"
#include "util/oracles.h"

using namespace kerf;
using namespace kerf::test;

namespace {

/// One surface crossing within the searched range.
struct Crossing {
    double t;
    bool entering;
    Vec3 normal;
};

/// The surface crossings with tmin < t < tmax of the spans the method gives, spans thinner
/// than `thin`·|t| left out (a tangency, where hit/miss may differ within the tolerance).
std::vector<Crossing> crossings(const Node& node, const Ray& ray, TraceMethod method,
                                double tolerance, double thin, double tmin = 0.0,
                                double tmax = kInf, TraceStats* stats = nullptr) {
    TraceContext ctx;
    ctx.method = method;
    ctx.relTolerance = tolerance;
    SpanList spans;
    node.spans(ray, tmin, tmax, ctx, spans);
    if (stats) *stats += ctx.stats;
    std::vector<Crossing> out;
    for (const Span& s : spans) {
        REQUIRE(s.in.t <= s.out.t);
        const double scale = std::fmax(std::fabs(s.in.t), std::fabs(s.out.t));
        const double width = s.out.t - s.in.t;
        if (std::isfinite(width) && width <= thin * scale) continue;
        if (s.in.isSurface() && s.in.t > tmin && s.in.t < tmax)
            out.push_back({s.in.t, true, s.in.normal});
        if (s.out.isSurface() && s.out.t > tmin && s.out.t < tmax)
            out.push_back({s.out.t, false, s.out.normal});
    }
    return out;
}

/// Each test case reseeds, so its rays do not depend on which other cases ran.
Random gRnd;

/// From 6 units away towards a point near the centre (about half of them hit), with a
/// direction of random length, so t is not a distance.
Ray randomRay(const Vec3& centre) {
    Ray r;
    r.origin = centre + 6.0 * gRnd.gaussianUnitVector();
    const Vec3 target =
        centre + Vec3(gRnd.uniform(-1.8, 1.8), gRnd.uniform(-1.8, 1.8), gRnd.uniform(-1.8, 1.8));
    r.dir = (target - r.origin) * gRnd.uniform(0.05, 3.0);
    return r;
}

struct Named {
    std::string name;
    NodePtr node;
    Vec3 centre;
};

std::vector<Named> closedFormPrimitives() {
    return {
        {"sphere", makeSphere(Vec3(0.3, -0.2, 0.1), 1.3), Vec3(0.3, -0.2, 0.1)},
        {"box", makeBox(Vec3(-1.0, -0.5, -0.8), Vec3(1.2, 0.7, 0.9)), Vec3(0.1, 0.1, 0.05)},
        {"cylinder", makeCylinder(Vec3(-0.3, -1.0, 0.2), Vec3(0.5, 1.1, -0.1), 0.7), Vec3(0.0)},
        {"cone", makeCone(Vec3(0.1, -1.0, 0.0), Vec3(-0.2, 1.0, 0.3), 0.9, 0.2), Vec3(0.0)},
        {"cone to a point", makeCone(Vec3(0.0, 0.0, -1.2), Vec3(0.0, 0.0, 1.0), 1.1, 0.0),
         Vec3(0.0)},
        {"axis-aligned cylinder", makeCylinder(Vec3(0.0, -1.0, 0.0), Vec3(0.0, 1.0, 0.0), 1.0),
         Vec3(0.0)},
        {"half-space", makeHalfSpace(Vec3(0.3, 1.0, -0.5), 0.4), Vec3(0.0)},
    };
}

std::shared_ptr<const Tape> sphereTape(double radius) {
    ExprGraph g;
    const ExprId s =
        g.binary(Op::Add, g.binary(Op::Add, g.unary(Op::Square, g.x()), g.unary(Op::Square, g.y())),
                 g.unary(Op::Square, g.z()));
    return Tape::compile(g, g.binary(Op::Sub, s, g.constant(radius * radius)));
}

}  // namespace

TEST_CASE("TraceMethod::Interval agrees with the closed forms") {
    for (const double tolerance : {1e-6, 1e-12}) {
        for (const Named& p : closedFormPrimitives()) {
            SECTION(p.name + " at tolerance " + std::to_string(tolerance)) {
                gRnd.seed(20240611);
                int hits = 0;
                double worst = 0.0;
                for (int i = 0; i < 3000; ++i) {
                    const Ray ray = randomRay(p.centre);
                    // Thin spans (tangencies) may differ: the isolation drops what is thinner
                    // than its tolerance. 4× covers where the bisection stops.
                    const double thin = 4.0 * tolerance;
                    const auto closed =
                        crossings(*p.node, ray, TraceMethod::Closed, tolerance, thin);
                    const auto interval =
                        crossings(*p.node, ray, TraceMethod::Interval, tolerance, thin);
                    INFO("ray " << i << " origin " << ray.origin.x << ' ' << ray.origin.y << ' '
                                << ray.origin.z << " dir " << ray.dir.x << ' ' << ray.dir.y << ' '
                                << ray.dir.z);
                    REQUIRE(interval.size() == closed.size());
                    hits += !closed.empty();
                    for (size_t k = 0; k < closed.size(); ++k) {
                        const double t = closed[k].t;
                        const double err = std::fabs(interval[k].t - t) / std::fabs(t);
                        worst = std::fmax(worst, err);
                        // The tolerance, plus the closed form's own rounding.
                        CHECK(err <= tolerance + 1e-14);
                        CHECK(interval[k].entering == closed[k].entering);
                        const Vec3 a = glm::normalize(interval[k].normal);
                        const Vec3 b = glm::normalize(closed[k].normal);
                        CHECK(glm::dot(a, b) > 1.0 - 1e-6);
                    }
                }
                CHECK(hits > 600);  // both hits and misses are exercised
                CHECK(3000 - hits > 200);
                INFO(p.name << " worst relative difference " << worst);
                CHECK(worst <= tolerance + 1e-14);
            }
        }
    }
}

TEST_CASE("TraceMethod::Interval is the closed method for the implicit") {
    const NodePtr implicit = makeImplicit(sphereTape(1.0), {Vec3(-2.0), Vec3(2.0)});
    gRnd.seed(7);
    for (int i = 0; i < 500; ++i) {
        const Ray ray = randomRay(Vec3(0.0));
        const auto a = crossings(*implicit, ray, TraceMethod::Closed, 1e-9, 0.0);
        const auto b = crossings(*implicit, ray, TraceMethod::Interval, 1e-9, 0.0);
        REQUIRE(a.size() == b.size());
        for (size_t k = 0; k < a.size(); ++k) CHECK(a[k].t == b[k].t);
    }
}

TEST_CASE("TraceMethod::Closed of the torus agrees with its interval isolation") {
    // The torus' closed method (convex pieces of its distance form, csg/primitives/torus_roots.h)
    // is a fast path for the interval isolation of its quartic: the same crossings within the
    // tolerance, spans thinner than it (tangencies) aside.
    gRnd.seed(7);
    for (const double tolerance : {1e-6, 1e-9, 1e-12}) {
        for (const double minor : {0.3, 0.02, 0.9}) {
            const NodePtr torus = makeTorus(1.0, minor);
            for (int i = 0; i < 500; ++i) {
                const Ray ray = randomRay(Vec3(0.0));
                const auto a =
                    crossings(*torus, ray, TraceMethod::Closed, tolerance, 4 * tolerance);
                const auto b =
                    crossings(*torus, ray, TraceMethod::Interval, tolerance, 4 * tolerance);
                INFO("minor " << minor << " tolerance " << tolerance << " ray " << i);
                REQUIRE(a.size() == b.size());
                for (size_t k = 0; k < a.size(); ++k) {
                    CHECK(std::fabs(a[k].t - b[k].t) <= tolerance * std::fabs(b[k].t));
                    CHECK(a[k].entering == b[k].entering);
                }
            }
        }
    }
}

TEST_CASE("TraceMethod::Interval spans are exact on [tmin, tmax] and clipped outside") {
    const NodePtr sphere = makeSphere(Vec3(0.0), 1.0);
    const Ray ray{Vec3(0.0, 0.0, -3.0), Vec3(0.0, 0.0, 1.0)};
    TraceContext ctx;
    ctx.method = TraceMethod::Interval;
    SpanList spans;
    sphere->spans(ray, 2.5, 10.0, ctx, spans);  // starts inside
    REQUIRE(spans.size() == 1);
    CHECK(spans[0].in.t == 2.5);
    CHECK_FALSE(spans[0].in.isSurface());
    CHECK(spans[0].out.t == Approx(4.0).epsilon(1e-15));
    CHECK(spans[0].out.relError == float(ctx.relTolerance));
    CHECK(ctx.stats.rootSteps > 0);
    CHECK(ctx.stats.intervalEvals > 0);
}

TEST_CASE("TraceMethod::SphereTrace agrees with the closed forms on easy rays") {
    const auto check = [](const Node& node, const Ray& ray, double tolerance) {
        TraceStats stats;
        INFO("ray from " << ray.origin.x << ' ' << ray.origin.y << ' ' << ray.origin.z
                         << " tolerance " << tolerance);
        const auto closed = crossings(node, ray, TraceMethod::Closed, tolerance, 0.0);
        const auto traced =
            crossings(node, ray, TraceMethod::SphereTrace, tolerance, 0.0, 0.0, kInf, &stats);
        REQUIRE(closed.size() == 2);
        REQUIRE(traced.size() == closed.size());
        CHECK(stats.rootSteps > 0);
        for (size_t k = 0; k < closed.size(); ++k) {
            // A head-on hit stops within the tolerance band: |Δt| ≤ tolerance·t (·2 for the
            // step taken past the entry before the exit search).
            CHECK(std::fabs(traced[k].t - closed[k].t) <= 2.0 * tolerance * closed[k].t);
            CHECK(traced[k].entering == closed[k].entering);
            CHECK(glm::dot(glm::normalize(traced[k].normal), glm::normalize(closed[k].normal)) >
                  0.999);
        }
    };
    for (const double tolerance : {1e-6, 1e-9}) {
        check(*makeSphere(Vec3(0.0), 1.0), {Vec3(0.1, 0.2, -5.0), Vec3(0.0, 0.0, 2.0)}, tolerance);
        check(*makeBox(Vec3(-1.0), Vec3(1.0)), {Vec3(0.3, 0.2, -5.0), Vec3(0.0, 0.0, 1.0)},
              tolerance);
        check(*makeCylinder(Vec3(0.0, -1.0, 0.0), Vec3(0.0, 1.0, 0.0), 1.0),
              {Vec3(-4.0, 0.2, 0.1), Vec3(1.0, 0.0, 0.0)}, tolerance);
        check(*makeCone(Vec3(0.0, -1.0, 0.0), Vec3(0.0, 1.0, 0.0), 1.0, 0.5),
              {Vec3(-4.0, 0.0, 0.1), Vec3(1.0, 0.0, 0.0)}, tolerance);
        check(*makeImplicit(sphereTape(1.0), {Vec3(-2.0), Vec3(2.0)}),
              {Vec3(0.1, 0.2, -5.0), Vec3(0.0, 0.0, 1.0)}, tolerance);
        // The torus seen along its axis through the tube: entry and exit of one side.
        check(*makeTorus(1.0, 0.3), {Vec3(1.0, 5.0, 0.05), Vec3(0.0, -1.0, 0.0)}, tolerance);
    }
}

TEST_CASE("TraceMethod::SphereTrace misses a grazing thin shell that Interval and Closed find") {
    // A shell of thickness 1e-4 of its radius; the ray passes 2e-5 inside the outer surface, so
    // it meets the shell (the outer sphere only) at an angle of ~0.36° to the surface.
    const NodePtr shell = makeBoolean(
        BoolOp::Difference, {makeSphere(Vec3(0.0), 1.0), makeSphere(Vec3(0.0), 1.0 - 1e-4)});
    const double d = 1.0 - 2e-5;
    const Ray ray{Vec3(-3.0, d, 0.0), Vec3(1.0, 0.0, 0.0)};
    const double entry = 3.0 - std::sqrt(1.0 - d * d);  // 3 − √((1 − d)(1 + d))
    for (const double tolerance : {1e-6, 1e-9}) {
        const auto closed = crossings(*shell, ray, TraceMethod::Closed, tolerance, 0.0);
        const auto interval = crossings(*shell, ray, TraceMethod::Interval, tolerance, 0.0);
        REQUIRE(closed.size() == 2);
        REQUIRE(interval.size() == 2);
        CHECK(closed[0].t == Approx(entry).epsilon(1e-12));
        CHECK(std::fabs(interval[0].t - entry) <= tolerance * entry + 1e-12);
        TraceStats stats;
        const auto traced =
            crossings(*shell, ray, TraceMethod::SphereTrace, tolerance, 0.0, 0.0, kInf, &stats);
        CHECK(traced.empty());  // gave up after kSphereTraceMaxSteps steps creeping closer
        CHECK(stats.rootSteps >= 512);
    }
}
