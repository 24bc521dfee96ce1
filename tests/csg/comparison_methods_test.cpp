// csg/comparison_methods: every primitive's implicit form (Primitive::implicitExpr) is its
// value(), a whole tree's tape (csg/tape/tree_tape.h) is the tree's value(), and the generic
// interval method handles unbounded ranges (half-spaces) as the closed form does.
#include "csg/primitives/comparison_methods.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "csg/tape/expr.h"
#include "csg/tape/tree_tape.h"
#include "csg/tree/solids.h"
#include "util/oracles.h"

using namespace kerf;
using namespace kerf::test;

namespace {

std::shared_ptr<const Tape> gyroidTape() {
    ExprGraph g;
    return Tape::compile(g, g.binary(Op::Sub, gyroidExpr(g), g.constant(0.2)));
}

std::vector<NodePtr> everyPrimitive() {
    return {makeSphere(Vec3(0.3, -0.2, 0.1), 1.3),
            makeBox(Vec3(-1.0, -0.5, -0.8), Vec3(1.2, 0.7, 0.9)),
            makeCylinder(Vec3(-0.3, -1.0, 0.2), Vec3(0.5, 1.1, -0.1), 0.7),
            makeCylinder(Vec3(0.0, -1.0, 0.0), Vec3(0.0, 1.0, 0.0), 1.0),
            makeCone(Vec3(0.1, -1.0, 0.0), Vec3(-0.2, 1.0, 0.3), 0.9, 0.2),
            makeTorus(1.0, 0.3),
            makeHalfSpace(Vec3(0.3, 1.0, -0.5), 0.4),
            makeImplicit(gyroidTape(), {Vec3(-1.0), Vec3(1.0)})};
}

}  // namespace

TEST_CASE("Primitive::implicitExpr is value() (with the bound's term for an implicit)") {
    Random rng(11);
    for (const NodePtr& node : everyPrimitive()) {
        const auto& p = static_cast<const Primitive&>(*node);
        const Tape& f = implicitTape(p);
        const std::shared_ptr<const Tape> whole = treeTape(p);
        INFO(nodeKindName(p.kind()));
        for (int i = 0; i < 2000; ++i) {
            const Vec3 q(rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2));
            const double v = p.value(q);
            // The same operations in the same order: equal up to a few roundings.
            CHECK(whole->eval(q) == Approx(v).margin(1e-14).epsilon(1e-14));
            if (p.kind() != NodeKind::Implicit)
                CHECK(f.eval(q) == Approx(v).margin(1e-14).epsilon(1e-14));
        }
    }
}

TEST_CASE("treeTape is the tree's value() through transforms and every Boolean") {
    const std::vector<NodePtr> prims = everyPrimitive();
    const Affine m = Affine::translate(Vec3(0.2, -0.1, 0.3))
                         .after(Affine::rotateDegrees(Vec3(20, -35, 50)))
                         .after(Affine::scale(Vec3(1.3, 0.7, 1.1)));
    const NodePtr tree = makeBoolean(
        BoolOp::Xor,
        {makeMaterial(
             makeTransform(makeBoolean(BoolOp::Difference, {prims[0], prims[2], prims[5]}), m), 1),
         makeBoolean(BoolOp::Intersection, {prims[1], prims[6], prims[7]}),
         makeBoolean(BoolOp::Union, {prims[3], prims[4]})});
    const std::shared_ptr<const Tape> whole = treeTape(*tree);
    Random rng(12);
    int inside = 0;
    for (int i = 0; i < 5000; ++i) {
        const Vec3 q(rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2));
        const double v = tree->value(q);
        inside += v <= 0.0;
        CHECK(whole->eval(q) == Approx(v).margin(1e-14).epsilon(1e-14));
    }
    CHECK(inside > 500);
    CHECK(inside < 4500);
}

TEST_CASE("TraceMethod::Interval of a half-space over an unbounded range") {
    // The generic method works on a finite window: infinite ends come back as clips at ±inf.
    const NodePtr h = makeHalfSpace(Vec3(0.3, 1.0, -0.5), 0.4);
    Random rng(13);
    for (int i = 0; i < 500; ++i) {
        const Ray ray{Vec3(rng.uniform(-50, 50), rng.uniform(-50, 50), rng.uniform(-50, 50)),
                      rng.unitVector() * rng.logUniform(1e-3, 1e3)};
        TraceContext closed, interval;
        interval.method = TraceMethod::Interval;
        SpanList a, b;
        h->spans(ray, -kInf, kInf, closed, a);
        h->spans(ray, -kInf, kInf, interval, b);
        INFO("ray " << i);
        REQUIRE(a.size() == 1);
        REQUIRE(b.size() == 1);
        const Span &x = a[0], &y = b[0];
        CHECK(x.in.isSurface() == y.in.isSurface());
        CHECK(x.out.isSurface() == y.out.isSurface());
        const Boundary& cx = x.in.isSurface() ? x.in : x.out;
        const Boundary& cy = y.in.isSurface() ? y.in : y.out;
        CHECK(std::fabs(cy.t - cx.t) <= 1e-9 * std::fabs(cx.t) + 1e-12);
        CHECK((x.in.isSurface() ? y.out.t : y.in.t) == (x.in.isSurface() ? kInf : -kInf));
    }
}
