// Node::firstSurface of the root-isolated primitives (implicit, torus), which stops the search
// at the first decided crossing, against the default it overrides: all spans, then
// firstSurfaceOf. The crossings found before the stop are those of the full search, so the
// two must agree bit for bit: same t, normal, entering flag, material and primitive.
// Also: the along-ray enclosures that isolation relies on, where sin and cos of one operand
// share a single sinCos, hold the exact f and df/dt of the gyroid.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <sstream>

#include "csg/tape/expr.h"
#include "csg/tape/tape.h"
#include "csg/tree/solids.h"
#include "util/oracles.h"
#include "util/random_solids.h"

using namespace kerf;
using kerf::test::gaussianUnit;

namespace {

/// sin(4x)·cos(4y) + sin(4y)·cos(4z) + sin(4z)·cos(4x), as in models/cup.kerf.
std::shared_ptr<const Tape> gyroidTape() {
    ExprGraph g;
    const ExprId four = g.constant(4.0);
    const ExprId x = g.binary(Op::Mul, four, g.x()), y = g.binary(Op::Mul, four, g.y()),
                 z = g.binary(Op::Mul, four, g.z());
    auto term = [&](ExprId a, ExprId b) {
        return g.binary(Op::Mul, g.unary(Op::Sin, a), g.unary(Op::Cos, b));
    };
    const ExprId f = g.binary(Op::Add, g.binary(Op::Add, term(x, y), term(y, z)), term(z, x));
    return Tape::compile(g, f);
}

NodePtr gyroid() { return makeImplicit(gyroidTape(), {Vec3(-1.0), Vec3(1.0)}); }

struct Comparison {
    int rays = 0;
    int hits = 0;
    int mismatches = 0;
    std::string firstMismatch;
    TraceStats early, full;  ///< the override's and the default's work
};

/// True when the first span the ray meets, found at a tolerance near double precision, is
/// thinner than `tolerance`·|t| (twice that, for its ends' own errors): spans that thin vanish
/// by design at `tolerance` (csg/trace_context.h), so a search that keeps one agrees within it.
bool thinAtTolerance(const Node& node, const Ray& ray, double tmin, double tmax, double tolerance) {
    TraceContext fine;
    fine.relTolerance = 1e-12;
    SpanList spans;
    node.spans(ray, tmin, tmax, fine, spans);
    if (spans.empty()) return false;
    const Span& first = spans[0];
    return first.out.t - first.in.t <= 2.0 * tolerance * std::fabs(first.in.t);
}

/// Compares the override with the default on one ray; records the first disagreement (a
/// thin span one keeps and the other drops is no disagreement when `withinTolerance`).
void compareOne(const Node& node, const Ray& ray, double tmin, double tmax, double tolerance,
                Comparison& c, bool withinTolerance = false) {
    TraceContext early, full;
    early.relTolerance = full.relTolerance = tolerance;
    Boundary a, b;
    bool enteringA = false, enteringB = false;
    const bool foundA = node.firstSurface(ray, tmin, tmax, early, a, enteringA);
    const bool foundB = node.Node::firstSurface(ray, tmin, tmax, full, b, enteringB);
    c.early += early.stats;
    c.full += full.stats;
    ++c.rays;
    if (foundB) ++c.hits;
    const bool same =
        foundA == foundB &&
        (!foundA || (withinTolerance ? std::fabs(a.t - b.t) <= tolerance * std::fabs(b.t) &&
                                           enteringA == enteringB
                                     : a.t == b.t && a.normal == b.normal &&
                                           enteringA == enteringB && a.material == b.material &&
                                           a.primitive == b.primitive && a.relError == b.relError));
    if (same) return;
    if (withinTolerance && foundA != foundB && thinAtTolerance(node, ray, tmin, tmax, tolerance))
        return;
    if (c.mismatches++ > 0) return;
    std::ostringstream s;
    s.precision(17);
    s << "ray o=(" << ray.origin.x << ", " << ray.origin.y << ", " << ray.origin.z << ") d=("
      << ray.dir.x << ", " << ray.dir.y << ", " << ray.dir.z << ") t in [" << tmin << ", " << tmax
      << "] tol " << tolerance << ": early " << foundA << " t=" << a.t << " entering " << enteringA
      << " material " << a.material << "; default " << foundB << " t=" << b.t << " entering "
      << enteringB << " material " << b.material;
    c.firstMismatch = s.str();
}

/// Random rays around a box `half` wide about `centre` (in the node's space): origins outside
/// and inside, directions of any length, and ranges that start late or end early.
Comparison compareRandom(const Node& node, const Vec3& centre, double half, int count,
                         uint64_t seed, bool withinTolerance = false) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Comparison c;
    for (int i = 0; i < count; ++i) {
        const double tolerance = i % 3 == 0 ? 1e-9 : (i % 3 == 1 ? 5e-4 : 2e-2);
        const Vec3 origin =
            centre + half *
                         Vec3(2.0 * unit(rng) - 1.0, 2.0 * unit(rng) - 1.0, 2.0 * unit(rng) - 1.0) *
                         (i % 4 == 0 ? 0.6 : 2.5);
        const Vec3 target = centre + 0.7 * half * gaussianUnit(rng) * unit(rng);
        const Vec3 dir = glm::normalize(target - origin) * (0.05 + 4.0 * unit(rng));
        const Ray ray{origin, dir};
        const double reach = 6.0 * half / glm::length(dir);  // t across the whole region
        const double tmin = i % 5 == 1 ? reach * unit(rng) * 0.5 : 0.0;
        const double tmax = i % 7 == 2 ? tmin + reach * unit(rng) : kInf;
        compareOne(node, ray, tmin, tmax, tolerance, c, withinTolerance);
    }
    return c;
}

