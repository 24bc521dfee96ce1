// valueExtended is the long-double twin of value: the same function, more precise.
#include "csg/tape/expr.h"
#include "csg/tree/solids.h"

#include <catch2/catch.hpp>

#include <random>

using namespace kerf;

TEST_CASE("Node::valueExtended agrees with value for every kind of node", "[value]") {
    ExprGraph g;
    const ExprId f =
        g.binary(Op::Add, g.binary(Op::Mul, g.unary(Op::Sin, g.x()), g.unary(Op::Cos, g.y())),
                 g.unary(Op::Sin, g.z()));
    const std::vector<NodePtr> nodes = {
        makeSphere({0.1, -0.2, 0.3}, 1.1),
        makeBox({-1, -0.5, -2}, {1, 0.5, 0.25}),
        makeCylinder({0, -1, 0}, {0.3, 1, 0.2}, 0.6),
        makeCone({0, -1, 0.1}, {0.2, 1, 0}, 0.7, 0.1),
        makeHalfSpace({1, 2, -0.5}, 0.3),
        makeTorus(1.0, 0.3),
        makeImplicit(Tape::compile(g, f), {{-1, -1, -1}, {1, 1, 1}}),
        makeBoolean(BoolOp::Difference, {makeBox({-1, -1, -1}, {1, 1, 1}), makeSphere({}, 1.2)}),
        makeMaterial(
            makeTransform(makeTorus(1.0, 0.25),
                          Affine::rotateDegrees({10, 20, 30}).after(Affine::scale({1, 2, 0.5}))),
            2),
    };
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> u(-2, 2);
    for (size_t k = 0; k < nodes.size(); ++k) {
        for (int i = 0; i < 2000; ++i) {
            const Vec3 p(u(rng), u(rng), u(rng));
            const double v = nodes[k]->value(p);
            const long double e = nodes[k]->valueExtended(LVec3(p));
            INFO("node " << k << " at " << p.x << ", " << p.y << ", " << p.z);
            REQUIRE(std::fabs((long double)v - e) <= 1e-12L * (1 + std::fabs(e)));
        }
    }
}
