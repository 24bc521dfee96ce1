// The object BVH's build: the shared builder (csg/bvh/bvh_builder.h) with the object rule
// (binned SAH, or median splits for the scene's objects), its nodes converted to 32-byte
// nodes whose float boxes are rounded outward, so a node never cuts its items.
#include "csg/bvh/bvh.h"

#include <algorithm>
#include <cmath>

#include "csg/bvh/bvh_nesting.h"
#include "csg/check.h"

namespace kerf {

namespace {

constexpr int kBins = 16;
constexpr int kMaxLeafSize = 4;
constexpr int kMedianLeafSize = 2;
/// SAH costs, in node box tests: an item costs its own box test (the caller repeats it in
/// double) and, now and then, its spans. Measured on the bench scenes: a cheaper item splits
/// small sets that a ray mostly meets whole, and the extra node tests cost more than they save.
constexpr double kNodeCost = 1.0;
constexpr double kItemCost = 1.5;
/// Below this depth the build splits by SAH; deeper (only for badly skewed inputs) it splits
/// at the median, which halves the count, so the tree stays within the traversal stack.
constexpr int kSahDepthLimit = 48;

/// The largest float ≤ x (−inf below the float range) and the smallest float ≥ x.
float floatDown(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) > x) f = std::nextafter(f, -INFINITY);
    return f;
}
float floatUp(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) < x) f = std::nextafter(f, INFINITY);
    return f;
}

}  // namespace

BvhBuildRule Bvh::buildRule(Split split) {
    BvhBuildRule rule;
    rule.split = split == Split::Sah ? BvhBuildRule::Split::Sah : BvhBuildRule::Split::Median;
    rule.cost = BvhBuildRule::SahCost::PerArea;
    rule.bins = kBins;
    rule.maxLeafSize = split == Split::Sah ? kMaxLeafSize : kMedianLeafSize;
    rule.coincidentLeaf = 0xffff;  // Node::count's range
    rule.sahDepthLimit = kSahDepthLimit;
    rule.nodeCost = kNodeCost;
    rule.itemCost = kItemCost;
    return rule;
}

Bvh::Bvh(const std::vector<Bounds3>& items, Split split)
    : mItemCount(static_cast<int>(items.size())) {
    std::vector<BvhBuildItem> build;
    for (int i = 0; i < mItemCount; ++i) {
        if (items[i].empty()) continue;  // an empty solid is never hit
        if (items[i].finite())
            build.push_back({items[i], items[i].center(), uint32_t(i)});
        else
            mUnbounded.push_back(i);
    }
    if (build.empty()) return;
    const BinaryBvh tree = buildBinaryBvh(std::move(build), buildRule(split));
    mNodes.resize(tree.nodes.size());
    for (size_t k = 0; k < tree.nodes.size(); ++k) {
        const BinaryBvhNode& from = tree.nodes[k];
        Node& to = mNodes[k];
        setBox(to, from.box);
        to.first = int32_t(from.first);
        to.count = uint16_t(from.count);  // leaves hold at most coincidentLeaf items
        to.axis = uint16_t(from.axis);
    }
    mOrder.assign(tree.order.begin(), tree.order.end());
    KERF_DCHECK(childBoxesNest(mNodes, [](const Node& n) { return n.first; }));
}

void Bvh::setBox(Node& node, const Bounds3& box) {
    for (int a = 0; a < 3; ++a) {
        node.lo[a] = floatDown(box.lo[a]);
        node.hi[a] = floatUp(box.hi[a]);
    }
}

int Bvh::depth() const {
    if (mNodes.empty()) return 0;
    int deepest = 0;
    std::vector<std::pair<int, int>> stack{{0, 1}};
    while (!stack.empty()) {
        const auto [node, d] = stack.back();
        stack.pop_back();
        deepest = std::max(deepest, d);
        if (mNodes[node].count == 0) {
            stack.push_back({node + 1, d + 1});
            stack.push_back({mNodes[node].first, d + 1});
        }
    }
    return deepest;
}

}  // namespace kerf
