// Op::Field, an external scalar field in a tape (csg/tape/scalar_field.h): two fields kept apart by
// the graph and the tape; every evaluator against the closed forms of a sphere's and a box's
// signed distances (point, long double, gradient, slope along a ray; interval enclosures of
// dense samples, and the exact range where the tape is the field alone); and tracing, as an
// implicit and as a primitive whose comparison stand-in calls the field, against the analytic
// hits of the sphere.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <stdexcept>

#include "csg/primitives/comparison_methods.h"
#include "csg/primitives/implicit_expr.h"
#include "csg/primitives/primitive.h"
#include "csg/tape/expr.h"
#include "csg/tape/tape.h"
#include "csg/tape/tape_ray_program.h"
#include "csg/tape/tree_tape.h"
#include "csg/trace_context.h"
#include "csg/tree/solids.h"
#include "util/oracles.h"
#include "util/test_fields.h"

using namespace kerf;
using kerf::test::BoxField;
using kerf::test::gaussianUnit;
using kerf::test::SphereField;
using LV = glm::tvec3<long double>;

namespace {

const Vec3 kCentre(0.2, -0.1, 0.3);
constexpr double kRadius = 0.9;

auto sphereField() { return std::make_shared<SphereField>(kCentre, kRadius); }
auto boxField() { return std::make_shared<BoxField>(Vec3(-0.3, 0.4, 0.1), Vec3(0.5, 0.3, 0.7)); }

/// The sphere's field alone: f = A(x, y, z).
std::shared_ptr<const Tape> sphereTape(const std::shared_ptr<const ScalarField>& a) {
    ExprGraph g;
    return Tape::compile(g, g.field(g.x(), g.y(), g.z(), a));
}

/// min(A(2x, y + 0.5z, z) − 0.1x, B(x, y, z)): both fields, their operands mapped (the chain
/// rule), a min to decide.
std::shared_ptr<const Tape> mixedTape(const std::shared_ptr<const ScalarField>& a,
                                      const std::shared_ptr<const ScalarField>& b) {
    ExprGraph g;
    ExprBuilder e{g};
    const ExprId x = g.x(), y = g.y(), z = g.z();
    const ExprId fa = g.field(e.mul(e.c(2.0), x), e.add(y, e.mul(e.c(0.5), z)), z, a);
    return Tape::compile(g, g.binary(Op::Min, e.sub(fa, e.mul(e.c(0.1), x)), g.field(x, y, z, b)));
}

/// The mixed tape's closed form in long double, and its gradient (the branch min takes).
struct Mixed {
    SphereField a{kCentre, kRadius};
    BoxField b = *boxField();

    LV mapA(const LV& p) const { return {2.0L * p.x, p.y + 0.5L * p.z, p.z}; }
    long double branchA(const LV& p) const {
        return a.valueExtended(mapA(p)) - (long double)0.1 * p.x;
    }
    long double value(const LV& p) const { return std::min(branchA(p), b.valueExtended(p)); }
    /// The gradient where the two branches are apart (false at a near tie).
    bool gradient(const Vec3& p, Vec3& out) const {
        const LV q(p);
        const long double fa = branchA(q), fb = b.valueExtended(q);
        if (std::fabs(fa - fb) < 1e-9L) return false;
        if (fb < fa) {
            b.valueGradient(p, out);  // the box's closed-form gradient (one face or a corner)
            return true;
        }
        const LV d = mapA(q) - LV(kCentre);
        const LV n = d / std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);  // ∇A at the mapped point
        out = Vec3(double(2.0L * n.x - 0.1L), double(n.y), double(0.5L * n.y + n.z));
        return true;
    }
};

/// Points of the box: a 5³ grid (faces and corners included) and random ones.
template <typename F>
void forSamples(const Bounds3& box, std::mt19937_64& rng, F&& f) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j)
            for (int k = 0; k < 5; ++k) f(box.lo + (box.hi - box.lo) * (Vec3(i, j, k) / 4.0));
    for (int s = 0; s < 60; ++s)
        f(box.lo + (box.hi - box.lo) * Vec3(unit(rng), unit(rng), unit(rng)));
}

Bounds3 randomBox(std::mt19937_64& rng, double size) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const Vec3 lo = (Vec3(unit(rng), unit(rng), unit(rng)) - 0.5) * 4.0;
    return {lo, lo + Vec3(unit(rng), unit(rng), unit(rng)) * size};
}

