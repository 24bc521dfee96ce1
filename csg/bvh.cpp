// BVH construction: median split on the longest axis of the centroids' box. The sets we build
// over (CSG children, scene objects) are small to medium, so a simple build is enough; the
// traversal (bvh.h) is what rays pay for.
#include "csg/bvh.h"

#include <algorithm>
#include <numeric>

namespace kerf {

namespace {
constexpr int kLeafSize = 2;
}

Bvh::Bvh(const std::vector<Bounds3>& items) : mItemCount(static_cast<int>(items.size())) {
    for (int i = 0; i < mItemCount; ++i) {
        if (items[i].empty()) continue;  // an empty solid is never hit
        if (items[i].finite())
            mOrder.push_back(i);
        else
            mUnbounded.push_back(i);
    }
    if (mOrder.empty()) return;
    mNodes.reserve(2 * mOrder.size());
    build(items, 0, static_cast<int>(mOrder.size()));
}

int Bvh::build(const std::vector<Bounds3>& items, int begin, int end) {
    const int self = static_cast<int>(mNodes.size());
    mNodes.push_back(Node{});
    Bounds3 box, centroids;
    for (int k = begin; k < end; ++k) {
        box.extend(items[mOrder[k]]);
        centroids.extend(items[mOrder[k]].center());
    }
    mNodes[self].box = box;
    const Vec3 e = centroids.extent();
    const int axis = (e.x >= e.y && e.x >= e.z) ? 0 : (e.y >= e.z ? 1 : 2);
    if (end - begin <= kLeafSize || e[axis] <= 0.0) {
        mNodes[self].first = begin;
        mNodes[self].count = end - begin;
        mNodes[self].axis = axis;
        return self;
    }
    const int mid = (begin + end) / 2;
    std::nth_element(mOrder.begin() + begin, mOrder.begin() + mid, mOrder.begin() + end,
                     [&](int32_t l, int32_t r) {
                         const double cl = items[l].lo[axis] + items[l].hi[axis];
                         const double cr = items[r].lo[axis] + items[r].hi[axis];
                         return cl < cr || (cl == cr && l < r);  // deterministic order
                     });
    build(items, begin, mid);  // the left child follows its parent directly
    const int right = build(items, mid, end);
    mNodes[self].first = right;
    mNodes[self].count = 0;
    mNodes[self].axis = axis;
    return self;
}

}  // namespace kerf
