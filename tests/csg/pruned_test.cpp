// pruned(node, box) on random trees of every node kind: inside random boxes the pruned
// result has the original's sign at random points and its spans on random rays, and it is
// never bigger than the original.
#include <catch2/catch.hpp>

#include "csg/tape/expr.h"
#include "csg/tree/prune.h"
#include "csg/tree/solids.h"
#include "util/oracles.h"
#include "util/prune_checks.h"

using namespace kerf;
using namespace kerf::test;

namespace {

Vec3 randomPoint(Random& rng, double r) {
    return {rng.uniform(-r, r), rng.uniform(-r, r), rng.uniform(-r, r)};
}

/// A random expression over x, y, z with min and max at its top levels: spheres, slabs and a
/// gyroid-like term, so interval evaluation has branches to decide.
ExprId randomExpr(ExprGraph& g, Random& rng, int depth) {
    if (depth == 0) {
        const Vec3 c = randomPoint(rng, 1.0);
        switch (static_cast<int>(rng.uniform(0, 3))) {
            case 0: {
                const ExprId dx = g.binary(Op::Sub, g.x(), g.constant(c.x));
                const ExprId dy = g.binary(Op::Sub, g.y(), g.constant(c.y));
                const ExprId dz = g.binary(Op::Sub, g.z(), g.constant(c.z));
                const ExprId r2 = g.binary(
                    Op::Add, g.binary(Op::Add, g.unary(Op::Square, dx), g.unary(Op::Square, dy)),
                    g.unary(Op::Square, dz));
                return g.binary(Op::Sub, g.unary(Op::Sqrt, r2), g.constant(rng.uniform(0.3, 1.0)));
            }
            case 1: {
                const Vec3 n = rng.unitVector();
                const ExprId dot =
                    g.binary(Op::Add,
                             g.binary(Op::Add, g.binary(Op::Mul, g.constant(n.x), g.x()),
                                      g.binary(Op::Mul, g.constant(n.y), g.y())),
                             g.binary(Op::Mul, g.constant(n.z), g.z()));
                return g.binary(Op::Sub, dot, g.constant(rng.uniform(-0.5, 0.5)));
            }
            default: {
                const ExprId k = g.constant(rng.uniform(2.0, 5.0));
                const ExprId kx = g.binary(Op::Mul, k, g.x()), ky = g.binary(Op::Mul, k, g.y());
                const ExprId kz = g.binary(Op::Mul, k, g.z());
                const auto term = [&](ExprId a, ExprId b) {
                    return g.binary(Op::Mul, g.unary(Op::Sin, a), g.unary(Op::Cos, b));
                };
                const ExprId sum =
                    g.binary(Op::Add, g.binary(Op::Add, term(kx, ky), term(ky, kz)), term(kz, kx));
                return g.binary(Op::Sub, g.unary(Op::Abs, sum), g.constant(0.4));
            }
        }
    }
    const ExprId a = randomExpr(g, rng, depth - 1), b = randomExpr(g, rng, depth - 1);
    switch (static_cast<int>(rng.uniform(0, 3))) {
        case 0: return g.binary(Op::Min, a, b);
        case 1: return g.binary(Op::Max, a, b);
        default: return g.binary(Op::Max, a, g.unary(Op::Neg, b));
    }
}

NodePtr randomLeaf(Random& rng) {
    const Vec3 c = randomPoint(rng, 1.0);
    switch (static_cast<int>(rng.uniform(0, 7))) {
        case 0: return makeSphere(c, rng.uniform(0.3, 1.2));
        case 1: return makeBox(c - Vec3(rng.uniform(0.2, 1.0)), c + Vec3(rng.uniform(0.2, 1.0)));
        case 2: return makeCylinder(c, randomPoint(rng, 1.0), rng.uniform(0.2, 0.8));
        case 3:
            return makeCone(c, randomPoint(rng, 1.0), rng.uniform(0.2, 0.8), rng.uniform(0.0, 0.5));
        case 4: return makeTorus(rng.uniform(0.6, 1.2), rng.uniform(0.1, 0.5));
        case 5: return makeHalfSpace(rng.unitVector(), rng.uniform(-0.5, 0.5));
        default: {
            ExprGraph g;
            const ExprId root = randomExpr(g, rng, static_cast<int>(rng.uniform(1, 4)));
            return makeImplicit(Tape::compile(g, root), {Vec3(-1.5), Vec3(rng.uniform(0.8, 1.5))});
        }
    }
}

NodePtr randomTree(Random& rng, int depth) {
    if (depth == 0 || rng.uniform(0, 1) < 0.25) return randomLeaf(rng);
    const double pick = rng.uniform(0, 1);
    if (pick < 0.15) {
        const Affine m = Affine::translate(randomPoint(rng, 0.5))
                             .after(Affine::rotateDegrees(randomPoint(rng, 180.0)))
                             .after(Affine::scale(Vec3(rng.uniform(0.6, 1.4), rng.uniform(0.6, 1.4),
                                                       rng.uniform(0.6, 1.4))));
        return makeTransform(randomTree(rng, depth - 1), m);
    }
    if (pick < 0.25) return makeMaterial(randomTree(rng, depth - 1), int32_t(rng.uniform(0, 4)));
    const BoolOp ops[] = {BoolOp::Union, BoolOp::Intersection, BoolOp::Difference, BoolOp::Xor};
    const BoolOp op = ops[static_cast<int>(rng.uniform(0, 4))];
    std::vector<NodePtr> kids;
    const int n = static_cast<int>(rng.uniform(2, 5));
    for (int i = 0; i < n; ++i) kids.push_back(randomTree(rng, depth - 1));
    return makeBoolean(op, std::move(kids));
}

int countNodes(const Node& n) {
    int c = 1;
    for (const NodePtr& k : n.children()) c += countNodes(*k);
    return c;
}

}  // namespace