void requireAgreement(const Comparison& c) {
    INFO(c.firstMismatch);
    INFO(c.rays << " rays, " << c.hits << " hits; interval evaluations " << c.early.intervalEvals
                << " (early stop) vs " << c.full.intervalEvals << " (all spans)");
    REQUIRE(c.mismatches == 0);
    REQUIRE(c.hits > c.rays / 5);  // the rays do meet the surface
    // Stopping early never costs more, and on these shapes saves at least a fifth.
    REQUIRE(c.early.intervalEvals <= c.full.intervalEvals * 4 / 5);
}

}  // namespace

TEST_CASE("Implicit::firstSurface") {
    const NodePtr g = gyroid();
    SECTION("equals the first surface of the spans on random rays") {
        requireAgreement(compareRandom(*g, Vec3(0.0), 1.0, 3000, 11));
    }
    SECTION("inside a material and a transform, at ordinary and extreme scales") {
        for (double scale : {0.8, 1e-6, 1e6}) {
            const Affine map = Affine::translate(Vec3(3.0, 1.0, 0.0) * scale)
                                   .after(Affine::rotateDegrees(Vec3(10.0, 30.0, -20.0)))
                                   .after(Affine::scale(Vec3(scale)));
            const NodePtr wrapped = makeTransform(makeMaterial(g, 3), map);
            INFO("scale " << scale);
            requireAgreement(compareRandom(*wrapped, Vec3(3.0, 1.0, 0.0) * scale, scale, 1500, 17));
        }
    }
}

