// The BVH builder (csg/bvh/bvh_builder.h): at each node the centroids are binned along each
// axis in one pass, the boundaries swept for the least SAH cost, and the range partitioned
// there; where SAH finds nothing or is not asked for, the range is halved at the median.
// Subtrees are written depth first into one array; a parallel task writes its second child's
// subtree into an array of its own, appended after the first child's.
#include "csg/bvh/bvh_builder.h"

#include <algorithm>
#include <cmath>

namespace kerf {

namespace {

constexpr int kMaxBins = 64;

/// The index of the widest of e's components (x before y before z on ties).
int widestAxis(const Vec3& e) { return e.x >= e.y ? (e.x >= e.z ? 0 : 2) : (e.y >= e.z ? 1 : 2); }

/// The best SAH boundary of a range: items in bins [0, bin) of axis go left.
struct SahChoice {
    int axis = -1;
    int bin = 0;
    double cost = kInf;  ///< offset + Σ A_child·n_child, the sweep's minimum
};

class Builder {
public:
    Builder(std::vector<BvhBuildItem>& items, const BvhBuildRule& rule)
        : mItems(items), mRule(rule), mBins(std::clamp(rule.bins, 2, kMaxBins)) {}

    void build(uint32_t begin, uint32_t end, int depth, std::vector<BinaryBvhNode>& out) const;

private:
    SahChoice sahSweep(uint32_t begin, uint32_t end, const Bounds3& cbox, double offset) const;
    double splitCost(const SahChoice& c, double area) const;
    double leafCost(uint32_t count, double area) const;
    uint32_t partitionAtBin(uint32_t begin, uint32_t end, const Bounds3& cbox,
                            const SahChoice& c) const;
    uint32_t medianSplit(uint32_t begin, uint32_t end, int axis) const;
    void buildChildren(uint32_t begin, uint32_t mid, uint32_t end, int depth, size_t self,
                       std::vector<BinaryBvhNode>& out) const;

