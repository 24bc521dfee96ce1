// The shared BVH builder (csg/bvh/bvh_builder.h) on random boxes, under the object, median,
// triangle and profile rules: every node's box is the hull of its items and holds its
// children's boxes, leaves tile the item order, every item appears once, leaves respect the
// leaf size, the SAH tree costs no more than the median tree, and the same input (serial or
// in parallel tasks) gives the same nodes.
#include <catch2/catch.hpp>

#include "csg/bvh/bvh_builder.h"

#include <random>
#include <thread>
#include <vector>

using namespace kerf;

namespace {

std::vector<BvhBuildItem> randomItems(size_t n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> pos(-100.0, 100.0), size(0.0, 5.0);
    std::vector<BvhBuildItem> items(n);
    for (size_t i = 0; i < n; ++i) {
        const Vec3 lo(pos(rng), pos(rng), pos(rng));
        const Bounds3 box{lo, lo + Vec3(size(rng), size(rng), size(rng))};
        items[i] = {box, box.center(), uint32_t(i)};
    }
    return items;
}

bool holds(const Bounds3& outer, const Bounds3& inner) {
    for (int a = 0; a < 3; ++a)
        if (inner.lo[a] < outer.lo[a] || inner.hi[a] > outer.hi[a]) return false;
    return true;
}

bool sameBox(const Bounds3& a, const Bounds3& b) { return a.lo == b.lo && a.hi == b.hi; }

/// Walks the subtree at `node`, checking boxes against the items (by id) and the leaf size;
/// returns the end of the subtree in the node array and appends the leaves' ranges to covered.
size_t checkSubtree(const BinaryBvh& t, size_t node, const std::vector<BvhBuildItem>& items,
                    uint32_t maxLeaf, std::vector<uint32_t>& covered) {
    REQUIRE(node < t.nodes.size());
    const BinaryBvhNode& n = t.nodes[node];
    if (n.count > 0) {
        CHECK(n.count <= maxLeaf);
        REQUIRE(n.first + n.count <= t.order.size());
        Bounds3 hull;
        for (uint32_t k = n.first; k < n.first + n.count; ++k) {
            hull.extend(items[t.order[k]].box);
            covered.push_back(k);
        }
        CHECK(sameBox(n.box, hull));
        return node + 1;
    }
    const size_t second = checkSubtree(t, node + 1, items, maxLeaf, covered);
    CHECK(n.first == second);  // the second child follows the first child's subtree
    CHECK(holds(n.box, t.nodes[node + 1].box));
    CHECK(holds(n.box, t.nodes[n.first].box));
    CHECK(sameBox(n.box, Bounds3::hull(t.nodes[node + 1].box, t.nodes[n.first].box)));
    return checkSubtree(t, n.first, items, maxLeaf, covered);
}

void checkTree(const BinaryBvh& t, const std::vector<BvhBuildItem>& items, uint32_t maxLeaf) {
    REQUIRE(t.order.size() == items.size());
    std::vector<int> seen(items.size(), 0);
    for (uint32_t id : t.order) {
        REQUIRE(id < items.size());
        ++seen[id];
    }
    for (int s : seen) CHECK(s == 1);
    std::vector<uint32_t> covered;
    CHECK(checkSubtree(t, 0, items, maxLeaf, covered) == t.nodes.size());
    // Leaves in depth-first order tile the item order: positions 0, 1, 2, ... once each.
    REQUIRE(covered.size() == items.size());
    for (size_t k = 0; k < covered.size(); ++k) CHECK(covered[k] == k);
}

/// The tree's SAH cost relative to the root: inner nodes cost one test, leaves one per item.
double sahCost(const BinaryBvh& t) {
    double sum = 0.0;
    for (const BinaryBvhNode& n : t.nodes) sum += bvhHalfArea(n.box) * (n.count > 0 ? n.count : 1);
    return sum / bvhHalfArea(t.nodes[0].box);
}

BvhBuildRule objectRule() {
    BvhBuildRule r;
    r.cost = BvhBuildRule::SahCost::PerArea;
    r.itemCost = 1.5;
    r.coincidentLeaf = 0xffff;
    return r;
}

BvhBuildRule medianRule(int leaf) {
    BvhBuildRule r;
    r.split = BvhBuildRule::Split::Median;
    r.maxLeafSize = leaf;
    return r;
}

BvhBuildRule triangleRule(bool parallel) {
    BvhBuildRule r;
    r.bins = 32;
    r.maxLeafSize = 8;
    r.nodeCost = 3.0;
    r.sahDepthLimit = 28;
    if (parallel) {
        r.parallelAbove = 64;
        r.parallelInvoke = [](const std::function<void()>& a, const std::function<void()>& b) {
            std::thread other(b);
            a();
            other.join();
        };
    }
    return r;
}

bool sameTree(const BinaryBvh& a, const BinaryBvh& b) {
    if (a.order != b.order || a.nodes.size() != b.nodes.size()) return false;
    for (size_t k = 0; k < a.nodes.size(); ++k) {
        const BinaryBvhNode &x = a.nodes[k], &y = b.nodes[k];
        if (!sameBox(x.box, y.box) || x.first != y.first || x.count != y.count || x.axis != y.axis)
            return false;
    }
    return true;
}

}  // namespace