TEST_CASE("Torus::firstSurface") {
    const NodePtr torus = makeTorus(1.0, 0.3);
    SECTION("equals the first surface of the spans on random rays") {
        requireAgreement(compareRandom(*torus, Vec3(0.0), 1.3, 3000, 23));
    }
    SECTION("inside a transform and a material") {
        const Affine map = Affine::translate(Vec3(-2.0, 0.5, 4.0))
                               .after(Affine::rotateDegrees(Vec3(70.0, 0.0, 15.0)));
        const NodePtr wrapped = makeMaterial(makeTransform(torus, map), 5);
        requireAgreement(compareRandom(*wrapped, Vec3(-2.0, 0.5, 4.0), 1.3, 2000, 29));
    }
    SECTION("hard cases: tangent rays, a start on the surface, ranges cut between crossings") {
        Comparison c;
        const Vec3 x(1.0, 0.0, 0.0), y(0.0, 1.0, 0.0), z(0.0, 0.0, 1.0);
        for (double tolerance : {1e-9, 1e-3}) {
            // Tangent to the top of the tube and to the inner equator: double roots.
            compareOne(*torus, {Vec3(1.0, 0.3, -3.0), z}, 0.0, kInf, tolerance, c);
            compareOne(*torus, {Vec3(0.7, -2.0, 0.0), y}, 0.0, kInf, tolerance, c);
            // Starting on the outer equator, going in; starting inside the tube (a −0 component).
            compareOne(*torus, {Vec3(1.3, 0.0, 0.0), -x}, 0.0, kInf, tolerance, c);
            compareOne(*torus, {Vec3(1.0, 0.0, 0.0), Vec3(-1.0, 0.0, -0.0)}, 0.0, kInf, tolerance,
                       c);
            // Through the centre in the equatorial plane: crossings at t = 1.7, 2.3, 3.7, 4.3.
            for (double tmin : {0.0, 2.0, 3.0, 4.0, 4.5})
                compareOne(*torus, {Vec3(-3.0, 0.0, 0.0), x}, tmin, kInf, tolerance, c);
            compareOne(*torus, {Vec3(-3.0, 0.0, 0.0), x}, 0.0, 1.5, tolerance, c);
        }
        INFO(c.firstMismatch);
        REQUIRE(c.mismatches == 0);

        // The equatorial ray against its closed form: from t = 2 the first surface is the exit
        // of the tube at x = −0.7, i.e. t = 2.3; from t = 0 the entry at t = 1.7.
        TraceContext ctx;
        Boundary hit;
        bool entering = true;
        const Ray ray{Vec3(-3.0, 0.0, 0.0), x};
        REQUIRE(torus->firstSurface(ray, 2.0, kInf, ctx, hit, entering));
        CHECK(hit.t == Approx(2.3).epsilon(1e-8));
        CHECK_FALSE(entering);
        CHECK(hit.normal.x > 0.0);  // the outward normal of the tube at x = −0.7 points to +x
        REQUIRE(torus->firstSurface(ray, 0.0, kInf, ctx, hit, entering));
        CHECK(hit.t == Approx(1.7).epsilon(1e-8));
        CHECK(entering);
        CHECK_FALSE(torus->firstSurface(ray, 0.0, 1.5, ctx, hit, entering));
    }
}

TEST_CASE("Tape::evalIntervalAlongRay with sin and cos of shared operands") {
    const auto tape = gyroidTape();
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int misses = 0;
    std::string firstMiss;
    for (int i = 0; i < 3000; ++i) {
        Ray ray{2.0 * gaussianUnit(rng) * unit(rng), gaussianUnit(rng) * (0.1 + 3.0 * unit(rng))};
        if (i % 10 == 0) ray.dir.y = 0.0;  // an axis the ray does not move along
        const double t0 = 2.0 * unit(rng) - 1.0, t1 = t0 + std::pow(10.0, -6.0 * unit(rng));
        Interval f, dfdt;
        tape->evalIntervalAlongRay(ray, Interval(t0, t1), f, dfdt);
        for (int k = 0; k < 8; ++k) {
            const long double t = t0 + (k == 0 ? 0.0 : k == 1 ? 1.0 : unit(rng)) * (t1 - t0);
            long double p[3], d[3];
            for (int a = 0; a < 3; ++a) p[a] = 4.0L * (ray.origin[a] + t * ray.dir[a]);
            for (int a = 0; a < 3; ++a) d[a] = 4.0L * ray.dir[a];
            long double value = 0.0L, slope = 0.0L;
            for (int a = 0; a < 3; ++a) {  // sin(p_a)·cos(p_{a+1})
                const int b = (a + 1) % 3;
                value += std::sin(p[a]) * std::cos(p[b]);
                slope +=
                    std::cos(p[a]) * d[a] * std::cos(p[b]) - std::sin(p[a]) * std::sin(p[b]) * d[b];
            }
            // The long-double reference is itself rounded: allow a few of its ulps.
            const long double slack = 1e-15L;
            if (f.lo <= value + slack && value - slack <= f.hi && dfdt.lo <= slope + slack &&
                slope - slack <= dfdt.hi)
                continue;
            if (misses++ == 0) {
                std::ostringstream s;
                s.precision(17);
                s << "t in [" << t0 << ", " << t1 << "]: f " << double(value) << " in [" << f.lo
                  << ", " << f.hi << "], df/dt " << double(slope) << " in [" << dfdt.lo << ", "
                  << dfdt.hi << "]";
                firstMiss = s.str();
            }
        }
    }
    INFO(firstMiss);
    REQUIRE(misses == 0);
}