TEST_CASE("pruned: random trees agree with the original inside random boxes") {
    Random rng(20261127);
    int states[3] = {0, 0, 0};
    int dropped = 0, simplifiedTapes = 0, failures = 0;
    for (int tree = 0; tree < 150; ++tree) {
        const NodePtr root = randomTree(rng, 3);
        for (int b = 0; b < 20; ++b) {
            const Vec3 c = randomPoint(rng, 1.6);
            const Vec3 half(rng.logUniform(0.01, 1.0), rng.logUniform(0.01, 1.0),
                            rng.logUniform(0.01, 1.0));
            const Bounds3 box{c - half, c + half};
            const Pruned p = pruned(root, box);
            ++states[static_cast<int>(p.state)];
            if (p.state == PruneState::Partial) {
                CHECK(countNodes(*p.node) <= countNodes(*root));
                CHECK(tapeInstructions(*p.node) <= tapeInstructions(*root));
                dropped += p.node->primitiveCount() < root->primitiveCount();
                simplifiedTapes += tapeInstructions(*p.node) < tapeInstructions(*root);
            }
            failures += checkPrunedAgrees(root, p, box, rng, 40, 6);
        }
    }
    INFO("empty " << states[0] << " full " << states[1] << " partial " << states[2]);
    CHECK(failures == 0);
    // Every outcome is exercised, and pruning does drop subtrees and shorten tapes.
    CHECK(states[0] > 100);
    CHECK(states[1] > 50);
    CHECK(states[2] > 500);
    CHECK(dropped > 100);
    CHECK(simplifiedTapes > 20);
}