TEST_CASE("BVH builder: valid trees under every rule", "[bvh]") {
    for (size_t n : {1, 2, 3, 5, 17, 100, 1000}) {
        const auto items = randomItems(n, uint32_t(n));
        INFO("items " << n);
        checkTree(buildBinaryBvh(items, objectRule()), items, 4);
        checkTree(buildBinaryBvh(items, medianRule(2)), items, 2);
        checkTree(buildBinaryBvh(items, triangleRule(false)), items, 8);
        checkTree(buildBinaryBvh(items, triangleRule(true)), items, 8);
        BvhBuildRule profile = medianRule(4);
        profile.medianAxis = BvhBuildRule::MedianAxis::NodeBox;
        profile.medianTieById = false;
        checkTree(buildBinaryBvh(items, profile), items, 4);
    }
}

TEST_CASE("BVH builder: no items, no nodes", "[bvh]") {
    const BinaryBvh t = buildBinaryBvh({}, objectRule());
    CHECK(t.nodes.empty());
    CHECK(t.order.empty());
}

TEST_CASE("BVH builder: coincident centroids share a leaf up to coincidentLeaf", "[bvh]") {
    std::vector<BvhBuildItem> items;
    for (uint32_t i = 0; i < 40; ++i) {
        const Bounds3 box{Vec3(-1.0 - i), Vec3(1.0 + i)};  // nested boxes, one centre
        items.push_back({box, box.center(), i});
    }
    const BinaryBvh shared = buildBinaryBvh(items, objectRule());
    REQUIRE(shared.nodes.size() == 1);
    CHECK(shared.nodes[0].count == 40);
    checkTree(shared, items, 40);
    // Without the rule they are halved at the median (by id) down to the leaf size.
    BvhBuildRule r = objectRule();
    r.coincidentLeaf = 0;
    const BinaryBvh halved = buildBinaryBvh(items, r);
    checkTree(halved, items, 4);
    CHECK(halved.nodes.size() > 1);
}

TEST_CASE("BVH builder: SAH costs no more than the median split", "[bvh]") {
    for (uint32_t seed : {1u, 2u, 3u, 4u}) {
        const auto items = randomItems(2000, seed);
        BvhBuildRule sah = triangleRule(false);
        sah.maxLeafSize = 4;
        sah.nodeCost = 1.0;
        const double sahTree = sahCost(buildBinaryBvh(items, sah));
        const double medianTree = sahCost(buildBinaryBvh(items, medianRule(4)));
        INFO("seed " << seed << " SAH " << sahTree << " median " << medianTree);
        CHECK(sahTree <= medianTree);
    }
}

TEST_CASE("BVH builder: deterministic, whatever the tasks", "[bvh]") {
    const auto items = randomItems(5000, 7);
    const BinaryBvh serial = buildBinaryBvh(items, triangleRule(false));
    CHECK(sameTree(serial, buildBinaryBvh(items, triangleRule(false))));
    CHECK(sameTree(serial, buildBinaryBvh(items, triangleRule(true))));
    const BinaryBvh object = buildBinaryBvh(items, objectRule());
    CHECK(sameTree(object, buildBinaryBvh(items, objectRule())));
}
