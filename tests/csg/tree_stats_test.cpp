// Counts over shared subtrees: one visit per distinct node, 64-bit instance counts.
#include "csg/tree/tree_stats.h"
#include "csg/tree/solids.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace kerf;

namespace {

/// A sphere used twice at each of `levels` levels: 2^levels instances of one primitive.
NodePtr doubled(int levels) {
    NodePtr s = makeSphere(Vec3(0.0), 0.4);
    for (int i = 0; i < levels; ++i)
        s = makeBoolean(BoolOp::Union,
                        {s, makeTransform(s, Affine::translate(Vec3(std::ldexp(1.0, i), 0, 0)))});
    return s;
}

}  // namespace

TEST_CASE("treeStats walks a shared subtree once and counts its uses in 64 bits") {
    // 2^60 leaves written out: a walk per use would never finish, an int would overflow.
    const NodePtr root = doubled(60);
    const TreeStats s = treeStats(*root);
    CHECK(s.primitives == 1);
    CHECK(s.nodes == 1 + 2 * 60);  // the sphere, then a transform and a union per level
    CHECK(s.instances == (int64_t(1) << 60));
    CHECK_FALSE(s.instancesSaturated);
    CHECK(s.depth == 1 + 2 * 60);
    CHECK(root->primitiveCount() == (int64_t(1) << 60));
    CHECK(root->depth() == 1 + 2 * 60);
}

TEST_CASE("treeStats saturates the instance count instead of wrapping") {
    const TreeStats s = treeStats(*doubled(70));
    CHECK(s.instancesSaturated);
    CHECK(s.instances == std::numeric_limits<int64_t>::max());
    CHECK(s.primitives == 1);
}

TEST_CASE("treeStats over several roots: shared parts once in the distinct counts") {
    const NodePtr a = makeSphere(Vec3(0.0), 1.0);
    const NodePtr b = makeBox(Vec3(0.0), Vec3(1.0));
    const NodePtr u = makeBoolean(BoolOp::Union, {a, b});
    const NodePtr d = makeBoolean(BoolOp::Difference, {u, a});
    const TreeStats s = treeStats(std::vector<NodePtr>{u, d, a});
    CHECK(s.primitives == 2);
    CHECK(s.nodes == 4);
    CHECK(s.instances == 2 + 3 + 1);
    CHECK(s.depth == 3);
}
