// Issue 24 §4: a solid repeated in one place is one operand (A ∪ A = A ∩ A = A, A − B − B =
// A − B), so doubling a shared solid in place costs nothing per ray.
#include "csg/tree/repeated_instances.h"
#include "csg/tree/solids.h"
#include "csg/tree/tree_stats.h"

#include <catch2/catch.hpp>

using namespace kerf;

namespace {

NodePtr turned(const NodePtr& s, double x) {
    return makeTransform(s, Affine::translate(Vec3(x, 0, 0)));
}

}  // namespace

TEST_CASE("a solid doubled in place 40 times is the solid itself") {
    const NodePtr sphere = makeSphere(Vec3(0.0), 1.0);
    NodePtr s = sphere;
    for (int i = 0; i < 40; ++i) s = makeBoolean(BoolOp::Union, {s, s});
    CHECK(s == sphere);
    CHECK(s->primitiveCount() == 1);
    NodePtr t = sphere;
    for (int i = 0; i < 40; ++i) t = makeBoolean(BoolOp::Intersection, {t, t});
    CHECK(t == sphere);
}

TEST_CASE("repeated instances: equal transforms and materials over one node are one") {
    const NodePtr a = makeSphere(Vec3(0.0), 1.0);
    const NodePtr twin = makeSphere(Vec3(0.0), 1.0);  // equal-looking, but another node
    CHECK(sameInstance(*turned(a, 1), *turned(a, 1)));
    CHECK(sameInstance(*makeMaterial(turned(a, 1), 3), *makeMaterial(turned(a, 1), 3)));
    CHECK_FALSE(sameInstance(*turned(a, 1), *turned(a, 2)));
    CHECK_FALSE(sameInstance(*turned(a, 1), *turned(twin, 1)));
    CHECK_FALSE(sameInstance(*makeMaterial(a, 1), *makeMaterial(a, 2)));
    CHECK_FALSE(sameInstance(*makeMaterial(turned(a, 1), 1), *turned(makeMaterial(a, 1), 1)));
    CHECK_FALSE(sameInstance(*turned(a, 0), *a));  // an identity transform is still a wrapper

    const std::vector<NodePtr> u = withoutRepeatedInstances(
        BoolOp::Union, {turned(a, 1), a, turned(a, 1), twin, turned(a, 2), a});
    REQUIRE(u.size() == 4);
    CHECK(sameInstance(*u[0], *turned(a, 1)));
    CHECK(u[1] == a);
    CHECK(u[2] == twin);
    CHECK(sameInstance(*u[3], *turned(a, 2)));
}

TEST_CASE("repeated instances: a difference drops repeated cutters, xor keeps everything") {
    const NodePtr a = makeSphere(Vec3(0.0), 1.0);
    const NodePtr b = makeBox(Vec3(0.0), Vec3(1.0));
    CHECK(withoutRepeatedInstances(BoolOp::Difference, {a, b, b, turned(b, 0), turned(b, 0)})
              .size() == 3);
    // A − A stays as written (empty), the first operand is never a repeat of a cutter.
    CHECK(withoutRepeatedInstances(BoolOp::Difference, {a, a}).size() == 2);
    CHECK(withoutRepeatedInstances(BoolOp::Difference, {a, b, a, a}).size() == 3);
    CHECK(withoutRepeatedInstances(BoolOp::Xor, {a, a, b}).size() == 3);
}

TEST_CASE("repeated instances: a wide union of repeats hashes, each distinct one kept once") {
    const NodePtr a = makeSphere(Vec3(0.0), 0.4);
    std::vector<NodePtr> children;
    for (int k = 0; k < 200000; ++k) children.push_back(turned(a, k % 1000));
    const NodePtr u = makeBoolean(BoolOp::Union, children);
    CHECK(u->children().size() == 1000);
    CHECK(treeStats(*u).instances == 1000);
}