TEST_CASE("HalfSpace::firstSurface") {
    // The override skips the span list; it must give the default's boundary bit for bit,
    // including rays parallel to the plane (±0 dot products), rays starting on the plane,
    // ranges that end before or start after the crossing, and tilted planes whose dot
    // products cancel (the compensated path).
    Comparison c;
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const NodePtr planes[] = {
        makeHalfSpace(Vec3(0.0, 1.0, 0.0), 0.0), makeHalfSpace(Vec3(0.0, -2.0, 0.0), 0.5),
        makeHalfSpace(Vec3(1.0, 1e-9, -3.0), 2.0), makeHalfSpace(Vec3(0.3, 0.4, 0.5), -1e6)};
    for (const NodePtr& plane : planes) {
        for (int i = 0; i < 4000; ++i) {
            Vec3 origin(unit(rng), unit(rng), unit(rng));
            Vec3 dir(unit(rng), unit(rng), unit(rng));
            if (i % 5 == 1) dir.y = (i % 2 ? 0.0 : -0.0);  // parallel to the axis planes
            if (i % 7 == 2) origin.y = 0.0;                // on the floor
            if (i % 11 == 3) origin *= 1e7;                // far away: cancelling dots
            const double tmin = i % 3 == 1 ? std::fabs(unit(rng)) : 0.0;
            const double tmax = i % 4 == 2 ? tmin + std::fabs(unit(rng)) : kInf;
            compareOne(*plane, {origin, dir}, tmin, tmax, 1e-9, c);
        }
        // Straight at the plane, along it, and from on it.
        compareOne(*plane, {Vec3(0.0, 1.0, 0.0), Vec3(0.0, -1.0, 0.0)}, 0.0, kInf, 1e-9, c);
        compareOne(*plane, {Vec3(0.0, 1.0, 0.0), Vec3(1.0, 0.0, 0.0)}, 0.0, kInf, 1e-9, c);
        compareOne(*plane, {Vec3(0.0, 0.0, 0.0), Vec3(0.0, 1.0, 0.0)}, 0.0, kInf, 1e-9, c);
        compareOne(*plane, {Vec3(0.0, 0.0, 0.0), Vec3(0.0, -1.0, 0.0)}, 0.0, kInf, 1e-9, c);
    }
    // Under a transform and a material, as the objects of a scene are.
    const NodePtr wrapped =
        makeMaterial(makeTransform(planes[2], Affine::rotateDegrees(Vec3(20.0, 0.0, 45.0))), 4);
    for (int i = 0; i < 2000; ++i)
        compareOne(
            *wrapped,
            {Vec3(unit(rng), unit(rng), unit(rng)) * 3.0, Vec3(unit(rng), unit(rng), unit(rng))},
            0.0, kInf, 1e-9, c);
    INFO(c.firstMismatch);
    REQUIRE(c.mismatches == 0);
    REQUIRE(c.hits > c.rays / 4);
    REQUIRE(c.early.primitiveTests == c.full.primitiveTests);  // the same work counted
}