/// A leaf whose implicit form is the field (as a mesh's will be), traced only by the
/// comparison methods: its Interval stand-in compiles a tape that calls the field.
class FieldPrimitive final : public Primitive {
public:
    FieldPrimitive(std::shared_ptr<const SphereField> f) : mField(std::move(f)) {
        mBounds = {kCentre - Vec3(kRadius * 1.01), kCentre + Vec3(kRadius * 1.01)};
    }
    void spans(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
               SpanList& out) const override {
        comparisonSpans(*this, ray, tmin, tmax, ctx, out);
    }
    double value(const Vec3& p) const override { return mField->value(p); }
    Interval valueInterval(const IntervalVec3& b) const override {
        return mField->range(b.x, b.y, b.z);
    }
    long double valueExtended(const LVec3& p) const override { return mField->valueExtended(p); }
    NodeKind kind() const override { return NodeKind::Mesh; }
    NodeParams params() const override { return MeshParams{nullptr, false}; }
    ExprId implicitExpr(ExprGraph& g, ExprId x, ExprId y, ExprId z) const override {
        return g.field(x, y, z, mField);
    }

private:
    std::shared_ptr<const SphereField> mField;
};

/// The sphere's entry and exit along the ray in long double; false when it misses or grazes.
bool sphereHits(const Ray& ray, long double& t0, long double& t1) {
    const LV o = LV(ray.origin) - LV(kCentre), d(ray.dir);
    const long double a = glm::dot(d, d), b = glm::dot(o, d),
                      c = glm::dot(o, o) - (long double)kRadius * kRadius;
    const long double disc = b * b - a * c;
    if (disc <= 1e-12L * b * b) return false;  // near-tangent: within the reference's own doubt
    t0 = (-b - std::sqrt(disc)) / a;
    t1 = (-b + std::sqrt(disc)) / a;
    return true;
}

}  // namespace

TEST_CASE("field/the graph and the tape keep two fields apart") {
    const std::shared_ptr<const ScalarField> a = sphereField(), b = boxField();
    // Another object with a's geometry is another field: fields are told apart by identity.
    const auto a2 = sphereField();
    ExprGraph g;
    const ExprId x = g.x(), y = g.y(), z = g.z();
    const ExprId fa = g.field(x, y, z, a), fb = g.field(x, y, z, b), fa2 = g.field(x, y, z, a2);
    CHECK(g.field(x, y, z, a) == fa);  // hash-consed: one node, one table entry
    CHECK(fa != fb);
    CHECK(fa != fa2);
    REQUIRE(g.fields().size() == 3);
    CHECK_THROWS_AS(g.field(x, y, z, nullptr), std::invalid_argument);

    // A tape copies the fields it calls, renumbered in order of first use.
    const auto onlyB = Tape::compile(g, fb);
    REQUIRE(onlyB->fields().size() == 1);
    CHECK(onlyB->fields()[0] == b);
    const auto both = Tape::compile(g, g.binary(Op::Min, fb, fa));
    REQUIRE(both->fields().size() == 2);
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> coord(-2.0, 2.0);
    for (int i = 0; i < 200; ++i) {
        const Vec3 p(coord(rng), coord(rng), coord(rng));
        CHECK(onlyB->eval(p) == b->value(p));
        CHECK(both->eval(p) == std::min(a->value(p), b->value(p)));
    }
    // At a constant point the node stays a field call (no folding), so the long double
    // evaluator still reaches valueExtended.
    const ExprId atPoint = g.field(g.constant(1.5), g.constant(0.25), g.constant(-0.5), a);
    REQUIRE(g.nodes()[atPoint].op == Op::Field);
    const auto constant = Tape::compile(g, atPoint);
    CHECK(constant->eval(Vec3(9.0)) == a->value(Vec3(1.5, 0.25, -0.5)));
    CHECK(constant->evalExtended(LV(9.0L)) == a->valueExtended(LV(1.5L, 0.25L, -0.5L)));
}

