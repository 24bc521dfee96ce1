// BVH construction by binned SAH (Wald 2007): at each node the centroids are binned along
// each axis and the split with the least surface-area cost is taken, or a leaf when splitting
// does not pay. Boxes are stored as floats rounded outward, so a node never cuts its items.
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

double halfArea(const Bounds3& b) {
    if (b.empty()) return 0.0;
    const Vec3 e = b.extent();
    return e.x * e.y + e.y * e.z + e.z * e.x;
}

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

struct Bvh::BuildItem {
    Bounds3 box;
    Vec3 centroid;
    int32_t index;
};

Bvh::Bvh(const std::vector<Bounds3>& items, Split split)
    : mItemCount(static_cast<int>(items.size())), mSplit(split) {
    std::vector<BuildItem> build;
    for (int i = 0; i < mItemCount; ++i) {
        if (items[i].empty()) continue;  // an empty solid is never hit
        if (items[i].finite())
            build.push_back({items[i], items[i].center(), i});
        else
            mUnbounded.push_back(i);
    }
    if (build.empty()) return;
    mNodes.reserve(2 * build.size());
    this->build(build, 0, static_cast<int>(build.size()), 0);
    mOrder.reserve(build.size());
    for (const BuildItem& b : build) mOrder.push_back(b.index);
    KERF_DCHECK(childBoxesNest(mNodes, [](const Node& n) { return n.first; }));
}

void Bvh::setBox(Node& node, const Bounds3& box) {
    for (int a = 0; a < 3; ++a) {
        node.lo[a] = floatDown(box.lo[a]);
        node.hi[a] = floatUp(box.hi[a]);
    }
}

int Bvh::build(std::vector<BuildItem>& items, int begin, int end, int depth) {
    const int self = static_cast<int>(mNodes.size());
    mNodes.push_back(Node{});
    Bounds3 box, centroids;
    for (int k = begin; k < end; ++k) {
        box.extend(items[k].box);
        centroids.extend(items[k].centroid);
    }
    setBox(mNodes[self], box);
    const int count = end - begin;
    const auto makeLeaf = [&] {
        mNodes[self].first = begin;
        mNodes[self].count = static_cast<uint16_t>(count);
        mNodes[self].axis = 0;
        return self;
    };
    const Vec3 extent = centroids.extent();
    if (count == 1 || (extent.x <= 0.0 && extent.y <= 0.0 && extent.z <= 0.0)) {
        if (count <= 0xffff) return makeLeaf();
    }

    if (mSplit == Split::Median) {
        const int longest =
            (extent.x >= extent.y && extent.x >= extent.z) ? 0 : (extent.y >= extent.z ? 1 : 2);
        if (count <= kMedianLeafSize || extent[longest] <= 0.0) {
            if (count <= 0xffff) return makeLeaf();
        }
    }

    int axis = -1, split = 0;  // split: items in bins [0, split) go left
    double bestCost = kInf;
    if (mSplit == Split::Sah && depth < kSahDepthLimit) {
        for (int a = 0; a < 3; ++a) {
            if (!(extent[a] > 0.0)) continue;
            Bounds3 binBox[kBins];
            int binCount[kBins] = {};
            const double scale = kBins / extent[a];
            if (!std::isfinite(scale)) continue;  // centroids too close to bin: median split
            const auto binOf = [&](const BuildItem& it) {
                const int b = static_cast<int>((it.centroid[a] - centroids.lo[a]) * scale);
                return std::min(std::max(b, 0), kBins - 1);
            };
            for (int k = begin; k < end; ++k) {
                const int b = binOf(items[k]);
                binBox[b].extend(items[k].box);
                ++binCount[b];
            }
            // Sweep from the right for the suffix areas, then from the left for the cost.
            double rightArea[kBins];
            int rightCount[kBins];
            Bounds3 acc;
            int n = 0;
            for (int b = kBins - 1; b > 0; --b) {
                acc = Bounds3::hull(acc, binBox[b]);
                n += binCount[b];
                rightArea[b] = halfArea(acc);
                rightCount[b] = n;
            }
            acc = Bounds3();
            n = 0;
            for (int b = 1; b < kBins; ++b) {
                acc = Bounds3::hull(acc, binBox[b - 1]);
                n += binCount[b - 1];
                if (n == 0 || rightCount[b] == 0) continue;
                const double cost = halfArea(acc) * n + rightArea[b] * rightCount[b];
                if (cost < bestCost) bestCost = cost, axis = a, split = b;
            }
        }
        // Cost relative to the node's area: a leaf costs count item tests.
        const double area = halfArea(box);
        const double splitCost = kNodeCost + kItemCost * (area > 0.0 ? bestCost / area : kInf);
        if (count <= kMaxLeafSize && !(splitCost < kItemCost * count)) return makeLeaf();
    }
    if (mSplit == Split::Sah && axis < 0 && count <= kMaxLeafSize) return makeLeaf();

    int mid;
    if (axis >= 0) {
        const double scale = kBins / extent[axis], lo = centroids.lo[axis];
        mid = static_cast<int>(
            std::partition(items.begin() + begin, items.begin() + end,
                           [&](const BuildItem& it) {
                               const int b = static_cast<int>((it.centroid[axis] - lo) * scale);
                               return std::min(std::max(b, 0), kBins - 1) < split;
                           }) -
            items.begin());
    } else {
        // Median split on the widest centroid axis (deterministic order for equal centroids).
        axis = (extent.x >= extent.y && extent.x >= extent.z) ? 0 : (extent.y >= extent.z ? 1 : 2);
        mid = (begin + end) / 2;
        std::nth_element(items.begin() + begin, items.begin() + mid, items.begin() + end,
                         [&](const BuildItem& l, const BuildItem& r) {
                             return l.centroid[axis] < r.centroid[axis] ||
                                    (l.centroid[axis] == r.centroid[axis] && l.index < r.index);
                         });
    }
    build(items, begin, mid, depth + 1);  // the left child follows its parent directly
    const int right = build(items, mid, end, depth + 1);
    mNodes[self].first = right;
    mNodes[self].count = 0;
    mNodes[self].axis = static_cast<uint16_t>(axis);
    return self;
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