TEST_CASE("Union::firstSurface") {
    // Unions of random primitives of every kind (shared face planes, half-spaces, implicit
    // boxes, tori), narrow ones searched child by child and wide ones through their BVH: the
    // early search must give what the union's spans give: found or not, the side crossed, and
    // t within the tolerance (root-found children are searched over a shorter range, so
    // their polish may end an ulp elsewhere).
    kerf::test::Random rnd(2024);
    for (int trial = 0; trial < 60; ++trial) {
        const int count = trial % 3 == 0 ? 12 : 2 + trial % 4;
        std::vector<NodePtr> kids;
        for (int k = 0; k < count; ++k) {
            const kerf::test::PrimitiveKind kind = kerf::test::randomKind(rnd);
            if (kind == kerf::test::PrimitiveKind::HalfSpace && trial % 2 == 0) continue;
            kids.push_back(makeMaterial(kerf::test::randomPrimitive(rnd, kind), k % 3));
        }
        if (kids.empty()) continue;
        const NodePtr u = makeBoolean(BoolOp::Union, kids);
        INFO("trial " << trial << ", " << kids.size() << " children");
        const Comparison c = compareRandom(*u, Vec3(0.0), 1.5, 300, 100 + uint64_t(trial), true);
        INFO(c.firstMismatch);
        REQUIRE(c.mismatches == 0);
        REQUIRE(c.hits > 0);
    }
}

TEST_CASE("Implicit::firstSurface for shadow rays (occlusion only)") {
    // Shadow rays ask only where a surface is: the crossing may be polished to the tolerance
    // instead of double precision, and get no normal. Found or not and the side crossed must
    // not change, and t must stay within the tolerance of the full search's.
    const NodePtr g =
        makeTransform(makeMaterial(gyroid(), 1), Affine::rotateDegrees(Vec3(15.0, -30.0, 5.0)));
    std::mt19937_64 rng(99);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
        const double tolerance = i % 2 ? 1e-3 : 1e-7;
        const Vec3 origin = 2.5 * Vec3(2 * unit(rng) - 1, 2 * unit(rng) - 1, 2 * unit(rng) - 1);
        const Ray ray{origin, gaussianUnit(rng)};
        TraceContext full, shadow;
        full.relTolerance = shadow.relTolerance = tolerance;
        Boundary a, b;
        bool ea = false, eb = false;
        const bool fa = g->firstSurface(ray, 0.0, kInf, full, a, ea);
        bool fb;
        {
            const OcclusionScope scope(shadow);
            fb = g->firstSurface(ray, 0.0, kInf, shadow, b, eb);
        }
        CHECK_FALSE(shadow.occlusionOnly);  // the scope restored it
        INFO("ray " << i << " tolerance " << tolerance << ": full " << fa << " t=" << a.t
                    << ", shadow " << fb << " t=" << b.t);
        REQUIRE(fa == fb);
        if (!fa) continue;
        ++hits;
        REQUIRE(ea == eb);
        REQUIRE(std::fabs(a.t - b.t) <= tolerance * std::fabs(a.t));
        REQUIRE(glm::length(a.normal) > 0.0);  // the full search's normal is there
    }
    CHECK(hits > 300);  // the rays do meet the surface
}