TEST_CASE("field/point, long double, gradient and slope against the closed form") {
    const auto tape = mixedTape(sphereField(), boxField());
    const Mixed ref;
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> coord(-2.0, 2.0);
    double worstValue = 0.0, worstGradient = 0.0;
    for (int i = 0; i < 5000; ++i) {
        const Vec3 p(coord(rng), coord(rng), coord(rng));
        const long double exact = ref.value(LV(p));
        const double v = tape->eval(p);
        worstValue = std::max(worstValue, double(std::fabs(v - exact)));
        CHECK(std::fabs(tape->evalExtended(LV(p)) - exact) <= 1e-17L);
        Vec3 grad, expected;
        CHECK(tape->evalGradient(p, grad) == v);
        if (ref.gradient(p, expected))
            worstGradient = std::max(worstGradient, glm::length(grad - expected));
        // Along a ray through p: the same bits as eval, and df/dt = ∇f·d.
        const Ray ray{p - 0.5 * gaussianUnit(rng), gaussianUnit(rng) * 1.7};
        double dfdt;
        const Vec3 q = ray.at(0.5);
        CHECK(tape->evalAlongRay(ray, 0.5, dfdt) == tape->eval(q));
        Vec3 gq;
        tape->evalGradient(q, gq);
        CHECK(std::fabs(dfdt - glm::dot(gq, ray.dir)) <= 1e-15 * (1.0 + std::fabs(dfdt)));
    }
    CHECK(worstValue <= 1e-14);
    CHECK(worstGradient <= 1e-14);
}

TEST_CASE("field/interval evaluators enclose samples and give the field's exact range") {
    const auto a = sphereField();
    const auto alone = sphereTape(a), mixed = mixedTape(a, boxField());
    std::mt19937_64 rng(3);
    int boxes = 0;
    for (double size : {1e-9, 1e-3, 0.1, 0.7, 3.0}) {
        for (int i = 0; i < 150; ++i) {
            const Bounds3 box = randomBox(rng, size);
            const Interval x(box.lo.x, box.hi.x), y(box.lo.y, box.hi.y), z(box.lo.z, box.hi.z);
            // The field alone: its range is the closed form's, up to rounding.
            long double lo, hi;
            a->exactRange(box, lo, hi);
            const Interval r = alone->evalInterval(x, y, z);
            CHECK_FALSE(r.maybeNan);
            CHECK(r.lo <= lo);
            CHECK(r.hi >= hi);
            CHECK(lo - r.lo <= 1e-14L * (1.0L + std::fabs(lo)));
            CHECK(r.hi - hi <= 1e-14L * (1.0L + std::fabs(hi)));

            for (const auto& tape : {alone, mixed}) {
                const Interval f = tape->evalInterval(x, y, z);
                std::vector<Choice> choices;
                const Interval fc = tape->evalInterval(x, y, z, choices);
                const auto simpler = tape->simplified(choices);
                CHECK(simpler->fields().size() == tape->fields().size());
                // Four boxes at once, by each path: evalInterval's bits in every lane.
                const Interval xs[4] = {x, x, x, x}, ys[4] = {y, y, y, y}, zs[4] = {z, z, z, z};
                for (Tape::Lanes4 lanes :
                     {Tape::Lanes4::Scalar, Tape::Lanes4::Avx2, Tape::Lanes4::Auto}) {
                    Interval out[4];
                    tape->evalInterval4(xs, ys, zs, out, lanes);
                    for (int k = 0; k < 4; ++k) {
                        CHECK(out[k].lo == f.lo);
                        CHECK(out[k].hi == f.hi);
                    }
                }
                forSamples(box, rng, [&](const Vec3& p) {
                    const double v = tape->eval(p);
                    INFO("box " << boxes << " p=(" << p.x << "," << p.y << "," << p.z
                                << ") v=" << v);
                    CHECK(f.contains(v));
                    CHECK(fc.contains(v));
                    CHECK(simpler->eval(p) == v);  // the simplified tape's contract on its box
                });
            }
            ++boxes;
        }
    }
    CHECK(boxes == 750);
}