TEST_CASE("pruned: the Boolean rules") {
    const NodePtr a = makeSphere(Vec3(-2.0, 0.0, 0.0), 1.0);
    const NodePtr b = makeSphere(Vec3(2.0, 0.0, 0.0), 1.0);
    const NodePtr big = makeSphere(Vec3(0.0), 10.0);
    const Bounds3 nearA{Vec3(-1.4, -0.3, -0.3), Vec3(-0.6, 0.3, 0.3)};  // straddles a's surface
    const Bounds3 inA{Vec3(-2.1, -0.1, -0.1), Vec3(-1.9, 0.1, 0.1)};

    SECTION("a union keeps the children that can matter; a full child fills it") {
        const NodePtr u = makeBoolean(BoolOp::Union, {a, b});
        const Pruned p = pruned(u, nearA);
        REQUIRE(p.state == PruneState::Partial);
        CHECK(p.node == a);  // b's bounds miss the box; a union of one is that child
        CHECK(pruned(u, inA).state == PruneState::Full);
    }
    SECTION("an intersection drops full children; an empty child empties it") {
        const NodePtr i = makeBoolean(BoolOp::Intersection, {big, a});
        const Pruned p = pruned(i, nearA);
        REQUIRE(p.state == PruneState::Partial);
        CHECK(p.node == a);
        CHECK(pruned(makeBoolean(BoolOp::Intersection, {a, b}), nearA).state == PruneState::Empty);
    }
    SECTION("a difference drops missed cutters; a full cutter empties it") {
        const NodePtr d = makeBoolean(BoolOp::Difference, {big, a, b});
        const Pruned p = pruned(d, nearA);
        REQUIRE(p.state == PruneState::Partial);
        REQUIRE(p.node->kind() == NodeKind::Difference);
        REQUIRE(p.node->children().size() == 2);
        CHECK(p.node->children()[0] == big);  // full body: the original stands in
        CHECK(p.node->children()[1] == a);
        CHECK(pruned(d, inA).state == PruneState::Empty);
    }
    SECTION("xor: full children flip the parity") {
        CHECK(pruned(makeBoolean(BoolOp::Xor, {big, a}), inA).state == PruneState::Empty);
        CHECK(pruned(makeBoolean(BoolOp::Xor, {big, b}), inA).state == PruneState::Full);
    }
    SECTION("a transform maps the box into its child's space") {
        const NodePtr t = makeTransform(makeBoolean(BoolOp::Union, {a, b}),
                                        Affine::translate(Vec3(4.0, 0.0, 0.0)));
        const Pruned p = pruned(t, {Vec3(2.6, -0.3, -0.3), Vec3(3.4, 0.3, 0.3)});
        REQUIRE(p.state == PruneState::Partial);
        REQUIRE(p.node->kind() == NodeKind::Transform);
        CHECK(p.node->children()[0] == a);
        CHECK(std::get<TransformParams>(p.node->params()).worldFromLocal.offset.x == 4.0);
    }
}

TEST_CASE("pruned: an implicit's tape keeps the branches interval evaluation cannot decide") {
    // min(sphere at −2, sphere at +2) − 0 … over a box near the left sphere only the left
    // branch remains, and the tape loses the right sphere's instructions.
    ExprGraph g;
    const auto sphere = [&](double cx) {
        const ExprId dx = g.binary(Op::Sub, g.x(), g.constant(cx));
        const ExprId r2 = g.binary(
            Op::Add, g.binary(Op::Add, g.unary(Op::Square, dx), g.unary(Op::Square, g.y())),
            g.unary(Op::Square, g.z()));
        return g.binary(Op::Sub, g.unary(Op::Sqrt, r2), g.constant(1.0));
    };
    const std::shared_ptr<const Tape> tape =
        Tape::compile(g, g.binary(Op::Min, sphere(-2.0), sphere(2.0)));
    const NodePtr node = makeImplicit(tape, {Vec3(-4.0), Vec3(4.0)});
    const Bounds3 box{Vec3(-1.4, -0.3, -0.3), Vec3(-0.6, 0.3, 0.3)};
    const Pruned p = pruned(node, box);
    REQUIRE(p.state == PruneState::Partial);
    REQUIRE(p.node->kind() == NodeKind::Implicit);
    const ImplicitParams ip = std::get<ImplicitParams>(p.node->params());
    // Of 21 instructions, x, y, z and one sphere (const, sub, square ×3, add ×2, sqrt, const,
    // sub) remain.
    CHECK(tape->size() == 21);
    CHECK(ip.tape->size() == 13);
    CHECK(ip.bound.lo == Vec3(-4.0));
    Random rng(5);
    for (int i = 0; i < 200; ++i) {
        const Vec3 q = pointIn(box, rng);
        CHECK(ip.tape->eval(q) == tape->eval(q));  // the same doubles inside the box
    }
    // Over a box that straddles both spheres' reach nothing can be dropped.
    CHECK(pruned(node, {Vec3(-1.5), Vec3(1.5)}).node == node);
    CHECK(checkPrunedAgrees(node, p, box, rng, 200, 50) == 0);
}