TEST_CASE("Intersection::firstSurface guided by a closed-form operand") {
    // A root-found operand (implicit, torus) intersected with a closed-form one is searched
    // only inside the closed-form operand's spans, up to its first crossing there. Found or
    // not and the side crossed must be what the intersection's spans give, and t within the
    // tolerance (the root-found operand is searched over shorter ranges, so its polish may
    // end an ulp elsewhere). Both operand orders, rays from outside and from inside, ranges
    // cut short, and guides that cut the surface in several places.
    const NodePtr g = gyroid();
    const NodePtr guides[] = {makeSphere(Vec3(0.0), 0.8), makeSphere(Vec3(0.3, -0.2, 0.1), 0.45),
                              makeBox(Vec3(-0.7, -0.3, -0.9), Vec3(0.6, 0.5, 0.2)),
                              makeCylinder(Vec3(0.0, -1.0, 0.0), Vec3(0.0, 1.0, 0.0), 0.6),
                              makeHalfSpace(Vec3(0.2, 1.0, -0.3), 0.1)};
    int guided = 0;
    uint64_t earlyEvals = 0, fullEvals = 0;
    for (const NodePtr& guide : guides) {
        for (bool guideFirst : {false, true}) {
            std::vector<NodePtr> kids{makeMaterial(g, 1), makeMaterial(guide, 2)};
            if (guideFirst) std::swap(kids[0], kids[1]);
            const NodePtr both = makeBoolean(BoolOp::Intersection, kids);
            const Comparison c =
                compareRandom(*both, Vec3(0.0), 1.0, 1500, 300 + uint64_t(guided), true);
            INFO("guide " << guided << (guideFirst ? " first" : " second") << ": "
                          << c.firstMismatch);
            REQUIRE(c.mismatches == 0);
            REQUIRE(c.hits > c.rays / 10);
            earlyEvals += c.early.intervalEvals;
            fullEvals += c.full.intervalEvals;
        }
        ++guided;
    }
    // Searching the implicit only inside the guide, up to its first crossing there, saves
    // evaluations over these guides (on a small guide the checks for slivers can cost more).
    CHECK(earlyEvals <= fullEvals * 9 / 10);
    SECTION("a torus clipped by a half-space, and tangent rays along the clip") {
        const NodePtr clipped = makeBoolean(
            BoolOp::Intersection, {makeTorus(1.0, 0.3), makeHalfSpace(Vec3(1.0, 0.0, 0.0), 0.5)});
        Comparison c = compareRandom(*clipped, Vec3(0.0), 1.3, 2000, 41, true);
        const Vec3 z(0.0, 0.0, 1.0);
        compareOne(*clipped, {Vec3(0.5, 0.0, -3.0), z}, 0.0, kInf, 1e-9, c, true);  // on the plane
        compareOne(*clipped, {Vec3(1.0, 0.3, -3.0), z}, 0.0, kInf, 1e-9, c, true);  // tangent
        compareOne(*clipped, {Vec3(1.0, 0.0, 0.0), z}, 0.0, kInf, 1e-9, c, true);   // inside
        INFO(c.firstMismatch);
        REQUIRE(c.mismatches == 0);
        REQUIRE(c.hits > c.rays / 10);
    }
}

TEST_CASE("Intersection::firstSurface: a span thinner than the tolerance agrees within it") {
    // Found by a clang build's random rays: the sphere enters at t = 0.634 inside the gyroid's
    // span [0.4727, 0.6437], so the intersection's span is 1.5% of t thick, under the 2%
    // tolerance. spans() drops it, the guided search keeps it; both are within the tolerance.
    std::vector<NodePtr> kids{makeMaterial(gyroid(), 1),
                              makeMaterial(makeSphere(Vec3(0.3, -0.2, 0.1), 0.45), 2)};
    const NodePtr both = makeBoolean(BoolOp::Intersection, kids);
    const Ray ray{Vec3(-2.0040421756874536, 0.31136960427763261, -1.1486515636220027),
                  Vec3(3.0601491244595946, -0.43129580637795822, 1.785009650158067)};
    REQUIRE(thinAtTolerance(*both, ray, 0.0, kInf, 0.02));
    REQUIRE_FALSE(thinAtTolerance(*both, ray, 0.0, kInf, 0.001));
    Comparison c;
    compareOne(*both, ray, 0.0, kInf, 0.02, c, true);
    CHECK(c.mismatches == 0);
    compareOne(*both, ray, 0.0, kInf, 0.001, c, true);  // kept by both at a finer tolerance
    CHECK(c.mismatches == 0);
    CHECK(c.hits == 1);
}
