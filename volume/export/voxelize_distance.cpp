// Exact point-to-mesh distances near a mesh: triangles bucketed by 8³-voxel blocks.
#include "volume/export/voxelize_distance.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace kerf {

namespace {
constexpr size_t kCluster = 8;
}  // namespace

double squaredDistanceToTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    // Barycentric regions of the plane: the nearest point is a corner, a point of an edge, or
    // the projection of p inside the triangle.
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    auto sq = [&](const Vec3& q) { return glm::dot(p - q, p - q); };
    if (d1 <= 0.0 && d2 <= 0.0) return sq(a);
    const Vec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return sq(b);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return sq(a + ab * (d1 / (d1 - d3)));
    const Vec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return sq(c);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return sq(a + ac * (d2 / (d2 - d6)));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
        return sq(b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))));
    const double sum = va + vb + vc;
    if (!(sum > 0.0)) {  // a triangle without area: its nearest edge
        const auto seg = [&](const Vec3& u, const Vec3& v) {
            const Vec3 e = v - u;
            const double l = glm::dot(e, e);
            const double t = l > 0.0 ? std::clamp(glm::dot(p - u, e) / l, 0.0, 1.0) : 0.0;
            return sq(u + e * t);
        };
        return std::min({seg(a, b), seg(b, c), seg(c, a)});
    }
    return sq(a + ab * (vb / sum) + ac * (vc / sum));
}

size_t MeshDistance::KeyHash::operator()(const BlockKey& k) const {
    uint64_t h = 0x9e3779b97f4a7c15ull;
    for (int64_t v : k) h = (h ^ uint64_t(v)) * 0xff51afd7ed558ccdull, h ^= h >> 32;
    return size_t(h);
}

int64_t MeshDistance::blockOf(double x) const { return int64_t(std::floor(x / mBlock)); }

MeshDistance::MeshDistance(const WatertightMesh& mesh, double voxel, double reach)
    : mMesh(mesh), mBlock(std::max(8.0 * voxel, 2.0 * reach)) {
    mBoxes.reserve(mesh.triangles.size());
    for (uint32_t t = 0; t < mesh.triangles.size(); ++t) {
        Bounds3 box;
        for (uint32_t v : mesh.triangles[t])
            box = Bounds3::hull(box, Bounds3{mesh.vertices[v], mesh.vertices[v]});
        mBoxes.push_back(box);
        int64_t lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
            lo[a] = blockOf(box.lo[a] - reach);
            hi[a] = blockOf(box.hi[a] + reach);
        }
        for (int64_t i = lo[0]; i <= hi[0]; ++i)
            for (int64_t j = lo[1]; j <= hi[1]; ++j)
                for (int64_t k = lo[2]; k <= hi[2]; ++k)
                    mBlocks[BlockKey{i, j, k}].triangles.push_back(t);
    }
    std::vector<Block*> blocks;
    blocks.reserve(mBlocks.size());
    for (auto& [key, block] : mBlocks) blocks.push_back(&block);
    tbb::parallel_for(size_t(0), blocks.size(), [&](size_t b) {
        Block& block = *blocks[b];
        Bounds3 all;
        for (uint32_t t : block.triangles) all = Bounds3::hull(all, mBoxes[t]);
        const Vec3 scale = 1023.0 / glm::max(all.hi - all.lo, Vec3(1e-300));
        auto morton = [&](uint32_t t) {
            const Vec3 q = (0.5 * (mBoxes[t].lo + mBoxes[t].hi) - all.lo) * scale;
            uint64_t code = 0;
            const uint32_t axis[3] = {uint32_t(q.x), uint32_t(q.y), uint32_t(q.z)};
            for (int bit = 9; bit >= 0; --bit)
                for (int a = 0; a < 3; ++a) code = (code << 1) | ((axis[a] >> bit) & 1u);
            return code;
        };
        std::vector<std::pair<uint64_t, uint32_t>> order;
        order.reserve(block.triangles.size());
        for (uint32_t t : block.triangles) order.push_back({morton(t), t});
        std::sort(order.begin(), order.end());
        for (size_t i = 0; i < order.size(); ++i) block.triangles[i] = order[i].second;
        for (size_t c = 0; c < order.size(); c += kCluster) {
            Bounds3 box;
            for (size_t i = c; i < std::min(order.size(), c + kCluster); ++i)
                box = Bounds3::hull(box, mBoxes[block.triangles[i]]);
            block.clusters.push_back(box);
        }
    });
}

double MeshDistance::distance(const Vec3& p, double bound, uint32_t& hint) const {
    const auto found = mBlocks.find(BlockKey{blockOf(p.x), blockOf(p.y), blockOf(p.z)});
    if (found == mBlocks.end()) return bound;
    const Block& block = found->second;
    auto squared = [&](uint32_t t) {
        const auto& tri = mMesh.triangles[t];
        return squaredDistanceToTriangle(p, mMesh.vertices[tri[0]], mMesh.vertices[tri[1]],
                                         mMesh.vertices[tri[2]]);
    };
    auto gap = [&](const Bounds3& box) {
        const Vec3 g = glm::max(glm::max(box.lo - p, p - box.hi), Vec3(0.0));
        return glm::dot(g, g);
    };
    // The bound only prunes; the minimum over the triangles not pruned is the same whatever
    // it started from, so the hint changes the work, not the answer.
    double best = bound * bound;
    uint32_t nearest = kNoHint;
    if (hint != kNoHint) {
        const double d = squared(hint);
        if (d < best) best = d, nearest = hint;
    }
    for (size_t c = 0; c < block.clusters.size(); ++c) {
        if (gap(block.clusters[c]) >= best) continue;
        const size_t end = std::min(block.triangles.size(), (c + 1) * kCluster);
        for (size_t i = c * kCluster; i < end; ++i) {
            const uint32_t t = block.triangles[i];
            if (gap(mBoxes[t]) >= best) continue;
            const double d = squared(t);
            if (d < best) best = d, nearest = t;
        }
    }
    hint = nearest;
    return std::sqrt(best);
}

}  // namespace kerf