TEST_CASE("field/interval evaluation along a ray encloses sampled values and slopes") {
    const auto tapes = {sphereTape(sphereField()), mixedTape(sphereField(), boxField())};
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const auto& tape : tapes) {
        for (int i = 0; i < 400; ++i) {
            const Ray ray{gaussianUnit(rng) * 3.0, gaussianUnit(rng) * (0.2 + 2.0 * unit(rng))};
            const double t0 = 4.0 * unit(rng), width = std::pow(10.0, -6.0 * unit(rng)) * 2.0;
            const Interval t(t0, t0 + width);
            Interval F, D, Fr, Dr;
            tape->evalIntervalAlongRay(ray, t, F, D);
            tape->evalIntervalAlongRayReference(ray, t, Fr, Dr);
            CHECK((F.lo == Fr.lo && F.hi == Fr.hi && D.lo == Dr.lo && D.hi == Dr.hi));
            // Each partial is bounded by L = 1: |df/dt| ≤ Σ |∂f/∂operand|·|d operand/dt|, which
            // the enclosure takes whole (the field gives no tighter gradient bound).
            for (int s = 0; s <= 40; ++s) {
                const double ts = s == 40 ? t.hi : t.lo + width * unit(rng);
                double dfdt;
                const double v = tape->evalAlongRay(ray, ts, dfdt);
                INFO("ray " << i << " t=" << ts);
                CHECK(F.contains(v));
                CHECK(D.contains(dfdt));
            }
        }
    }
    // The sphere alone along a unit ray: the slope bound is exactly Σ|d_i|·[−1, 1].
    const Ray ray{Vec3(3.0, 0.0, 0.0), glm::normalize(Vec3(-1.0, 0.5, 0.25))};
    Interval F, D;
    sphereTape(sphereField())->evalIntervalAlongRay(ray, Interval(0.0, 1.0), F, D);
    const double bound = std::fabs(ray.dir.x) + std::fabs(ray.dir.y) + std::fabs(ray.dir.z);
    CHECK(D.hi >= bound);
    CHECK(D.hi <= bound * (1.0 + 1e-15));
    CHECK(D.lo == -D.hi);
}

TEST_CASE("field/no ray plan for a tape with a field; the rebuilt graph keeps the fields") {
    const auto tape = mixedTape(sphereField(), boxField());
    CHECK_FALSE(TapeRayPlan::accepts(*tape));
    CHECK_THROWS_AS(TapeRayPlan(*tape), std::invalid_argument);
    ExprGraph g;
    CHECK(TapeRayPlan::accepts(*Tape::compile(g, g.binary(Op::Add, g.x(), g.y()))));

    // An implicit rebuilds its graph from the tape (Primitive::implicitExpr): the tree tape
    // calls the same two fields and computes the implicit's value.
    const NodePtr node = makeImplicit(tape, {Vec3(-1.5), Vec3(1.5)});
    const auto tree = treeTape(*node);
    REQUIRE(tree->fields().size() == 2);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> coord(-2.0, 2.0);
    for (int i = 0; i < 500; ++i) {
        const Vec3 p(coord(rng), coord(rng), coord(rng));
        CHECK(tree->eval(p) == node->value(p));
    }
}

TEST_CASE("field/tracing hits the sphere at its analytic depth") {
    const auto a = sphereField();
    const Bounds3 box{kCentre - Vec3(1.2), kCentre + Vec3(1.2)};
    const NodePtr implicit = makeImplicit(sphereTape(a), box);
    const FieldPrimitive primitive(a);
    std::mt19937_64 rng(6);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    TraceContext ctx;
    int hits = 0;
    for (double tolerance : {1e-9, 1e-12}) {
        ctx.relTolerance = tolerance;
        for (int i = 0; i < 300; ++i) {
            Ray ray{kCentre + gaussianUnit(rng) * (2.0 + 6.0 * unit(rng)), Vec3(0.0)};
            ray.dir = (kCentre + gaussianUnit(rng) * 1.1 * unit(rng) - ray.origin) *
                      (0.1 + 3.0 * unit(rng));
            long double t0 = 0.0L, t1 = 0.0L;
            const bool crosses = sphereHits(ray, t0, t1);
            INFO("tolerance " << tolerance << " ray " << i);
            // The implicit by its own root isolation, and the primitive by the Interval
            // comparison method, whose stand-in evaluates the field's tape along the ray.
            SpanList s, p;
            ctx.method = TraceMethod::Closed;
            implicit->spans(ray, 0.0, kInf, ctx, s);
            Boundary first;
            bool entering = false;
            const bool found = implicit->firstSurface(ray, 0.0, kInf, ctx, first, entering);
            ctx.method = TraceMethod::Interval;
            primitive.spans(ray, 0.0, kInf, ctx, p);
            if (!crosses) continue;
            ++hits;
            for (const SpanList* list : {&s, &p}) {
                REQUIRE(list->size() == 1);
                CHECK(std::fabs((*list)[0].in.t - t0) <= tolerance * t0);
                CHECK(std::fabs((*list)[0].out.t - t1) <= tolerance * t1);
            }
            REQUIRE(found);
            CHECK(entering);
            CHECK(std::fabs(first.t - t0) <= tolerance * t0);
            // The normal is the field's gradient: along the radius.
            const Vec3 n = s[0].in.normal, r = ray.at(s[0].in.t) - kCentre;
            CHECK(glm::length(glm::cross(n / glm::length(n), r / glm::length(r))) < 1e-9);
        }
    }
    CHECK(hits > 200);
}