TEST_CASE("Node: the open tree gives kinds, children, parameters and rebuilds") {
    const NodePtr s = makeSphere(Vec3(1.0, 2.0, 3.0), 0.5);
    const NodePtr c = makeCone(Vec3(0.0), Vec3(0.0, 1.0, 0.0), 0.5, 0.25);
    const NodePtr tree = makeMaterial(
        makeTransform(makeBoolean(BoolOp::Difference, {s, c}), Affine::scale(Vec3(2.0))), 3);
    CHECK(describeTree(*tree) == "material(transform(difference(sphere, cone)))");
    CHECK(std::get<MaterialParams>(tree->params()).material == 3);
    const SphereParams sp = std::get<SphereParams>(s->params());
    CHECK(sp.center == Vec3(1.0, 2.0, 3.0));
    CHECK(sp.radius == 0.5);
    const ConeParams cp = std::get<ConeParams>(c->params());
    CHECK(cp.b == Vec3(0.0, 1.0, 0.0));
    CHECK(cp.r2 == 0.25);
    CHECK(s->withChildren({}) == nullptr);

    // Rebuilding the transform over the same child gives the same values bit for bit.
    const NodePtr t = tree->children()[0];
    const NodePtr again = t->withChildren({t->children()[0]});
    REQUIRE(again != t);
    Random rng(3);
    for (int i = 0; i < 100; ++i) {
        const Vec3 q = randomPoint(rng, 3.0);
        CHECK(again->value(q) == t->value(q));
    }
    const NodePtr swapped = t->children()[0]->withChildren({c, s});
    CHECK(describeTree(*swapped) == "difference(cone, sphere)");
    CHECK(swapped->kind() == NodeKind::Difference);
    CHECK(booleanOp(swapped->kind()) == BoolOp::Difference);
}

TEST_CASE("prunedMany equals pruned box by box") {
    // The octree classifies a cell's 8 children together; each result must be pruned()'s:
    // the same state and, where partial, the same node (shared where nothing was dropped).
    ExprGraph g;
    const ExprId k = g.constant(6.283185307179586);
    auto sc = [&](ExprId a, ExprId b) {
        return g.binary(Op::Mul, g.unary(Op::Sin, g.binary(Op::Mul, k, a)),
                        g.unary(Op::Cos, g.binary(Op::Mul, k, b)));
    };
    const ExprId f = g.binary(Op::Add, g.binary(Op::Add, sc(g.x(), g.y()), sc(g.y(), g.z())),
                              g.binary(Op::Add, sc(g.z(), g.x()), g.constant(0.3)));
    const NodePtr gyroid = makeImplicit(Tape::compile(g, f), {Vec3(-1.0), Vec3(1.2)});
    const NodePtr withMin = makeImplicit(
        Tape::compile(g, g.binary(Op::Min, f, g.binary(Op::Sub, g.x(), g.constant(0.5)))),
        {Vec3(-1.0), Vec3(1.0)});
    const Affine map = Affine::translate(Vec3(0.3, -0.2, 0.1))
                           .after(Affine::rotateDegrees(Vec3(10.0, 25.0, -5.0)))
                           .after(Affine::scale(Vec3(0.9)));
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.6, 1.6), w(0.001, 0.6);
    for (const NodePtr& node :
         {gyroid, makeMaterial(makeTransform(gyroid, map), 2), withMin,
          makeTransform(makeBoolean(BoolOp::Union, {gyroid, withMin}), map)}) {
        int states[3] = {0, 0, 0};
        for (int trial = 0; trial < 400; ++trial) {
            Bounds3 boxes[kPrunedManyMax];
            const int count = 1 + trial % kPrunedManyMax;
            for (int b = 0; b < count; ++b) {
                const Vec3 lo(u(rng), u(rng), u(rng));
                boxes[b] = {lo, lo + Vec3(w(rng), w(rng), w(rng))};
            }
            Pruned many[kPrunedManyMax];
            prunedMany(node, boxes, count, many);
            for (int b = 0; b < count; ++b) {
                const Pruned one = pruned(node, boxes[b]);
                INFO("trial " << trial << " box " << b);
                REQUIRE(many[b].state == one.state);
                ++states[int(one.state)];
                if (one.state == PruneState::Partial && one.node == node)
                    CHECK(many[b].node == node);
                if (one.state == PruneState::Partial && one.node != node) {
                    // Rebuilt nodes are new objects: compare what they compute.
                    for (const Vec3& p : {boxes[b].lo, boxes[b].center(), boxes[b].hi})
                        CHECK(many[b].node->value(p) == one.node->value(p));
                }
            }
        }
        INFO("empty " << states[0] << ", full " << states[1] << ", partial " << states[2]);
        CHECK(states[0] > 0);
        CHECK(states[2] > 0);
    }
}