    std::vector<BvhBuildItem>& mItems;
    const BvhBuildRule& mRule;
    const int mBins;
};

// Bins the range's centroids along all three axes in one pass, then sweeps each axis's
// boundaries: right to left for the areas and counts right of each, left to right for the cost.
SahChoice Builder::sahSweep(uint32_t begin, uint32_t end, const Bounds3& cbox,
                            double offset) const {
    Bounds3 binBox[3][kMaxBins];
    uint32_t binCount[3][kMaxBins] = {};
    double scale[3];
    bool active[3];
    for (int a = 0; a < 3; ++a) {
        const double extent = cbox.hi[a] - cbox.lo[a];
        scale[a] = extent > 0.0 ? mBins / extent : 0.0;
        active[a] = extent > 0.0 && std::isfinite(scale[a]);  // too close to bin: median
    }
    for (uint32_t i = begin; i < end; ++i) {
        const BvhBuildItem& it = mItems[i];
        for (int a = 0; a < 3; ++a) {
            if (!active[a]) continue;
            const int b = std::min(mBins - 1, int((it.centroid[a] - cbox.lo[a]) * scale[a]));
            binBox[a][b].extend(it.box);
            ++binCount[a][b];
        }
    }
    SahChoice best;
    for (int a = 0; a < 3; ++a) {
        if (!active[a]) continue;
        double rightArea[kMaxBins];
        uint32_t rightCount[kMaxBins];
        Bounds3 acc;
        uint32_t n = 0;
        for (int b = mBins - 1; b > 0; --b) {
            acc.extend(binBox[a][b]);
            n += binCount[a][b];
            rightArea[b] = bvhHalfArea(acc);
            rightCount[b] = n;
        }
        acc = Bounds3();
        n = 0;
        for (int b = 1; b < mBins; ++b) {  // boundary b: bins [0, b) left, [b, bins) right
            acc.extend(binBox[a][b - 1]);
            n += binCount[a][b - 1];
            if (n == 0 || rightCount[b] == 0) continue;
            const double cost = offset + bvhHalfArea(acc) * n + rightArea[b] * rightCount[b];
            if (cost < best.cost) best = {a, b, cost};
        }
    }
    return best;
}

double Builder::splitCost(const SahChoice& c, double area) const {
    if (c.axis < 0) return kInf;
    if (mRule.cost == BvhBuildRule::SahCost::AreaScaled) return c.cost;
    return mRule.nodeCost + mRule.itemCost * (area > 0.0 ? c.cost / area : kInf);
}

double Builder::leafCost(uint32_t count, double area) const {
    if (mRule.cost == BvhBuildRule::SahCost::AreaScaled) return double(count) * area;
    return mRule.itemCost * count;
}

uint32_t Builder::partitionAtBin(uint32_t begin, uint32_t end, const Bounds3& cbox,
                                 const SahChoice& c) const {
    const int axis = c.axis, bins = mBins;
    const double lo = cbox.lo[axis];
    const double scale = bins / (cbox.hi[axis] - lo);
    const auto it =
        std::partition(mItems.begin() + begin, mItems.begin() + end, [&](const BvhBuildItem& r) {
            return std::min(bins - 1, int((r.centroid[axis] - lo) * scale)) < c.bin;
        });
    return uint32_t(it - mItems.begin());
}

uint32_t Builder::medianSplit(uint32_t begin, uint32_t end, int axis) const {
    const uint32_t mid = begin + (end - begin) / 2;
    const auto first = mItems.begin() + begin, nth = mItems.begin() + mid,
               last = mItems.begin() + end;
    if (mRule.medianTieById)
        std::nth_element(first, nth, last, [&](const BvhBuildItem& l, const BvhBuildItem& r) {
            const double cl = l.centroid[axis], cr = r.centroid[axis];
            return cl < cr || (cl == cr && l.id < r.id);
        });
    else
        std::nth_element(first, nth, last, [&](const BvhBuildItem& l, const BvhBuildItem& r) {
            return l.centroid[axis] < r.centroid[axis];
        });
    return mid;
}

void Builder::build(uint32_t begin, uint32_t end, int depth,
                    std::vector<BinaryBvhNode>& out) const {
    const size_t self = out.size();
    out.push_back(BinaryBvhNode{});
    Bounds3 box, cbox;
    for (uint32_t k = begin; k < end; ++k) {
        box.extend(mItems[k].box);
        cbox.extend(mItems[k].centroid);
    }
    out[self].box = box;
    const uint32_t count = end - begin;
    const auto makeLeaf = [&] {
        out[self].first = begin;
        out[self].count = count;
        out[self].axis = 0;
    };
    const Vec3 extent = cbox.extent();
    const bool coincident = extent.x <= 0.0 && extent.y <= 0.0 && extent.z <= 0.0;
    const uint32_t maxLeaf = uint32_t(std::max(mRule.maxLeafSize, 1));
    if (coincident && count <= std::max(maxLeaf, mRule.coincidentLeaf)) return makeLeaf();

    const double area = bvhHalfArea(box);
    SahChoice sah;
    if (mRule.split == BvhBuildRule::Split::Sah && depth < mRule.sahDepthLimit) {
        const bool scaled = mRule.cost == BvhBuildRule::SahCost::AreaScaled;
        sah = sahSweep(begin, end, cbox, scaled ? mRule.nodeCost * area : 0.0);
    }
    if (count <= maxLeaf && !(splitCost(sah, area) < leafCost(count, area))) return makeLeaf();

    uint32_t mid;
    int axis = sah.axis;
    if (axis >= 0) {
        mid = partitionAtBin(begin, end, cbox, sah);
    } else {
        // Too many for a leaf and no SAH split (coincident centroids, too deep, or asked for):
        // halve at the median along the widest axis.
        const bool byBox = mRule.medianAxis == BvhBuildRule::MedianAxis::NodeBox;
        axis = widestAxis(byBox ? box.extent() : extent);
        mid = medianSplit(begin, end, axis);
    }
    out[self].count = 0;
    out[self].axis = axis;
    buildChildren(begin, mid, end, depth, self, out);
    // invariant: parent bounds contain children (each child's box is the hull of a sub-range)
}

void Builder::buildChildren(uint32_t begin, uint32_t mid, uint32_t end, int depth, size_t self,
                            std::vector<BinaryBvhNode>& out) const {
    const uint32_t count = end - begin;
    if (!mRule.parallelInvoke || count <= std::max(mRule.parallelAbove, 2u)) {
        build(begin, mid, depth + 1, out);  // the first child follows its parent directly
        out[self].first = uint32_t(out.size());
        build(mid, end, depth + 1, out);
        return;
    }
    std::vector<BinaryBvhNode> second;
    mRule.parallelInvoke([&] { build(begin, mid, depth + 1, out); },
                         [&] { build(mid, end, depth + 1, second); });
    const uint32_t offset = uint32_t(out.size());
    out[self].first = offset;
    for (BinaryBvhNode& n : second)
        if (n.count == 0) n.first += offset;  // inner nodes point at their second child
    out.insert(out.end(), second.begin(), second.end());
}

}  // namespace

double bvhHalfArea(const Bounds3& b) {
    if (b.empty()) return 0.0;
    const Vec3 e = b.extent();
    return e.x * e.y + e.y * e.z + e.z * e.x;
}

BinaryBvh buildBinaryBvh(std::vector<BvhBuildItem> items, const BvhBuildRule& rule) {
    BinaryBvh tree;
    if (items.empty()) return tree;
    tree.nodes.reserve(2 * items.size());
    Builder(items, rule).build(0, uint32_t(items.size()), 0, tree.nodes);
    tree.order.resize(items.size());
    for (size_t k = 0; k < items.size(); ++k) tree.order[k] = items[k].id;
    return tree;
}

}  // namespace kerf
